// `ncc run IN [--emit=moves|vars] [-o FILE]` (IN is a source program or a .ncb file) and
// `ncc dis FILE.ncb`.
#include <iostream>

#include "absl/strings/str_format.h"
#include "cli.h"
#include "pending_output.h"
#include "ncc/bytecode/disassembler.h"
#include "ncc/driver/json_output.h"
#include "ncc/driver/run.h"

namespace ncc::cli {

namespace {

struct RunArgs {
  CommonOptions common;
  std::string input;
  std::string output;
  std::string emit = "summary";
  uint64_t max_steps = driver::kDefaultMaxSteps;
};

void printSummary(std::ostream& out, const driver::RunSummary& s, const bytecode::Program& program,
                  const std::optional<vm::Alarm>& alarm) {
  out << "program time     " << absl::StrFormat("%.3f s (feed-rate estimate, no acceleration)", s.estimated_seconds) << '\n'
      << "path length      " << absl::StrFormat("%.3f mm cutting, %.3f mm rapid", s.cutting_length, s.rapid_length) << '\n'
      << "motions          " << absl::StrFormat("%d rapid, %d line, %d arc, %d dwell", s.rapids, s.lines, s.arcs, s.dwells) << '\n'
      << "machine functions " << s.machine_events << '\n'
      << "final position  ";
  for (int i = 0; i < program.axisCount(); ++i)
    out << ' ' << program.header.axes[i].name << driver::jsonNumber(s.final_position[i]);
  out << '\n' << "status           " << (alarm ? "alarm " + alarm->code : std::string("completed")) << '\n';
}

// Reports a run-time alarm like a compile diagnostic: file:line:col: error[CODE]: message.
void reportAlarm(driver::Session& session, const bytecode::Program& program, const vm::Alarm& alarm) {
  SourceLocation where{0, alarm.where.line, alarm.where.column};
  if (alarm.where.file < program.strings.size() && !program.strings[alarm.where.file].empty())
    where.file = session.sources().addFile(program.strings[alarm.where.file]);
  session.diagnostics().error(alarm.code, where, alarm.message);
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
  if (args.emit == "summary") printSummary(output.stream(), result.summary, program, result.alarm);
  if (!output.commit()) return kUsage;
  if (!args.output.empty() && args.emit != "summary")
    printSummary(std::cout, result.summary, program, result.alarm);
  return kOk;
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
                  "summary (default): run figures; moves: JSON Lines, one motion primitive per "
                  "line; vars: JSON object of every non-vacant variable at the end")
      ->check(CLI::IsMember({"summary", "moves", "vars"}));
  cmd->add_option("-o,--output", args->output, "write the emitted output here (default: stdout)");
  cmd->add_option("--max-steps", args->max_steps,
                  "stop with alarm NCC7204 after this many VM instructions (0: no limit); guards "
                  "against programs that loop forever")
      ->capture_default_str();
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
