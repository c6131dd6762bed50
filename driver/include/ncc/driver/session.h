#pragma once
// A compilation session: the input program, its dialect, the machine it is compiled for, and
// the source manager and diagnostics every stage reports to. The CLI, the tests and the
// benchmarks all start here.
#include <filesystem>
#include <optional>
#include <string>

#include "ncc/machine/dialect.h"
#include "ncc/machine/machine_config.h"
#include "ncc/support/diagnostics.h"
#include "ncc/support/source_manager.h"

namespace ncc::driver {

struct SessionOptions {
  std::optional<Dialect> dialect;                   // default: from the file name
  std::optional<std::filesystem::path> machine_file;  // default: the built-in machine
  std::optional<std::filesystem::path> program_dir;   // default: the program's folder
};

// Why a session could not be opened; maps to exit code 2 (usage / configuration).
struct SetupError {
  std::string message;
};

class Session {
 public:
  Session() : diags_(&sources_) {}
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // Registers `input`, resolves the dialect and loads the machine. On failure returns the
  // reason (machine-file diagnostics are in diagnostics() as well).
  std::optional<SetupError> open(const std::filesystem::path& input, const SessionOptions& options);

  SourceManager& sources() { return sources_; }
  DiagnosticEngine& diagnostics() { return diags_; }
  const MachineConfig& machine() const { return machine_; }
  Dialect dialect() const { return dialect_; }
  uint32_t mainFile() const { return main_file_; }
  const std::filesystem::path& input() const { return input_; }
  const std::filesystem::path& programDir() const { return program_dir_; }

 private:
  SourceManager sources_;
  DiagnosticEngine diags_;
  MachineConfig machine_;
  Dialect dialect_ = Dialect::FanucM;
  uint32_t main_file_ = 0;
  std::filesystem::path input_;
  std::filesystem::path program_dir_;
};

// Dialects whose grammar and semantics exist today.
bool dialectSupported(Dialect d);

}  // namespace ncc::driver
