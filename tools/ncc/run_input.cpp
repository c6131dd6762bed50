#include "run_input.h"

#include "absl/strings/str_cat.h"
#include "ncc/driver/run.h"
#include "progress.h"

namespace ncc::cli {

void RunInput::addTo(CLI::App& command, const std::string& probe_help,
                     const std::string& signal_help) {
  command.add_option("--probe", probe, probe_help);
  command.add_option("--signal", signal, signal_help);
}

std::optional<int> loadForRun(driver::Session& session, const std::filesystem::path& input,
                              const CommonOptions& common, const RunInput& run,
                              MachineConfig& machine, bytecode::Program& program) {
  if (std::optional<int> failed = openSession(session, input, common)) return *failed;
  if (session.variablesFile() && driver::isBytecodeInput(session)) {
    printError("NCC0018", "--vars needs a source program: a bytecode file's variables were fixed "
                          "when it was compiled");
    return kUsage;
  }
  // Run-time properties (not hashed): the VM applies them, the compile does not see them.
  machine = session.machine();
  for (const std::string& text : run.probe) {
    if (std::optional<std::string> error = setProbeFromOption(machine.probe, machine.axes, text)) {
      printError("NCC0308", absl::StrCat("--probe: ", *error));
      return kUsage;
    }
  }
  for (const std::string& text : run.signal) {
    if (std::optional<std::string> error = setSignalFromOption(machine.signals, text)) {
      printError("NCC0310", absl::StrCat("--signal: ", *error));
      return kUsage;
    }
  }
  bool loaded = false;
  std::optional<driver::SetupError> no_scratch;  // NCC0004: $TMPDIR unusable
  {
    CompileProgress progress(session);
    // Paged: the run's memory does not grow with the program (docs/cli.md, "ncc run memory").
    loaded = driver::loadProgram(session, program, /*check_machine=*/true,
                                 driver::Residence::Paged, &no_scratch);
  }
  if (no_scratch) {
    printDiagnostics(session);
    printError(no_scratch->code, no_scratch->message);
    return kUsage;
  }
  printDiagnostics(session);  // errors, or the warnings of the compile
  if (!loaded) return kProgramError;
  session.diagnostics().clear();
  return std::nullopt;
}

}  // namespace ncc::cli
