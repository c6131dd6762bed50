#pragma once
// Non-linear ("per-axis") positioning: G00 with FANUC LRP (No.1401#1) = 0, Mazak likewise.
//
// Every moving axis runs its own rest-to-rest jerk-limited S-curve (scurve.h) from `from` to
// `to` at its own rapid velocity and acceleration, with kSmoothJerkShare of its jerk (the same
// share lines use, so sampled jerk keeps the same margin). All axes start together and each
// arrives when its own profile ends: the path is a dog-leg, not a straight line, and the move
// takes as long as the slowest axis. Axes without travel stand still; rotary axes are plain
// axes here (deg, deg/s, ...).
//
// Fixed-size storage (one profile per axis slot), no allocation, no throw; every result is a
// pure function of the inputs to make() and of t.
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
  // with travel uses rapid_velocity[i], acceleration[i] and kSmoothJerkShare * jerk[i].
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

  // The slowest axis' time: when the last axis arrives.
  double duration() const { return duration_; }
  // When axis i arrives (0 for axes without travel).
  double axisDuration(int axis) const { return profiles_[axis].duration; }
  // Axis i's 1-D profile over |to_i - from_i| (unsigned; the direction is applied on top).
  const SCurveProfile& axisProfile(int axis) const { return profiles_[axis]; }

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
  double clampTime(double t) const;

  bool valid_ = true;
  int count_ = 0;
  AxisValues from_{};
  AxisValues to_{};
  std::array<double, kMaxAxes> sign_{};  // +1 / -1 per moving axis, 0 for standing axes
  std::array<SCurveProfile, kMaxAxes> profiles_{};
  double duration_ = 0.0;
};

}  // namespace ncc::vm::motion
