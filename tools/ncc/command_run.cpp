// `ncc run IN [--emit=summary|trace|moves|vars] [-o FILE]` (IN is a source program or a .ncb
// file, "-" the standard input) and `ncc dis FILE.ncb`.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "absl/strings/str_format.h"
#include "cli.h"
#include "ncc/driver/variables_file.h"
#include "pending_output.h"
#include "progress.h"
#include "run_input.h"
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
  RunInput run;                               // --probe, --signal
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
      printError("NCC0006", absl::StrCat(option, " '", text,
                                         "': expected SECONDS=PERCENT with SECONDS >= 0 and "
                                         "PERCENT in 1..", max_percent));
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
      printError("NCC0006", absl::StrCat("--feed-hold-at '", text,
                                         "': expected SECONDS=DURATION in seconds, SECONDS >= 0 "
                                         "and DURATION above 0 and at most 86400 (a day)"));
      return false;
    }
    holds.push_back({seconds, duration});
  }
  sortBySeconds(holds);
  for (std::size_t i = 1; i < holds.size(); ++i) {
    if (holds[i].seconds < holds[i - 1].seconds + holds[i - 1].duration) {
      printError("NCC0006", absl::StrCat("--feed-hold-at: the holds at ", holds[i - 1].seconds,
                                         " s and ", holds[i].seconds, " s overlap"));
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

// Sees the executor's events as the controller takes them: writes the moves (--emit=moves,
// streamed: memory stays flat) and counts blocks for the progress display.
class RunObserver : public vm::EventObserver {
 public:
  RunObserver(const bytecode::Program& program, std::ostream* moves, Progress& progress)
      : program_(program), moves_(moves), progress_(progress) {}
  void onEvent(const vm::Event& e) override {
    const vm::SourcePosition& where =
        e.kind == vm::Event::Kind::Motion ? e.motion.where : e.machine.where;
    if (where.line != last_.line || where.file != last_.file) {
      progress_.block(where.file, where.line);
      last_ = where;
    }
    if (moves_ && e.kind == vm::Event::Kind::Motion) driver::writeMoveJson(*moves_, e.motion, program_);
  }

 private:
  const bytecode::Program& program_;
  std::ostream* moves_;
  Progress& progress_;
  vm::SourcePosition last_;
};

// --vars FILE: the persistent common variables the run left, written back whole or not at all.
bool saveVariables(driver::Session& session, const driver::SimulationResult& sim) {
  std::vector<driver::InputFile> inputs;
  for (const driver::InputFile& f : session.inputFiles())
    if (f.path != *session.variablesFile()) inputs.push_back(f);
  PendingOutput out;
  if (!out.open(session.variablesFile()->string(), inputs)) return false;
  driver::writeVariablesFile(out.stream(), driver::persistentVariables(session, sim.variables));
  return out.commit();
}

// Every output mode runs the program through the whole controller (executor, planner,
// interpolator, servo model): the same checks, so the same alarm and exit code whatever is
// emitted. What an alarm leaves (docs/cli.md, "Output files"): the summary says it in its
// status line; a trace keeps the ticks up to the alarm; the moves keep those taken before
// it and end with an alarm record; vars writes nothing (there is no end state).
int runController(driver::Session& session, const MachineConfig& machine,
                  const bytecode::Program& program, const RunArgs& args) {
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
  PendingOutput output;
  if (!output.open(args.output, session.inputFiles())) return kUsage;
  std::unique_ptr<driver::TraceWriter> trace;
  if (args.emit == "trace") {
    driver::TraceHeader header;
    for (const bytecode::AxisInfo& axis : program.header.axes) header.axes.push_back(axis.name);
    header.tick_seconds = machine.ipo_cycle_seconds;
    header.tick_every = args.trace_every;
    bool binary = !output.toStdout() && !absl::EndsWithIgnoreCase(args.output, ".csv");
    trace = binary ? driver::makeBinaryTraceWriter(output.stream(), header)
                   : driver::makeCsvTraceWriter(output.stream(), header);
  }
  // The percentage of the file only for a source input (a .ncb's lines are not the source's).
  // Not while moves or a trace stream to the terminal the line would be drawn on.
  const bool streams_to_terminal =
      output.toStdout() && (args.emit == "moves" || args.emit == "trace") && stdoutIsTerminal();
  Progress progress("running", session, /*clock_every=*/1,
                    driver::isBytecodeInput(session) ? 0 : session.mainFile(), !streams_to_terminal);
  RunObserver observer(program, args.emit == "moves" ? &output.stream() : nullptr, progress);
  options.observer = &observer;
  if (progress.enabled()) options.progress = [&](const vm::TickOutput& t) { progress.tick(t.time); };
  driver::SimulationResult sim = driver::simulate(program, machine, trace.get(), options);
  progress.clear();
  if (!sim.error.empty()) {
    // "CODE: message" from the controller's load.
    const std::size_t colon = sim.error.find(": ");
    if (colon == std::string::npos) printError("NCC7100", sim.error);
    else printError(sim.error.substr(0, colon), sim.error.substr(colon + 2));
    return kProgramError;
  }
  const bool json = args.emit == "summary-json";
  const bool summary_only = args.emit == "summary" || json;
  auto summary = [&](std::ostream& out) {
    const SummaryInput in{sim, program, machine.ipo_cycle_seconds, machine.lookahead_segments};
    json ? printSummaryJson(out, in) : printSummary(out, in);
  };
  if (summary_only) summary(output.stream());
  if (args.emit == "moves" && sim.alarm) driver::writeAlarmJson(output.stream(), *sim.alarm, program);
  if (args.emit == "vars" && !sim.alarm) driver::writeVariablesJson(output.stream(), sim.variables);
  bool written = true;
  if (args.emit == "vars" && sim.alarm) output.discard();
  else written = output.commit();
  if (written && args.emit == "trace" && !output.toStdout()) summary(std::cout);
  if (sim.alarm) {
    reportAlarm(session, program, *sim.alarm);
    printDiagnostics(session);
  }
  if (!written) return kUsage;
  if (!sim.alarm && session.variablesFile() && !saveVariables(session, sim)) return kUsage;
  return sim.alarm ? kRuntimeAlarm : kOk;
}

int runRun(const RunArgs& args) {
  driver::Session session;
  MachineConfig machine;
  bytecode::Program program;
  if (std::optional<int> failed =
          loadForRun(session, args.input, args.common, args.run, machine, program))
    return *failed;
  return runController(session, machine, program, args);
}

int runDis(const std::string& input, const CommonOptions& common) {
  driver::Session session;
  if (std::optional<int> failed = openSession(session, input, common)) return *failed;
  if (!driver::isBytecodeInput(session)) {
    printError("NCC0007", "'" + input + "' is not a bytecode file (compile it first: ncc compile)");
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
  cmd->add_option("input", args->input, "program source or .ncb file (-: the standard input)")->required();
  cmd->add_option("--emit", args->emit,
                  "summary (default): the simulated run's figures; summary-json: the same as "
                  "one JSON object; trace: setpoint, actual position of every axis and source "
                  "line per IPO tick (-o FILE.csv, or a compact binary trace for any other "
                  "extension); moves: JSON Lines, one motion primitive per line; "
                  "vars: JSON object of every non-vacant variable at the end. Every mode runs the "
                  "same simulation: the same alarms and exit code")
      ->check(CLI::IsMember({"summary", "summary-json", "trace", "moves", "vars"}));
  cmd->add_option("-o,--output", args->output, "write the emitted output here (default or -: stdout)");
  cmd->add_option("--trace-every", args->trace_every,
                  "--emit=trace: write every Nth IPO tick only (ticks 0, N, 2N, ...)")
      ->check(CLI::Range(uint64_t{1}, uint64_t{1000000000}))
      ->capture_default_str();
  addRunLimitOptions(*cmd, args->max_steps, args->max_time);
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
  args->run.addTo(*cmd,
                  "AXIS=VALUE: the simulated skip signal of G31 comes on where AXIS reaches VALUE "
                  "(machine coordinates) moving towards it (repeatable; over [machine.probe])",
                  "N=VALUE: the interface input signal #N (#1000-#1031: 0 or 1; #1033-#1035: a "
                  "32-bit word) a program reads (repeatable; over [machine.signals])");
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
