#pragma once
// A compilation session: the input program, its dialect, the machine it is compiled for, and
// the source manager and diagnostics every stage reports to. The CLI, the tests and the
// benchmarks all start here.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ncc/eval/loop_limits.h"
#include "ncc/machine/dialect.h"
#include "ncc/machine/machine_config.h"
#include "ncc/support/diagnostics.h"
#include "ncc/support/source_manager.h"
#include "ncc/vm/run_limits.h"

namespace ncc::driver {

// A run stops with alarm NCC7204 after this many VM instructions unless told otherwise: a
// guard against programs that loop forever without moving.
inline constexpr uint64_t kDefaultMaxSteps = 100'000'000;

// The bounds of a run (docs/cli.md, Bounds), 0: no limit. The compiler applies them too
// (driver/src/run_budget.h), so that every command ends an endless program.
struct RunBounds {
  double max_seconds = vm::kDefaultMaxRunSeconds;  // --max-time: simulated s, NCC7208
  uint64_t max_steps = kDefaultMaxSteps;           // --max-steps: VM instructions, NCC7204
};

// Where the compiler passes a bound: `Report` it as an error (compile, check), or `LeaveToRun`:
// stop there quietly, the program compiled so far going to the VM, which raises the same alarm
// inside it (run, plot).
enum class BoundAction : uint8_t { Report, LeaveToRun };

struct SessionOptions {
  std::optional<Dialect> dialect;                   // default: from the file name
  std::optional<std::filesystem::path> machine_file;  // default: the built-in machine
  std::optional<std::filesystem::path> program_dir;   // default: the program's folder
  // What ends an endless loop that neither moves nor dwells (NCC2419).
  eval::LoopLimits loop_limits;
  RunBounds bounds;
  BoundAction bound_action = BoundAction::Report;
  // --vars FILE: persistent common variables loaded before compiling (variables_file.h).
  std::optional<std::filesystem::path> variables_file;
  // --defer: the VM prepares every block while the program runs, as it does from the first
  // block that needs a run-time value (docs/runtime.md).
  bool defer = false;
};

// What a compile found out about the program, beyond its diagnostics (ncc plot uses it).
struct CompileFacts {
  bool cutter_comp = false;           // a block asked for cutter compensation (G41/G42)
  bool prepared_at_run_time = false;  // blocks were left to the VM's block preparation
};

// Why a session could not be opened; maps to exit code 2 (usage / configuration). Codes
// (docs/cli.md): NCC0001 unreadable input, NCC0002 unknown or unsupported dialect, NCC0003
// invalid machine file.
struct SetupError {
  std::string code;
  std::string message;
};

// A file a session reads, and what it is to the session ("the program", "the machine file",
// "the subprogram"), for messages.
struct InputFile {
  std::filesystem::path path;
  const char* role;
};

// The input name that means the standard input.
inline constexpr const char* kStdinName = "-";

class Session {
 public:
  Session() : diags_(&sources_) {}
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // Registers `input` ("-": reads the standard input whole, shown as <stdin>), resolves the
  // dialect and loads the machine. On failure returns the reason (machine-file diagnostics
  // are in diagnostics() as well).
  std::optional<SetupError> open(const std::filesystem::path& input, const SessionOptions& options);

  SourceManager& sources() { return sources_; }
  DiagnosticEngine& diagnostics() { return diags_; }
  const MachineConfig& machine() const { return machine_; }
  Dialect dialect() const { return dialect_; }
  uint32_t mainFile() const { return main_file_; }
  const std::filesystem::path& input() const { return input_; }
  const std::filesystem::path& programDir() const { return program_dir_; }
  const eval::LoopLimits& loopLimits() const { return loop_limits_; }
  const RunBounds& bounds() const { return bounds_; }
  BoundAction boundAction() const { return bound_action_; }
  const std::optional<std::filesystem::path>& variablesFile() const { return variables_file_; }
  bool defer() const { return defer_; }
  // false: compiles keep the programmed path, cutter compensation's requests dropped
  // (passes::PipelineOptions::compensate; `ncc plot` draws that path beside the tool centre's).
  bool compensate() const { return compensate_; }
  void setCompensate(bool on) { compensate_ = on; }
  // Set by each compile (compile.h) of this session: what the last one found.
  const CompileFacts& compileFacts() const { return compile_facts_; }
  CompileFacts& compileFacts() { return compile_facts_; }
  // The standard input's bytes when the input is "-", else nullptr.
  const std::string* stdinContents() const { return sources_.buffer(main_file_); }
  // Every file on disk the session reads: the program (source or bytecode), the subprograms
  // registered so far and the machine file. An output must never replace one of them.
  std::vector<InputFile> inputFiles() const;
  // Called with each block's location as the compile reads it (progress display); optional.
  void setBlockObserver(std::function<void(const SourceLocation&)> observer) {
    block_observer_ = std::move(observer);
  }
  const std::function<void(const SourceLocation&)>& blockObserver() const { return block_observer_; }

 private:
  SourceManager sources_;
  DiagnosticEngine diags_;
  MachineConfig machine_;
  Dialect dialect_ = Dialect::FanucM;
  uint32_t main_file_ = 0;
  std::filesystem::path input_;
  std::filesystem::path program_dir_;
  std::optional<std::filesystem::path> machine_file_;
  eval::LoopLimits loop_limits_;
  RunBounds bounds_;
  BoundAction bound_action_ = BoundAction::Report;
  std::optional<std::filesystem::path> variables_file_;
  bool defer_ = false;
  bool compensate_ = true;
  CompileFacts compile_facts_;
  std::function<void(const SourceLocation&)> block_observer_;
};

// Dialects whose grammar and semantics exist today.
bool dialectSupported(Dialect d);

}  // namespace ncc::driver
