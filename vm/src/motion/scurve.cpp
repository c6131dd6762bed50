#include "ncc/vm/motion/scurve.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace ncc::vm::motion {
namespace {

// Velocity gained by one jerk-up/jerk-down pair that just touches a_max: a_max^2 / j_max.
// Below it a ramp is triangular in acceleration (a_max not reached).
double fullJerkVelocity(double a_max, double j_max) { return a_max * a_max / j_max; }

}  // namespace

VelocityRamp VelocityRamp::make(double v_from, double v_to, double a_max, double j_max) {
  return fromGain(v_from, v_to - v_from, a_max, j_max);
}

VelocityRamp VelocityRamp::fromGain(double v_from, double dv, double a_max, double j_max) {
  VelocityRamp r;
  r.v_from = v_from;
  r.v_to = v_from;
  if (!(dv > 0.0)) return r;
  r.v_to = v_from + dv;
  r.jerk = j_max;
  if (dv >= fullJerkVelocity(a_max, j_max)) {
    r.t_jerk = a_max / j_max;
    r.t_accel = dv / a_max - r.t_jerk;
  } else {
    r.t_jerk = std::sqrt(dv / j_max);
  }
  r.duration = 2.0 * r.t_jerk + r.t_accel;
  // (v_from + v_to) / 2 * duration, with the gain kept exact.
  r.distance = (v_from + 0.5 * dv) * r.duration;
  return r;
}

PathState VelocityRamp::at(double tau) const {
  tau = std::clamp(tau, 0.0, duration);
  const double j = jerk;
  const double peak_a = j * t_jerk;
  if (tau <= t_jerk) {  // jerk +j from rest acceleration
    return {v_from * tau + j * tau * tau * tau / 6.0, v_from + 0.5 * j * tau * tau, j * tau, j};
  }
  if (tau <= t_jerk + t_accel) {  // constant acceleration
    const double u = tau - t_jerk;
    const double v1 = v_from + 0.5 * j * t_jerk * t_jerk;
    const double s1 = v_from * t_jerk + j * t_jerk * t_jerk * t_jerk / 6.0;
    return {s1 + v1 * u + 0.5 * peak_a * u * u, v1 + peak_a * u, peak_a, 0.0};
  }
  // Jerk -j down to zero acceleration: mirror of the first phase about the ramp end, so the
  // end state (distance, v_to, a = 0) is exact.
  const double r = duration - tau;
  return {distance - (v_to * r - j * r * r * r / 6.0), v_to - 0.5 * j * r * r, j * r, -j};
}

double rampDistance(double v1, double v2, double a_max, double j_max) {
  return VelocityRamp::make(std::min(v1, v2), std::max(v1, v2), a_max, j_max).distance;
}

double brakingReserve(double v, double a_max, double j_max) {
  // rampDistance(v_exit, v) with dv = v - v_exit: (v + v_exit) sqrt(dv / j) while the ramp is
  // triangular (dv <= b = a^2/j), (v + v_exit) (dv / a + a / j) / 2 beyond. Each is largest
  // where its slope in v_exit is 0 (v_exit = v/3, and b/2), so the longest is there, at the
  // border of the two (v_exit = v - b), or at v_exit = 0.
  const double b = fullJerkVelocity(a_max, j_max);
  double longest = rampDistance(0.0, v, a_max, j_max);
  for (const double v_exit : {v / 3.0, 0.5 * b, v - b})
    if (v_exit > 0.0 && v_exit < v) longest = std::max(longest, rampDistance(v_exit, v, a_max, j_max));
  return longest;
}

