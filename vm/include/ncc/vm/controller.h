#pragma once
// The embedding API (issue 3, docs/embedding.md): verified bytecode + a machine configuration
// in, one setpoint and one simulated actual position per IPO tick out.
//
//   bytecode::Error error;
//   std::unique_ptr<vm::Controller> ctl = vm::Controller::load(bytes, machine, error);
//   if (!ctl) { report(error); return; }
//   vm::TickOutput out;
//   while (ctl->tick(out) == vm::TickStatus::Running) drive(out.commanded);
//   if (const vm::Alarm* alarm = ctl->alarm()) report(*alarm);
//
// It ties together the executor (bytecode -> events), the motion planner (events ->
// setpoints) and the servo model (setpoints -> actual positions).
//
// Real-time discipline: everything is allocated in the constructor; tick() allocates nothing
// (the alarm strings are reserved up front), never throws and does bounded work (at most
// ControllerOptions::max_events_per_tick executor events, the planner's bounded tick, a fixed
// servo step). Deterministic: no clocks, no threads; the same program and machine give
// bit-identical outputs (tests/controller pins a hash).
//
// Links with ncc_vm, ncc_bytecode, ncc_machine and ncc_support only: never the frontend.
// A program with blocks prepared while it runs (PREPARE, docs/runtime.md) evaluates and lowers
// them in prepare(), which then allocates; tick() with prepare_in_tick false does not.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ncc/bytecode/error.h"
#include "ncc/bytecode/program.h"
#include "ncc/machine/machine_config.h"
#include "ncc/vm/controller_stats.h"
#include "ncc/vm/events.h"
#include "ncc/vm/executor.h"
#include "ncc/vm/motion/planner.h"
#include "ncc/vm/servo/servo_model.h"

namespace ncc::vm {

enum class TickStatus : uint8_t {
  Running,   // `out` holds a new tick
  Finished,  // the program ended; `out` repeats the last tick
  Alarm,     // the run stopped with alarm(); `out` is the last tick (a servo alarm: the one
             // that tripped it)
};

struct TickOutput {
  uint64_t tick = 0;                 // k
  double time = 0.0;                 // k * T, s
  AxisValues commanded{};            // interpolator setpoint, machine coordinates
  AxisValues actual{};               // servo model's table position
  AxisValues following_error{};      // per axis, mm (deg)
  double path_velocity = 0.0;        // commanded, mm/s
  SourcePosition where;              // source of the block being interpolated
  std::string_view file;             // program.strings[where.file]; "" when unknown
  TickStatus status = TickStatus::Running;
};

// Sees every executor event the controller takes into its look-ahead, in execution order
// (`ncc run --emit=moves` streams the motion primitives from here). Called from prepare();
// an event that raises an alarm as it is taken (G95 with the spindle stopped) is not passed.
class EventObserver {
 public:
  virtual ~EventObserver() = default;
  virtual void onEvent(const Event& event) = 0;
};

struct ControllerOptions {
  // Most motion segments the planner's look-ahead holds (allocated once); 0: the machine's
  // MachineConfig::lookahead_segments.
  std::size_t window_capacity = 0;
  // Most executor events pulled in one tick: bounds a tick's work when the program emits many
  // events that do not fill the window (M codes, zero-length moves). A lower bound can only
  // make the planner see less ahead (it then plans to brake at the end of what it has).
  uint32_t max_events_per_tick = 1024;
  // Executor instruction budget for the whole run (0: unlimited), alarm NCC7204 when hit.
  // Guards against a macro loop without motion, which would otherwise keep one tick busy.
  uint64_t step_limit = 0;
  // Simulated-time limit of the run, s (0: unlimited), alarm NCC7208 naming the block
  // (run_limits.h): at the tick that reaches it, or as soon as the moves before a block have
  // run when that block cannot end before it even at the machine's top speed.
  double max_seconds = 0.0;
  // Operator overrides at the start of the run (MotionPlanner::setOverrides): feed 0..2
  // (200 %), rapid 0..1. `max_feed_override` (0: `feed_override`) is the highest the feed
  // override may be turned to during the run (setFeedOverride); moves are planned for it.
  // The rapid override may be turned anywhere in 0..1 (setRapidOverride).
  double feed_override = 1.0;
  double rapid_override = 1.0;
  double max_feed_override = 0.0;
  // true: tick() runs prepare() itself before computing the setpoint (the simple loop).
  // false: the caller runs prepare() in each cycle's slack, after tick() (the real-time loop:
  // tick() then holds only the interpolation and the servo step). Either way the outputs are
  // bit-identical as long as prepare() runs once before the first tick and once between two
  // ticks.
  bool prepare_in_tick = true;
  // Optional; must outlive the controller. No effect on the outputs.
  EventObserver* observer = nullptr;
};

class Controller {
 public:
  // Loads and verifies `bytes` against `machine` (including the configuration hash); on
  // failure returns nullptr and fills `error`. Never throws.
  static std::unique_ptr<Controller> load(std::span<const uint8_t> bytes,
                                          const MachineConfig& machine, bytecode::Error& error,
                                          const ControllerOptions& options = {});
  static std::unique_ptr<Controller> loadFile(const std::filesystem::path& path,
                                              const MachineConfig& machine,
                                              bytecode::Error& error,
                                              const ControllerOptions& options = {});
  // Verifies `program` first (as load() does).
  static std::unique_ptr<Controller> create(bytecode::Program program,
                                            const MachineConfig& machine, bytecode::Error& error,
                                            const ControllerOptions& options = {});

