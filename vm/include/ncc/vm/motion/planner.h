#pragma once
// MotionPlanner: the executor's motion primitives in, one setpoint per IPO tick out.
//
//   MotionPlanner planner(machine, 1024);
//   for (uint64_t k = 0;; ++k) {
//     while (planner.canAccept() && executor.next(event)) planner.accept(event);
//     if (executor finished) planner.endOfProgram();
//     if (!planner.setpoint(k, position, info)) break;   // program done
//   }
//
// Real-time discipline: everything is allocated in the constructor; push/accept/setpoint
// allocate nothing, never throw, and do bounded work (a push: the backward pass over the
// segments whose plan changes; a tick: at most the queued segments). Deterministic: the same
// pushes at the same ticks give bit-identical setpoints.
//
// G64 (continuous_path.h): feed lines are held back one primitive so that their end vertex
// can be blended within the corner tolerance or passed as part of a smooth chain.
//
// Overrides (docs/planner.md, "Overrides and feed hold"): the feed and rapid overrides may be
// turned during the run (setFeedOverride, setRapidOverride).
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "ncc/machine/axes.h"
#include "ncc/machine/machine_config.h"
#include "ncc/vm/events.h"
#include "ncc/vm/motion/continuous_path.h"
#include "ncc/vm/motion/interpolator.h"
#include "ncc/vm/motion/limits.h"
#include "ncc/vm/motion/lookahead.h"

namespace ncc::vm::motion {

class MotionPlanner {
 public:
  // `window_capacity`: most segments held by the look-ahead (the ring is allocated here).
  MotionPlanner(const MachineConfig& machine, std::size_t window_capacity);

  // True while pushing more could still change the plan: the ring has room and the queued
  // path is shorter than the look-ahead's reach (LookAhead::wantsMore).
  bool canAccept() const { return hasRoom() && queue_.wantsMore(); }
  // True while the ring has room for any primitive (push succeeds).
  bool hasRoom() const { return queue_.room() >= ContinuousPath::kSlotsPerMove; }

  // Takes one primitive (its `from` must be where the previous one ended). False when the
  // ring is too full; nothing is taken then.
  bool push(const MotionPrimitive& motion);
  // Routes an executor event: motion to push(), S/M03/M04/M05 to the spindle state (feed per
  // rev, dwell in revolutions), M00/M01/M02/M30 to an exact stop. False only when the ring is
  // full.
  bool accept(const Event& event);
  void setSpindleSpeed(double rpm) { spindle_rpm_ = rpm; }
  // Operator overrides as fractions, set before the run: `feed` scales every programmed feed
  // (up to 200 %), `rapid` the axes' rapid speeds (up to 100 %). `max_feed` (default: `feed`)
  // is the highest the feed override may be turned to during the run (setFeedOverride):
  // moves are planned for it, since a curve's tangential limits shrink as its speed grows, so
  // a higher maximum costs time on fast curves. Values outside are clamped (at least 0.1 %).
  void setOverrides(double feed, double rapid, double max_feed = 0.0);
  // The operator turns the feed override knob during the run, between ticks (fraction,
  // clamped to [0.1 %, max_feed]; not G63 tapping, not rapids). The queued path is re-planned
  // at once (O(queued runs)); the motion under way changes speed from the next tick on (a
  // cruise is cut there; a ramp up ends early when the new limit is below its peak; a brake
  // runs to its end), within every axis limit (Interpolator::commitForReplan).
  // Deterministic: the same calls before the same ticks give the same setpoints. 0 % is not a
  // feed hold: it is taken as 0.1 %.
  void setFeedOverride(double feed);
  double feedOverride() const { return feed_override_ * queue_.feedScale(); }
  // What setFeedOverride(feed) turns the knob to: clamped to [0.1 %, max_feed].
  double feedOverrideWithin(double feed) const {
    return std::clamp(feed, kMinFeedOverride, feed_override_);
  }
  // The operator turns the rapid override during the run, between ticks (fraction, clamped
  // to [0.1 %, 100 %]). Rapids are planned at 100 % and the override scales their speed limit
  // only (their acceleration and jerk are a line's), so a turn up never breaks a limit.
  // Re-plans like setFeedOverride; a non-linear G00 under way re-plans its own axis profiles
  // (AxisRapid::replan).
  void setRapidOverride(double rapid);
  double rapidOverride() const { return queue_.scales().rapid; }
  static double rapidOverrideWithin(double rapid) {
    return std::clamp(rapid, kMinRapidOverride, 1.0);
  }
  // Feed hold (the operator's button), between ticks: the path brakes to rest along the
  // programmed path as the limits allow, rapids included (a non-linear G00 stops each axis on
  // its own; a G63 tap and a dwell under way finish first), and stands there; released, it
  // goes on from there.
  // Re-plans like setFeedOverride. Deterministic like it.
  void setFeedHold(bool held);
  bool feedHold() const { return queue_.held(); }
  // The path comes to rest at the end of the last queued segment (M00/M01).
  void stop();
  // No more input: setpoint() returns false once everything queued has run.
  void endOfProgram();

