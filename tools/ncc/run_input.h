#pragma once
// What `ncc run` and `ncc plot` share before the VM starts: the machine's run-time properties
// (--probe, --signal: not part of the compiled program) and the program, compiled from a source
// or loaded from a .ncb, with the compile's diagnostics printed.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "CLI/CLI.hpp"
#include "cli.h"
#include "ncc/bytecode/program.h"
#include "ncc/driver/session.h"
#include "ncc/machine/machine_config.h"

namespace ncc::cli {

struct RunInput {
  std::vector<std::string> probe;   // "AXIS=VALUE", as given
  std::vector<std::string> signal;  // "N=VALUE", as given
  // --probe and --signal, with `probe_help` and `signal_help` as their help texts.
  void addTo(CLI::App& command, const std::string& probe_help, const std::string& signal_help);
};

// Opens the session for `input`, refuses --vars with a .ncb (NCC0018), applies --probe
// (NCC0308) and --signal (NCC0310) to a copy of the session's machine in `machine`, and
// compiles or loads the program into `program` (paged). The exit code when it cannot run.
std::optional<int> loadForRun(driver::Session& session, const std::filesystem::path& input,
                              const CommonOptions& common, const RunInput& run,
                              MachineConfig& machine, bytecode::Program& program);

}  // namespace ncc::cli