  // Like create(), but borrows `program` instead of taking it: `program` must outlive the
  // controller. For a caller that keeps the program anyway (the CLI prints from it): a long
  // program is not held twice (2 M blocks are about 100 MB of code and line table).
  static std::unique_ptr<Controller> createBorrowing(const bytecode::Program& program,
                                                     const MachineConfig& machine,
                                                     bytecode::Error& error,
                                                     const ControllerOptions& options = {});

  // `program` must have passed bytecode::verify() for `machine`. (If it has not, the executor
  // still stops with an alarm instead of crashing.) Keeps its own copies of both.
  Controller(bytecode::Program program, const MachineConfig& machine,
             const ControllerOptions& options = {});
  // The executor and planner hold references into the controller: not copyable or movable.
  Controller(const Controller&) = delete;
  Controller& operator=(const Controller&) = delete;

  // One IPO cycle. See TickStatus for what `out` holds. With prepare_in_tick it first runs
  // prepare(); else only the real-time part: the setpoint from what is already planned, the
  // servo step, the statistics.
  TickStatus tick(TickOutput& out) noexcept;
  // The preparation (a real controller's preprocessing task): pulls executor events into the
  // look-ahead while it wants more, at most max_events_per_tick of them, and plans the next
  // profile piece (MotionPlanner::planAhead). Real-time loops call
  // it after tick(), in the rest of the cycle; a look-ahead that is not refilled in time only
  // makes the path brake at the end of what it holds. Never throws; allocates only to prepare
  // the blocks of a program that prepares them while it runs (PREPARE, docs/runtime.md).
  void prepare() noexcept;

  // The operator turns the feed override knob (fraction, clamped to [0.001,
  // max_feed_override]) between ticks. It takes effect at the next prepare() (the one tick()
  // runs first in the simple loop; in the real-time loop, turn it between tick() and
  // prepare()), which re-plans the queued window before pulling more events: the work is
  // linear in the queued runs (about 70 ns each: planner_bench BM_FeedOverrideTurn), in the
  // preparation, never in the tick's real-time part; no allocation. The motion under way
  // changes speed from the next tick on, within every axis limit
  // (MotionPlanner::setFeedOverride). Deterministic: the same calls between the same ticks
  // give the same trace in both loops. Reads back the value requested.
  void setFeedOverride(double feed) noexcept {
    if (std::isfinite(feed)) pending_feed_override_ = feed;
  }
  double feedOverride() const;
  // The operator turns the rapid override (fraction, clamped to [0.001, 1]), likewise from
  // the next prepare(): rapids change speed from the next tick on, a non-linear G00 on each
  // axis (MotionPlanner::setRapidOverride). Reads back the value
  // requested.
  void setRapidOverride(double rapid) noexcept {
    if (std::isfinite(rapid)) pending_rapid_override_ = rapid;
  }
  double rapidOverride() const {
    return pending_rapid_override_ ? motion::MotionPlanner::rapidOverrideWithin(*pending_rapid_override_)
                                   : planner_.rapidOverride();
  }
  // Feed hold (the operator's button), likewise from the next prepare(): the path brakes to
  // rest along the programmed path within every limit and stands there until released
  // (MotionPlanner::setFeedHold). The run goes on ticking (Running) meanwhile.
  void setFeedHold(bool held) noexcept { pending_feed_hold_ = held; }
  bool feedHold() const { return pending_feed_hold_.value_or(planner_.feedHold()); }