double reachableGain(double v, double length, double a_max, double j_max) {
  if (length <= 0.0) return 0.0;
  const double b = fullJerkVelocity(a_max, j_max);
  // Distance of the ramp v -> v + b (the largest triangular one): (2v + b) * b / a.
  const double d_full = (2.0 * v + b) * b / a_max;
  if (length <= d_full) {
    // Triangular: (2v + x^2) x = L sqrt(j) with x = sqrt(w - v), i.e. x^3 + p x + q = 0,
    // p = 2v >= 0, q = -L sqrt(j) < 0: one real root. Cardano with u^3 = -q/2 + sqrt(D),
    // w = p / (3u); x = u - w = -q / (u^2 + u w + w^2) avoids cancellation.
    const double p = 2.0 * v;
    const double q = -length * std::sqrt(j_max);
    const double disc = 0.25 * q * q + p * p * p / 27.0;
    const double u = std::cbrt(-0.5 * q + std::sqrt(disc));
    const double w = p / (3.0 * u);
    const double x = -q / (u * u + u * w + w * w);
    return x * x;
  }
  // Trapezoidal: (w^2 - v^2) / (2a) + (v + w) a / (2j) = L, i.e. w^2 + b w + c = 0 with
  // c = v b - v^2 - 2 a L < 0. Positive root in the cancellation-free form.
  const double c = v * b - v * v - 2.0 * a_max * length;
  // Never below 0: where a^2/j and a L / v are below v's last digit the root rounds a unit or
  // two under v (review 12), and the look-ahead relies on reaching at least v.
  return std::max(-2.0 * c / (b + std::sqrt(b * b - 4.0 * c)) - v, 0.0);
}

double reachableVelocity(double v, double length, double a_max, double j_max) {
  return v + reachableGain(v, length, a_max, j_max);
}

namespace {

// Distance of v0 -> vp -> v1 without cruise; increasing in vp for vp >= max(v0, v1).
double peakDistance(double vp, double v0, double v1, double a_max, double j_max) {
  return rampDistance(v0, vp, a_max, j_max) + rampDistance(v1, vp, a_max, j_max);
}

// d/dw of rampDistance(v, w) for w > v.
double rampDistanceSlope(double v, double w, double a_max, double j_max) {
  const double dv = w - v;
  if (dv >= fullJerkVelocity(a_max, j_max)) return w / a_max + 0.5 * a_max / j_max;
  if (dv <= 0.0) return INFINITY;
  const double root = std::sqrt(dv / j_max);
  return root + (v + w) / (2.0 * j_max * root);
}

// The peak velocity vp in [lo, hi] with peakDistance(vp) = L, given
// peakDistance(lo) <= L < peakDistance(hi). Returns a vp with peakDistance(vp) <= L (the
// remainder becomes a short cruise).
double solvePeak(double length, double v0, double v1, double lo, double hi, double a_max,
                 double j_max) {
  const double b = fullJerkVelocity(a_max, j_max);
  auto fits = [&](double vp) {
    return vp >= lo && vp <= hi && peakDistance(vp, v0, v1, a_max, j_max) <= length;
  };
  // Equal end velocities: the profile is symmetric, each half covers L/2.
  if (v0 == v1) {
    const double vp = std::min(reachableVelocity(v0, 0.5 * length, a_max, j_max), hi);
    if (fits(vp)) return vp;
  }
  // Both ramps reach a_max: vp^2 + b vp + a * C = 0 (quadratic, docs/planner.md).
  {
    const double c = a_max * (-(v0 * v0 + v1 * v1) / (2.0 * a_max) +
                              (v0 + v1) * a_max / (2.0 * j_max) - length);
    if (c < 0.0) {
      const double vp = -2.0 * c / (b + std::sqrt(b * b - 4.0 * c));
      if (vp >= std::max(v0, v1) + b && fits(vp)) return vp;
    }
  }
  // Mixed cases: Newton on a monotone function, safeguarded by bisection; bounded steps.
  // Newton approaches the root from one side, so the bracket's far side does not move: once a
  // Newton step no longer moves x (converged to rounding), x is taken if it fits, else a
  // point just below it; bisecting the far side down instead costs dozens of evaluations.
  const double resolution = 1e-13 * hi;
  constexpr double kConverged = 4e-16;  // a Newton step below this share of x: at the root
  const double base = std::max(v0, v1);  // <= lo
  double x = 0.5 * (lo + hi);
  for (int i = 0; i < 100 && hi - lo > resolution; ++i) {
    const double f = peakDistance(x, v0, v1, a_max, j_max) - length;
    if (f <= 0.0) lo = x; else hi = x;
    if (f == 0.0) break;
    // Newton in w = sqrt(x - base): near base the ramp from the higher end velocity is short
    // and its distance grows like sqrt(x - base), which Newton in x overshoots; in w it is
    // smooth.
    const double slope = rampDistanceSlope(v0, x, a_max, j_max) + rampDistanceSlope(v1, x, a_max, j_max);
    const double w = std::sqrt(x - base);
    const double w_next = w - f / (2.0 * w * slope);
    const double newton = w_next > 0.0 ? base + w_next * w_next : base;
    if (std::abs(newton - x) <= kConverged * x) {
      if (f < 0.0) return x;
      const double below = std::min(x, newton) * (1.0 - kConverged);
      if (fits(below)) return below;
    }
    // Outside the bracket: below it, the root sits just above lo (Newton says so even in w),
    // so close in on lo geometrically; above it, bisect.
    x = newton <= lo ? lo + 0.01 * (x - lo) : newton < hi ? newton : 0.5 * (lo + hi);
  }
  return lo;
}

}  // namespace