  // The preparation's share of the forward pass, called after pushing: plans the piece that
  // follows the running one (Interpolator::planNextPiece), so that the tick finds it ready,
  // and brings the segments the tick reads next into cache (LookAhead::prefetchFront).
  // Optional: setpoint() gives the same result without it, only doing that work itself.
  void planAhead();

  // Setpoint of tick k (k increasing by one per call, t = k * ipo_cycle_seconds). Returns
  // false when the program is done; while waiting for input it holds position and returns
  // true.
  bool setpoint(uint64_t k, AxisValues& out, SetpointInfo& info);

  bool finished() const { return ended_ && !path_.holding() && queue_.empty(); }
  // Feed per revolution (G95 move, or a dwell in revolutions) with the spindle stopped: S is 0
  // (or was never given) or M05 is active. The planner then takes no more input (as if the
  // program ended there) and reports the block; the caller raises alarm NCC7207 when what
  // was queued before it has run.
  bool spindleAlarm() const { return spindle_alarm_; }
  const SourcePosition& spindleAlarmWhere() const { return spindle_alarm_where_; }
  const AxisLimits& limits() const { return limits_; }
  std::size_t queued() const { return queue_.size(); }

 private:
  // Segments planAhead() warms for the next tick: a cycle passes a blend and the lines on
  // either side of it, a few more when segments are shorter than a cycle's travel.
  static constexpr std::size_t kSegmentsWarmed = 4;
  // After endOfProgram(): queues the held line once the ring has room. True when nothing more
  // will be queued (the last run is final).
  bool closeInput();
  // push() of a G00: a linear one joins the path like a line; a non-linear one is its own
  // piece, from rest to rest.
  void pushRapid(const MotionPrimitive& m);
  // Where the motion under way is committed to before the speed limits change to those of
  // `scales` (Interpolator::commitForReplan).
  Commitment commitFor(const SpeedScales& scales);
  // Applies `scales` to the queue (re-planned from where the motion under way commits to).
  void changeScales(const SpeedScales& scales);

  AxisLimits limits_;  // what every segment is planned with (rapids at 100 %)
  // limits_ with the live rapid override applied to the rapid speeds: a non-linear G00's axis
  // profiles (Interpolator).
  AxisLimits rapid_limits_;
  static constexpr double kMinRapidOverride = 1e-3;
  static constexpr double kMinFeedOverride = 1e-3;
  static constexpr double kMaxFeedOverride = 2.0;
  double feed_override_ = 1.0;  // the one moves are planned with: the highest the knob may reach
  LookAhead queue_;
  ContinuousPath path_;
  Interpolator interpolator_;
  double spindle_rpm_ = 0.0;
  bool spindle_stopped_ = false;  // M05 seen (and no M03/M04 since)
  bool spindle_alarm_ = false;
  SourcePosition spindle_alarm_where_;
  bool ended_ = false;
};

}  // namespace ncc::vm::motion