  TickStatus status() const { return status_; }
  // The alarm that stopped the run, or nullptr. Executor alarms (NCC72xx) are raised when the
  // motion queued before them has run, i.e. when the block is reached; servo alarms (25050
  // contour, 25040 standstill) on the tick that trips them.
  const Alarm* alarm() const { return has_alarm_ ? &alarm_ : nullptr; }
  // The program's non-vacant variables as the executor holds them (it runs ahead of the
  // motion by the look-ahead; at the end of the program they are the final values).
  std::vector<std::pair<std::string, double>> variables() const { return executor_.variables(); }
  // Run statistics so far (final once status() != Running).
  RunStatistics statistics() const;

  const bytecode::Program& program() const { return program_; }
  const MachineConfig& machine() const { return machine_; }
  double cycleSeconds() const { return machine_.ipo_cycle_seconds; }
  int axisCount() const { return machine_.axisCount(); }

 private:
  // Runs the program `owned` holds, or else the `borrowed` one.
  Controller(std::unique_ptr<const bytecode::Program> owned, const bytecode::Program* borrowed,
             const MachineConfig& machine, const ControllerOptions& options);
  void pullEvents();
  void raiseServoAlarm(const ServoAlarm& servo_alarm, SourcePosition where);
  void raiseExecutorAlarm();
  void raiseSpindleAlarm();
  void raisePositioningAlarm(int axis, double error, SourcePosition where);
  // NCC7208: the simulated-time limit; `needed` > 0 when a block's lower bound passed it.
  void raiseTimeLimitAlarm(SourcePosition where, double needed);
  // Adds the event's least duration to the run's; false (and the alarm pending) when that
  // passes max_seconds.
  bool withinTimeLimit(const Event& event);
  // After an exact stop or a rapid (SetpointInfo::in_position_check): true once every axis'
  // position error (encoder against the compensated setpoint) is within STOP_LIMIT_FINE;
  // raises 25080 after POSITIONING_TIME.
  bool inPosition(const AxisValues& position_error, uint64_t tick);
  std::string_view fileName(uint32_t file) const;

  // Declaration order matters: the executor refers to program_.
  const MachineConfig machine_;
  const std::unique_ptr<const bytecode::Program> owned_program_;  // null when borrowed
  const bytecode::Program& program_;
  const ControllerOptions options_;
  Executor executor_;
  motion::MotionPlanner planner_;
  // Operator requests since the last prepare(), applied there before the events are pulled.
  std::optional<double> pending_feed_override_;
  std::optional<double> pending_rapid_override_;
  std::optional<bool> pending_feed_hold_;
  ServoModel servo_;
  StatisticsAccumulator stats_;
  uint64_t lookahead_limited_ticks_ = 0;  // ticks with SetpointInfo::lookahead_limited
  // The time limit in ticks (0: none), and the least time of what the executor produced so
  // far; a block that would pass the limit waits in late_block_ until the queue has run.
  uint64_t max_ticks_ = 0;
  double least_seconds_ = 0.0;
  double spindle_rpm_ = 0.0;  // S in force, for the least time of a G95 move
  std::optional<SourcePosition> late_block_;

  Event event_;                   // the executor's output slot (reused)
  bool event_pending_ = false;    // event_ was pulled but the planner had no room
  bool input_done_ = false;       // the executor finished (end of program or alarm)
  uint64_t next_tick_ = 0;
  TickOutput last_;               // the last tick produced
  TickStatus status_ = TickStatus::Running;
  Alarm alarm_;                   // strings reserved in the constructor
  bool has_alarm_ = false;
  // In-position wait: the setpoint is held at the stop until the axes get there.
  bool waiting_in_position_ = false;
  uint64_t wait_start_ = 0;
  motion::SetpointInfo held_info_;
};

}  // namespace ncc::vm
