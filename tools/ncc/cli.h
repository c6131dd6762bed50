#pragma once
// The `ncc` command line: options shared by every command and the command entry points.
// Exit codes (docs/cli.md): 0 ok, 1 errors in the program, 2 usage (also an unreadable input
// or an output that cannot be written), 3 alarm at run time.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "CLI/CLI.hpp"
#include "ncc/driver/session.h"

namespace ncc::cli {

enum ExitCode : int { kOk = 0, kProgramError = 1, kUsage = 2, kRuntimeAlarm = 3 };

// A driver error on stderr: `ncc: error[CODE]: message` (codes NCC00xx in docs/cli.md).
void printError(std::string_view code, std::string_view message);

// --dialect, --machine, --program-dir, --max-time, --max-steps, --max-idle-blocks,
// --max-back-jumps, --vars, --defer: accepted by every command that reads a program.
struct CommonOptions {
  std::string dialect;
  std::string machine_file;
  std::string program_dir;
  eval::LoopLimits loop_limits;
  driver::RunBounds bounds;
  // Set by the commands that run the program (run, plot): a bound the compile passes is left to
  // the run's own alarm.
  driver::BoundAction bound_action = driver::BoundAction::Report;
  std::string vars_file;
  bool defer = false;
  void addTo(CLI::App& command);
  // Converts to session options; an unknown dialect name is a usage error (message returned).
  std::optional<std::string> toSessionOptions(driver::SessionOptions& out) const;
};

// --max-steps N and --max-time SECONDS, the bounds of every run and compile (docs/cli.md), with
// their checks in one place for every command that takes them: a negative count, a negative,
// non-finite or huge time is a usage error (NCC0010, exit 2) rather than a run without a bound.
void addRunLimitOptions(CLI::App& command, uint64_t& max_steps, double& max_time);

// Opens a session for `input` ("-": the standard input), printing setup errors. Returns an
// exit code on failure. A --vars file that cannot be one (a device, a FIFO, too large) is
// NCC0019, before anything is read.
std::optional<int> openSession(driver::Session& session, const std::filesystem::path& input,
                               const CommonOptions& common);

// Prints the session's diagnostics to stderr.
void printDiagnostics(driver::Session& session);

void addCompileCommand(CLI::App& app, int& exit_code);
void addCheckCommand(CLI::App& app, int& exit_code);
void addDisCommand(CLI::App& app, int& exit_code);
void addRunCommand(CLI::App& app, int& exit_code);
void addTraceCommand(CLI::App& app, int& exit_code);
void addPlotCommand(CLI::App& app, int& exit_code);

}  // namespace ncc::cli
