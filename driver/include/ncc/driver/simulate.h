#pragma once
// `ncc run`'s simulation: the program through the VM's planner, interpolator and servo model
// (vm::Controller), tick by tick, optionally writing a trace.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ncc/bytecode/program.h"
#include "ncc/driver/trace.h"
#include "ncc/machine/machine_config.h"
#include "ncc/vm/controller_stats.h"
#include "ncc/vm/controller.h"
#include "ncc/vm/events.h"
#include "ncc/vm/run_limits.h"

namespace ncc::driver {

struct SimulationResult {
  vm::RunStatistics statistics;
  std::optional<vm::Alarm> alarm;  // the alarm that stopped the run
  AxisValues final_commanded{};    // the last setpoint
  std::string error;               // the program could not be loaded into the controller
  // Non-vacant variables when the run stopped (the executor runs ahead of the motion by the
  // look-ahead: exact at the program's end and at an executor alarm).
  std::vector<std::pair<std::string, double>> variables;
};

// The operator turns the feed override knob to `feed` (fraction) at `seconds` into the run:
// applied before the first tick at or after that time.
struct FeedOverrideTurn {
  double seconds = 0.0;
  double feed = 1.0;
};

// The operator turns the rapid override to `rapid` (fraction) at `seconds` into the run:
// applied before the first tick at or after that time.
struct RapidOverrideTurn {
  double seconds = 0.0;
  double rapid = 1.0;
};

// The operator holds the feed (feed hold) at `seconds` into the run and releases it
// `duration` seconds later.
struct FeedHoldSpan {
  double seconds = 0.0;
  double duration = 0.0;
};

// The operator's settings for a simulated run.
struct SimulationOptions {
  uint64_t max_steps = 0;       // VM instruction budget (0: no limit), alarm NCC7204
  // Simulated-time limit, s (0: no limit), alarm NCC7208 (vm/run_limits.h).
  double max_seconds = vm::kDefaultMaxRunSeconds;
  double feed_override = 1.0;   // fraction, up to 2 (200 %), at the start
  double rapid_override = 1.0;  // fraction, up to 1
  // Turns of the feed override during the run, in time order. Moves are planned for the
  // highest feed override of the run (vm::ControllerOptions::max_feed_override).
  std::vector<FeedOverrideTurn> feed_override_turns;
  // Turns of the rapid override during the run, in time order.
  std::vector<RapidOverrideTurn> rapid_override_turns;
  // Feed holds, in time order, not overlapping.
  std::vector<FeedHoldSpan> feed_holds;
  // Sees every executor event the controller takes (vm::EventObserver); optional.
  vm::EventObserver* observer = nullptr;
  // Called every kProgressTicks ticks with the latest one (progress display); optional.
  std::function<void(const vm::TickOutput&)> progress;
};

inline constexpr uint64_t kProgressTicks = 4096;

// Runs `program` to its end (or an alarm, or the instruction budget).
SimulationResult simulate(const bytecode::Program& program, const MachineConfig& machine,
                          TraceWriter* trace, const SimulationOptions& options);

}  // namespace ncc::driver