double lowestReachableVelocity(double v0, double length, double a_max, double j_max) {
  // A full stop first: the braking distance is not monotone in the end velocity (a short
  // triangular ramp decelerates more gently, so braking part of the way can take longer than
  // stopping), and a stop that fits up to rounding must give 0, not a point on the far side.
  // "Up to rounding" is 1e-9 of the length (a picometre per millimetre): velocities chained
  // through several runs carry more than one ulp, and planProfile's ramp rebuild absorbs it.
  if (rampDistance(0.0, v0, a_max, j_max) <= length * (1.0 + 1e-9)) return 0.0;
  // Beyond it the distance only falls towards v0, so bisection finds the lowest end velocity.
  double lo = 0.0, hi = v0;
  for (int i = 0; i < 100 && hi - lo > 1e-13 * v0; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (rampDistance(mid, v0, a_max, j_max) <= length) hi = mid; else lo = mid;
  }
  return hi;
}

SCurveProfile planProfile(double length, double v_start, double v_end, double v_max,
                          double a_max, double j_max) {
  SCurveProfile p;
  v_start = std::max(v_start, 0.0);
  v_end = std::max(v_end, 0.0);
  if (!(length > 0.0)) {
    p.v_start = p.v_peak = p.v_end = v_start;
    p.end_reachable = v_end == v_start;
    return p;
  }
  p.length = length;
  double up_gain = -1.0;  // set when v_end is the reachable maximum: ramp from the exact gain
  if (v_end > v_start) {
    const double gain = reachableGain(v_start, length, a_max, j_max);
    if (v_end - v_start > gain) {
      v_end = v_start + gain;
      up_gain = gain;
      p.end_reachable = false;
    }
  } else if (v_end < v_start) {
    // Short only by rounding (1e-9 of the length, as lowestReachableVelocity counts it: end
    // velocities chained through several runs carry more than one ulp): kept, the ramp
    // rebuild below absorbs it. Raising v_end instead could jump far, since the braking
    // distance is not monotone in the end velocity near a stop.
    if (reachableVelocity(v_end, length, a_max, j_max) < v_start &&
        rampDistance(v_end, v_start, a_max, j_max) > length * (1.0 + 1e-9)) {
      v_end = lowestReachableVelocity(v_start, length, a_max, j_max);
      p.end_reachable = false;
    }
  }
  const double lo = std::max(v_start, v_end);
  const double hi = std::max(v_max, lo);
  double vp = hi;
  if (peakDistance(hi, v_start, v_end, a_max, j_max) > length) {
    vp = peakDistance(lo, v_start, v_end, a_max, j_max) >= length
             ? lo
             : solvePeak(length, v_start, v_end, lo, hi, a_max, j_max);
  }
  p.v_start = v_start;
  p.v_end = v_end;
  p.v_peak = vp;
  p.accel = (up_gain >= 0.0 && vp == v_end) ? VelocityRamp::fromGain(v_start, up_gain, a_max, j_max)
                                             : VelocityRamp::make(v_start, vp, a_max, j_max);
  p.decel = VelocityRamp::make(v_end, vp, a_max, j_max);
  if (p.accel.distance + p.decel.distance > length) {
    // A velocity gain far below the velocities themselves carries their rounding, so the
    // ramps may overshoot L slightly. Rebuild the longer ramp from the distance left for it:
    // s stays continuous and the velocity absorbs the rounding (an ulp of v).
    if (p.decel.distance >= p.accel.distance) {
      p.decel = VelocityRamp::fromGain(
          v_end, reachableGain(v_end, length - p.accel.distance, a_max, j_max), a_max, j_max);
    } else {
      p.accel = VelocityRamp::fromGain(
          v_start, reachableGain(v_start, length - p.decel.distance, a_max, j_max), a_max, j_max);
    }
  }
  const double rest = length - p.accel.distance - p.decel.distance;
  p.t_cruise = (vp > 0.0 && rest > 0.0) ? rest / vp : 0.0;
  p.duration = p.accel.duration + p.t_cruise + p.decel.duration;
  return p;
}

