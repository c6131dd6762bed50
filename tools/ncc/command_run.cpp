// `ncc run IN [--emit=moves|vars] [-o FILE]` (IN is a source program or a .ncb file) and
// `ncc dis FILE.ncb`.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "absl/strings/match.h"
#include "absl/strings/str_split.h"
#include "absl/strings/str_format.h"
#include "cli.h"
#include "pending_output.h"
#include "run_summary.h"
#include "ncc/bytecode/disassembler.h"
#include "ncc/driver/json_output.h"
#include "ncc/driver/run.h"
#include "ncc/driver/simulate.h"
#include "ncc/driver/trace.h"

namespace ncc::cli {

namespace {

struct RunArgs {
  CommonOptions common;
  std::string input;
  std::string output;
  std::string emit = "summary";
  uint64_t trace_every = 1;  // --trace-every N: every Nth tick
  uint64_t max_steps = driver::kDefaultMaxSteps;
  double max_time = vm::kDefaultMaxRunSeconds;  // s of simulated time
  double feed_override = 100.0;   // %
  double rapid_override = 100.0;  // %
  std::vector<std::string> feed_override_at;  // "SECONDS=PERCENT", as given
  std::vector<std::string> rapid_override_at;  // "SECONDS=PERCENT", as given
  std::vector<std::string> feed_hold_at;      // "SECONDS=DURATION", as given
};

// A plain decimal number (digits, '.', an exponent, a leading '-'): no hex, no whitespace,
// no '+', nothing after it. SimpleAtod would take "0x32" as 50.
bool parseDecimal(std::string_view text, double& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value, std::chars_format::general);
  return ec == std::errc() && ptr == end && std::isfinite(value);
}

// "A=B" with both plain decimal numbers.
bool parsePair(const std::string& text, double& first, double& second) {
  const std::vector<std::string> parts = absl::StrSplit(text, absl::MaxSplits('=', 1));
  return parts.size() == 2 && parseDecimal(parts[0], first) && parseDecimal(parts[1], second);
}

// Operator events in time order; a stable sort, so events at the same time keep the order
// given.
template <class Event>
void sortBySeconds(std::vector<Event>& events) {
  std::stable_sort(events.begin(), events.end(),
                   [](const Event& a, const Event& b) { return a.seconds < b.seconds; });
}

// --feed-override-at / --rapid-override-at SECONDS=PERCENT: the turns of an override, in
// time order, PERCENT in 1..`max_percent`. False with a message on stderr for a malformed or
// out-of-range value.
template <class Turn>
bool parseOverrideTurns(const char* option, double max_percent,
                        const std::vector<std::string>& given, std::vector<Turn>& turns) {
  for (const std::string& text : given) {
    double seconds = 0.0, percent = 0.0;
    if (!parsePair(text, seconds, percent) || seconds < 0.0 ||
        !(percent >= 1.0 && percent <= max_percent)) {
      std::cerr << "ncc: error: " << option << " '" << text
                << "': expected SECONDS=PERCENT with SECONDS >= 0 and PERCENT in 1.." << max_percent
                << "\n";
      return false;
    }
    turns.push_back({seconds, percent / 100.0});
  }
  sortBySeconds(turns);
  return true;
}

// Longest simulated feed hold: every held tick is simulated.
constexpr double kMaxFeedHoldSeconds = 86400.0;

// --feed-hold-at SECONDS=DURATION: the feed holds, in time order. False with a message on
// stderr for a malformed, negative or overlapping one.
bool parseFeedHolds(const std::vector<std::string>& given, std::vector<driver::FeedHoldSpan>& holds) {
  for (const std::string& text : given) {
    double seconds = 0.0, duration = 0.0;
    if (!parsePair(text, seconds, duration) || seconds < 0.0 || !(duration > 0.0) ||
        duration > kMaxFeedHoldSeconds) {
      std::cerr << "ncc: error: --feed-hold-at '" << text
                << "': expected SECONDS=DURATION in seconds, SECONDS >= 0 and DURATION above 0 "
                   "and at most 86400 (a day)\n";
      return false;
    }
    holds.push_back({seconds, duration});
  }
  sortBySeconds(holds);
  for (std::size_t i = 1; i < holds.size(); ++i) {
    if (holds[i].seconds < holds[i - 1].seconds + holds[i - 1].duration) {
      std::cerr << "ncc: error: --feed-hold-at: the holds at " << holds[i - 1].seconds << " s and "
                << holds[i].seconds << " s overlap\n";
      return false;
    }
  }
  return true;
}

// Reports a run-time alarm like a compile diagnostic: file:line:col: error[CODE]: message.
void reportAlarm(driver::Session& session, const bytecode::Program& program, const vm::Alarm& alarm) {
  SourceLocation where{0, alarm.where.line, alarm.where.column};
  if (alarm.where.file < program.strings.size() && !program.strings[alarm.where.file].empty())
    where.file = session.sources().addFile(program.strings[alarm.where.file]);
  session.diagnostics().error(alarm.code, where, alarm.message);
}

// --emit=summary|summary-json|trace: the program through the planner, interpolator and servo.
int runSimulation(driver::Session& session, const bytecode::Program& program, const RunArgs& args) {
  PendingOutput output;
  if (!output.open(args.output)) return kUsage;
  std::unique_ptr<driver::TraceWriter> trace;
  if (args.emit == "trace") {
    driver::TraceHeader header;
    for (const bytecode::AxisInfo& axis : program.header.axes) header.axes.push_back(axis.name);
    header.tick_seconds = session.machine().ipo_cycle_seconds;
    header.tick_every = args.trace_every;
    bool binary = !args.output.empty() && !absl::EndsWithIgnoreCase(args.output, ".csv");
    trace = binary ? driver::makeBinaryTraceWriter(output.stream(), header)
                   : driver::makeCsvTraceWriter(output.stream(), header);
  }
  driver::SimulationOptions options;
  options.max_steps = args.max_steps;
  options.max_seconds = args.max_time;
  options.feed_override = args.feed_override / 100.0;
  options.rapid_override = args.rapid_override / 100.0;
  if (!parseOverrideTurns("--feed-override-at", 200.0, args.feed_override_at,
                          options.feed_override_turns) ||
      !parseOverrideTurns("--rapid-override-at", 100.0, args.rapid_override_at,
                          options.rapid_override_turns) ||
      !parseFeedHolds(args.feed_hold_at, options.feed_holds))
    return kUsage;
  driver::SimulationResult sim = driver::simulate(program, session.machine(), trace.get(), options);
  if (!sim.error.empty()) {
    std::cerr << "ncc: error: " << sim.error << '\n';
    return kProgramError;
  }
  const MachineConfig& machine = session.machine();
  const bool json = args.emit == "summary-json";
  const bool summary_only = args.emit == "summary" || json;
  auto summary = [&](std::ostream& out) {
    const SummaryInput in{sim, program, machine.ipo_cycle_seconds, machine.lookahead_segments};
    json ? printSummaryJson(out, in) : printSummary(out, in);
  };
  if (sim.alarm) {
    output.discard();
    reportAlarm(session, program, *sim.alarm);
    printDiagnostics(session);
    if (summary_only) summary(std::cerr);
    return kRuntimeAlarm;
  }
  if (summary_only) summary(output.stream());
  if (!output.commit()) return kUsage;
  if (!args.output.empty() && !summary_only) summary(std::cout);
  return kOk;
}

// --emit=moves and --emit=vars: the executor's motion primitives and variables.
int runExecutor(driver::Session& session, const bytecode::Program& program, const RunArgs& args) {
  // Moves stream out as the VM produces them (memory stays flat on long programs); a file
  // appears only when the run completes.
  PendingOutput output;
  if (!output.open(args.output)) return kUsage;
  driver::EventHandler on_event;
  if (args.emit == "moves") {
    on_event = [&](const vm::Event& e) {
      if (e.kind == vm::Event::Kind::Motion) driver::writeMoveJson(output.stream(), e.motion, program);
    };
  }
  driver::RunResult result = driver::runProgram(program, session.machine(), on_event, args.max_steps);
  if (result.alarm) {
    output.discard();
    reportAlarm(session, program, *result.alarm);
    printDiagnostics(session);
    return kRuntimeAlarm;
  }
  if (args.emit == "vars") driver::writeVariablesJson(output.stream(), result.variables);
  return output.commit() ? kOk : kUsage;
}

int runRun(const RunArgs& args) {
  driver::Session session;
  if (std::optional<int> failed = openSession(session, args.input, args.common)) return *failed;
  bytecode::Program program;
  if (!driver::loadProgram(session, program)) {
    printDiagnostics(session);
    return kProgramError;
  }
  printDiagnostics(session);  // warnings of the compile
  session.diagnostics().clear();
  if (args.emit == "summary" || args.emit == "summary-json" || args.emit == "trace")
    return runSimulation(session, program, args);
  return runExecutor(session, program, args);
}

int runDis(const std::string& input, const CommonOptions& common) {
  driver::Session session;
  if (std::optional<int> failed = openSession(session, input, common)) return *failed;
  if (!driver::isBytecodeFile(input)) {
    std::cerr << "ncc: error: '" << input << "' is not a bytecode file (compile it first: ncc compile)\n";
    return kUsage;
  }
  bytecode::Program program;
  if (!driver::loadProgram(session, program, /*check_machine=*/false)) {
    printDiagnostics(session);
    return kProgramError;
  }
  bytecode::disassemble(program, std::cout);
  return kOk;
}

}  // namespace

void addRunCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* cmd = app.add_subcommand("run", "compile (or load a .ncb) and run a program in the VM");
  cmd->add_option("input", args->input, "program source or .ncb file")->required();
  cmd->add_option("--emit", args->emit,
                  "summary (default): the simulated run's figures; summary-json: the same as "
                  "one JSON object; trace: setpoint, actual position of every axis and source "
                  "line per IPO tick (-o FILE.csv, or a compact binary trace for any other "
                  "extension); moves: JSON Lines, one motion primitive per line; "
                  "vars: JSON object of every non-vacant variable at the end")
      ->check(CLI::IsMember({"summary", "summary-json", "trace", "moves", "vars"}));
  cmd->add_option("-o,--output", args->output, "write the emitted output here (default: stdout)");
  cmd->add_option("--trace-every", args->trace_every,
                  "--emit=trace: write every Nth IPO tick only (ticks 0, N, 2N, ...)")
      ->check(CLI::Range(uint64_t{1}, uint64_t{1000000000}))
      ->capture_default_str();
  cmd->add_option("--max-steps", args->max_steps,
                  "stop with alarm NCC7204 after this many VM instructions (0: no limit); guards "
                  "against programs that loop forever")
      ->capture_default_str();
  cmd->add_option("--max-time", args->max_time,
                  "stop the simulated run with alarm NCC7208 after this many seconds of "
                  "simulated time (0: no limit); also at once when a block cannot end before it")
      ->check(CLI::Range(0.0, 1e12))
      ->capture_default_str();
  cmd->add_option("--feed-override", args->feed_override,
                  "feed override at the start of the simulated run, % of the programmed F")
      ->check(CLI::Range(1.0, 200.0))
      ->capture_default_str();
  cmd->add_option("--rapid-override", args->rapid_override,
                  "rapid override at the start of the simulated run, % of the axes' rapid speeds")
      ->check(CLI::Range(1.0, 100.0))
      ->capture_default_str();
  cmd->add_option("--feed-override-at", args->feed_override_at,
                  "SECONDS=PERCENT: the operator turns the feed override to PERCENT (1..200) at "
                  "that time of the simulated run (repeatable); moves are planned for the "
                  "highest feed override of the run");
  cmd->add_option("--rapid-override-at", args->rapid_override_at,
                  "SECONDS=PERCENT: the operator turns the rapid override to PERCENT (1..100) at "
                  "that time of the simulated run (repeatable)");
  cmd->add_option("--feed-hold-at", args->feed_hold_at,
                  "SECONDS=DURATION: the operator holds the feed at that time of the simulated "
                  "run and releases it DURATION seconds later (repeatable): the path brakes to "
                  "rest on the programmed path, stands, and goes on");
  args->common.addTo(*cmd);
  cmd->callback([args, &exit_code] { exit_code = runRun(*args); });
}

void addDisCommand(CLI::App& app, int& exit_code) {
  auto input = std::make_shared<std::string>();
  auto common = std::make_shared<CommonOptions>();
  CLI::App* cmd = app.add_subcommand("dis", "disassemble a bytecode file");
  cmd->add_option("input", *input, ".ncb file")->required();
  common->addTo(*cmd);
  cmd->callback([input, common, &exit_code] { exit_code = runDis(*input, *common); });
}

}  // namespace ncc::cli
