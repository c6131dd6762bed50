#pragma once
// 1-D jerk-limited (7-phase S-curve) motion along a path of known length.
//
// A profile is: velocity ramp v_start -> v_peak, cruise at v_peak, ramp v_peak -> v_end. Each
// ramp starts and ends at zero acceleration (jerk +j, constant a, jerk -j), so segments can be
// chained without an acceleration step. Closed forms and the case analysis: docs/planner.md.
// Everything here is a pure function of its arguments: no state, no allocation, no throw.

namespace ncc::vm::motion {

// Kinematic state on the path: distance from the start, and its time derivatives.
struct PathState {
  double s = 0.0;  // mm
  double v = 0.0;  // mm/s
  double a = 0.0;  // mm/s^2
  double j = 0.0;  // mm/s^3
};

// A velocity change from `v_from` up to `v_to` (>= v_from) with |a| <= a_max, |j| <= j_max,
// zero acceleration at both ends. Braking is the same ramp run backwards in time.
struct VelocityRamp {
  double v_from = 0.0;
  double v_to = 0.0;
  double jerk = 0.0;      // j_max (0 when the ramp is empty)
  double t_jerk = 0.0;    // duration of each jerk phase
  double t_accel = 0.0;   // duration of the constant-acceleration phase (0: a_max not reached)
  double duration = 0.0;  // 2 * t_jerk + t_accel
  double distance = 0.0;  // (v_from + v_to) / 2 * duration (the ramp is point-symmetric)

  static VelocityRamp make(double v_from, double v_to, double a_max, double j_max);
  // The same from the velocity gain: exact for gains far below v_from's rounding.
  static VelocityRamp fromGain(double v_from, double gain, double a_max, double j_max);
  // State `tau` seconds after the ramp start, 0 <= tau <= duration (clamped).
  PathState at(double tau) const;
};

// Distance a ramp between v1 and v2 (either order) needs.
double rampDistance(double v1, double v2, double a_max, double j_max);
// The room to keep for braking from `v` to an exit not known yet: the longest
// rampDistance(v_exit, v) over v_exit in [0, v]. A jerk-limited brake to a lower speed can
// need more path than one to rest (it is shorter in time but faster): from 43.9 mm/s at
// 2000 mm/s^2 and 45000 mm/s^3, 1.448 mm to 6.04 mm/s against 1.371 mm to rest; up to 9 %
// more at v_exit = v/3.
double brakingReserve(double v, double a_max, double j_max);

// The highest velocity reachable from `v` (accelerating) within distance `length`; by
// symmetry also the highest velocity from which one can brake to `v` within `length`.
// Closed form (a cubic when a_max is not reached, a quadratic when it is).
double reachableVelocity(double v, double length, double a_max, double j_max);
// reachableVelocity(v, ...) - v, computed without the rounding of v.
double reachableGain(double v, double length, double a_max, double j_max);
// The lowest velocity one can brake to from `v0` within `length` (0 if a stop fits, up to
// rounding); a bisection, for planProfile's unreachable end velocity.
double lowestReachableVelocity(double v0, double length, double a_max, double j_max);

struct SCurveProfile {
  double length = 0.0;
  double v_start = 0.0;
  double v_peak = 0.0;
  double v_end = 0.0;      // the end velocity actually used (see end_reachable)
  VelocityRamp accel;      // v_start -> v_peak
  VelocityRamp decel;      // v_end -> v_peak, run backwards from the end
  double t_cruise = 0.0;
  double duration = 0.0;
  // False when the requested end velocity could not be reached within `length`: when
  // accelerating, v_end was lowered to the reachable maximum (look-ahead lowers the next
  // junction); when braking, v_end was raised to the lowest reachable velocity (the caller's
  // backward pass was wrong: a planner bug, reported rather than hidden).
  bool end_reachable = true;

  // State at time t (0 <= t <= duration; clamped). s(duration) == length exactly: the
  // braking ramp is evaluated from the end.
  PathState at(double t) const;
};

// The time-optimal profile over `length` from v_start to v_end with |v| <= v_max,
// |a| <= a_max, |j| <= j_max. Requires positive limits. length <= 0 gives an empty profile.
SCurveProfile planProfile(double length, double v_start, double v_end, double v_max,
                          double a_max, double j_max);

// Cuts a profile under way for a new speed limit `limit` from its local time `next` (the next
// tick) on: a ramp up that has not reached its jerk-down phase, when `limit` is below its
// peak, ends at `limit` (the same ramp to a lower gain), or as early as a = 0 allows from
// `next` on if that is above `limit`; else a cruise ends at `next` (or where it begins). The
// profile then ends there at a = 0 (v_end = v_peak, no braking ramp, length and duration
// shortened); every state before is unchanged. False, the profile
// untouched, when it is braking or in its last jerk phase: it runs on to its end.
bool cutProfile(SCurveProfile& p, double next, double limit);

}  // namespace ncc::vm::motion