PathState SCurveProfile::at(double t) const {
  if (t <= 0.0) return {0.0, v_start, 0.0, accel.duration > 0.0 ? accel.jerk : 0.0};
  if (t >= duration) return {length, v_end, 0.0, 0.0};
  if (t < accel.duration) return accel.at(t);
  const double t_decel = accel.duration + t_cruise;
  if (t < t_decel) return {accel.distance + v_peak * (t - accel.duration), v_peak, 0.0, 0.0};
  // Braking: the decel ramp backwards in time from the end. s = L - S(r), v = S'(r),
  // a = -S''(r), j = S'''(r) with r = duration - t.
  const PathState back = decel.at(duration - t);
  return {length - back.s, back.v, -back.a, back.j};
}

bool cutProfile(SCurveProfile& p, double next, double limit) {
  // The start ramp spans [0, c0), the cruise [c0, c1).
  const double c0 = p.accel.duration;
  const double c1 = c0 + p.t_cruise;
  const VelocityRamp& ramp = p.accel;
  if (limit < p.v_peak && next < c0 && ramp.v_to > ramp.v_from &&
      next < ramp.t_jerk + ramp.t_accel) {
    // Accelerating, not yet in the jerk-down phase: the ramp up to `next` is unchanged (the
    // same jerk, the same phases). It ends at the new limit, or where a jerk-down phase from
    // `next` on ends if that is above the limit: a ramp of the same jerk and peak
    // acceleration to the lower gain follows the same phases up to `next`. (Ending at once
    // far below the limit, and accelerating again in a new piece, made a turn early in a
    // ramp slower than the lower override from the start.)
    const double peak_a = ramp.jerk * ramp.t_jerk;
    const double earliest = next < ramp.t_jerk ? ramp.jerk * next * next : peak_a * next;
    const double gain = std::max(earliest, limit - ramp.v_from);
    p.accel = VelocityRamp::fromGain(ramp.v_from, gain, peak_a, ramp.jerk);
    p.v_peak = p.accel.v_to;
    p.t_cruise = 0.0;
  } else if (p.t_cruise > 0.0 && std::max(next, c0) < c1) {
    p.t_cruise = std::max(next, c0) - c0;  // end at the cut, cruising
  } else {
    return false;
  }
  p.decel = VelocityRamp::make(p.v_peak, p.v_peak, 1.0, 1.0);
  p.v_end = p.v_peak;
  p.length = p.accel.distance + p.v_peak * p.t_cruise;
  p.duration = p.accel.duration + p.t_cruise;
  return true;
}

}  // namespace ncc::vm::motion
