#pragma once
// `ncc run`: obtain a verified program (compile the source, or load a .ncb file), execute it
// in the VM and hand every event to the caller, accumulating a run summary.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ncc/bytecode/program.h"
#include "ncc/driver/session.h"
#include "ncc/vm/events.h"

namespace ncc::driver {

// True when `path` names a bytecode file (by its magic number, else by the .ncb extension).
bool isBytecodeFile(const std::filesystem::path& path);

// Compiles the session's input (or loads it when it is bytecode) and verifies the result
// against the session's machine (`check_machine`: also that it was compiled for that machine;
// off for disassembly). Errors are reported to the session's diagnostics.
bool loadProgram(Session& session, bytecode::Program& program, bool check_machine = true);

// Figures of a run. The time is a feed-rate estimate: each move at its programmed feed (rapids
// at the slowest moving axis's rapid speed), dwells as programmed; acceleration is the
// planner's business (a later stage) and not included.
struct RunSummary {
  uint64_t rapids = 0, lines = 0, arcs = 0, dwells = 0, machine_events = 0;
  double cutting_length = 0.0;  // mm along lines and arcs
  double rapid_length = 0.0;    // mm along rapids
  double estimated_seconds = 0.0;
  AxisValues final_position{};
};

struct RunResult {
  std::optional<vm::Alarm> alarm;  // set when the run stopped on an alarm
  RunSummary summary;
  std::vector<std::pair<std::string, double>> variables;  // non-vacant, at the end
};

using EventHandler = std::function<void(const vm::Event&)>;

// A run stops with alarm NCC7204 after this many VM instructions unless told otherwise: a
// program that loops forever must not hang the command line. 100 million instructions are far
// more than a 1,000,000-block program executes.
inline constexpr uint64_t kDefaultMaxSteps = 100'000'000;

RunResult runProgram(const bytecode::Program& program, const MachineConfig& machine,
                     const EventHandler& on_event, uint64_t max_steps = kDefaultMaxSteps);

// Path length of one motion primitive (arcs and helices exactly).
double motionLength(const vm::MotionPrimitive& motion, int axis_count);

}  // namespace ncc::driver
