#pragma once
// Non-linear ("per-axis") positioning: G00 with FANUC LRP (No.1401#1) = 0, Mazak likewise.
//
// Every moving axis runs its own rest-to-rest jerk-limited S-curve (scurve.h) from `from` to
// `to` at its own rapid velocity, acceleration and jerk (kBetweenStopsJerkShare: it starts and
// ends at rest, so no junction step needs room). All axes start together and each
// arrives when its own profile ends: the path is a dog-leg, not a straight line, and the move
// takes as long as the slowest axis. Axes without travel stand still; rotary axes are plain
// axes here (deg, deg/s, ...).
//
// The operator may change the speeds while it runs (replan(): a live rapid override, feed
// hold and its release): each axis then cuts its profile under way like a path piece
// (cutProfile) and goes on with new legs from there: a brake to rest under hold, else a
// brake to the new speed and a profile to `to`. An axis has at most kLegs legs; after the
// last it stands where it ended (at `to` once arrived).
//
// Fixed-size storage (kLegs profiles per axis slot), no allocation, no throw; every result is
// a pure function of the inputs to make(), of the replan() calls and of t.
#include <array>

#include "ncc/machine/axes.h"
#include "ncc/vm/motion/limits.h"
#include "ncc/vm/motion/scurve.h"

namespace ncc::vm::motion {

// Path quantities of a per-axis rapid at one instant, for SetpointInfo. The path is the curve
// traced by the axis positions; there is no path length parameter.
struct AxisRapidMotion {
  double velocity = 0.0;      // |v|, the Euclidean norm of the axis velocities
  double acceleration = 0.0;  // d|v|/dt (negative while the path slows down)
  double jerk = 0.0;          // d2|v|/dt2
};

class AxisRapid {
 public:
  // The per-axis rapid over the first `limits.count` axes (other slots stay at `to`). Axis i
  // with travel uses rapid_velocity[i], acceleration[i] and kBetweenStopsJerkShare * jerk[i].
  // Requires finite positions and, for every axis that moves, positive finite limits (the
  // machine file guarantees them); otherwise valid() is false and the move has duration 0.
  static AxisRapid make(const AxisValues& from, const AxisValues& to, const AxisLimits& limits);
  // Whether make() would give a valid rapid, without planning its profiles (the planner checks
  // this when it queues the move; the interpolator makes it when the move starts).
  static bool possible(const AxisValues& from, const AxisValues& to, const AxisLimits& limits);

  bool valid() const { return valid_; }
  int axisCount() const { return count_; }
  const AxisValues& from() const { return from_; }
  const AxisValues& to() const { return to_; }

  // The slowest axis' time: when the last axis arrives (infinite while an axis stands short
  // of `to` under a feed hold).
  double duration() const { return duration_; }
  // When axis i arrives (0 for axes without travel; infinite while it stands short of `to`).
  double axisDuration(int axis) const;
  // Axis i's first leg (the whole 1-D profile over |to_i - from_i| until a replan(); unsigned:
  // the direction is applied on top).
  const SCurveProfile& axisProfile(int axis) const { return legs_[axis][0].profile; }

  // From local time `next` (the next tick) on: under `held`, every axis brakes to rest as its
  // limits allow and stands; else each goes on to `to` at its rapid speed in `limits`. An
  // axis braking to its end, or in the last jerk phase of a ramp without cruise, runs on to the
  // end of that profile first. Results for t >= `next` are as before until `next`; earlier
  // times are no longer kept (legs that ended are dropped), which the interpolator never asks.
  void replan(double next, const AxisLimits& limits, bool held);

  // Axis positions at time t from the start, t clamped to [0, duration()]. Axis i gives
  // to[i] bit-exactly once t >= axisDuration(i) (so everything is `to` for t >= duration()),
  // and from[i] at t = 0 (t <= 0) while it still has travel. Positions never leave the
  // interval between from[i] and to[i] (no overshoot).
  void position(double t, AxisValues& out) const;
  // Signed axis velocities / accelerations at t (zero outside [0, duration()]).
  void velocity(double t, AxisValues& out) const;
  void acceleration(double t, AxisValues& out) const;
  // Signed state of axis i along its own axis (s: signed distance from from[i]).
  PathState axisState(int axis, double t) const;
  // Path speed and its derivatives at t.
  AxisRapidMotion pathMotion(double t) const;
  double pathSpeed(double t) const { return pathMotion(t).velocity; }

 private:
  // One stretch of an axis' motion: `profile` from local time t0, at distance s0 from `from`.
  struct Leg {
    double t0 = 0.0, s0 = 0.0;
    SCurveProfile profile;
    double end() const { return t0 + profile.duration; }
  };
  // A leg now, the first after make(), a cut one and the two a replan() adds after it.
  static constexpr int kLegs = 3;

  double clampTime(double t) const;
  // Axis i's unsigned 1-D state at t (distance from from[i]).
  PathState legState(int axis, double t) const;
  void updateDuration();

  bool valid_ = true;
  bool replanned_ = false;  // legs beyond the first profile: the general evaluation
  int count_ = 0;
  AxisValues from_{};
  AxisValues to_{};
  std::array<double, kMaxAxes> sign_{};  // +1 / -1 per moving axis, 0 for standing axes
  std::array<double, kMaxAxes> travel_{};  // |to - from|
  std::array<std::array<Leg, kLegs>, kMaxAxes> legs_{};
  std::array<int, kMaxAxes> leg_count_{};
  std::array<bool, kMaxAxes> stops_short_{};  // held: it stands short of `to` after its legs
  double duration_ = 0.0;
};

}  // namespace ncc::vm::motion
