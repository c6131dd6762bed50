#include "ncc/vm/motion/axis_rapid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncc::vm::motion {
namespace {

bool positiveFinite(double x) { return x > 0.0 && std::isfinite(x); }

}  // namespace

bool AxisRapid::possible(const AxisValues& from, const AxisValues& to, const AxisLimits& limits) {
  for (int i = 0; i < std::clamp(limits.count, 0, kMaxAxes); ++i) {
    if (!std::isfinite(from[i]) || !std::isfinite(to[i])) return false;
    if (to[i] == from[i]) continue;  // a standing axis needs no limits
    if (!positiveFinite(limits.rapid_velocity[i]) || !positiveFinite(limits.acceleration[i]) ||
        !positiveFinite(kBetweenStopsJerkShare * limits.jerk[i]))
      return false;
  }
  return true;
}

AxisRapid AxisRapid::make(const AxisValues& from, const AxisValues& to, const AxisLimits& limits) {
  AxisRapid r;
  r.count_ = std::clamp(limits.count, 0, kMaxAxes);
  r.from_ = from;
  r.to_ = to;
  r.valid_ = possible(from, to, limits);
  for (int i = 0; r.valid_ && i < r.count_; ++i) {
    if (to[i] == from[i]) continue;  // standing axis: no leg, sign 0
    const double v = limits.rapid_velocity[i];
    const double a = limits.acceleration[i];
    const double j = kBetweenStopsJerkShare * limits.jerk[i];
    r.sign_[i] = to[i] > from[i] ? 1.0 : -1.0;
    r.travel_[i] = std::abs(to[i] - from[i]);
    r.legs_[i][0].profile = planProfile(r.travel_[i], 0.0, 0.0, v, a, j);
    r.leg_count_[i] = 1;
    r.duration_ = std::max(r.duration_, r.legs_[i][0].profile.duration);
  }
  if (!r.valid_) {
    // Deterministic and harmless: no motion profile at all (the caller rejects the move).
    r.sign_ = {};
    r.leg_count_ = {};
    r.duration_ = 0.0;
  }
  return r;
}

double AxisRapid::axisDuration(int axis) const {
  if (axis < 0 || axis >= count_ || leg_count_[axis] == 0) return 0.0;
  if (stops_short_[axis]) return std::numeric_limits<double>::infinity();
  return legs_[axis][leg_count_[axis] - 1].end();
}

void AxisRapid::updateDuration() {
  duration_ = 0.0;
  for (int i = 0; i < count_; ++i) duration_ = std::max(duration_, axisDuration(i));
}

void AxisRapid::replan(double next, const AxisLimits& limits, bool held) {
  if (!valid_) return;
  replanned_ = true;
  for (int i = 0; i < count_; ++i) {
    const int n = leg_count_[i];
    if (n == 0) continue;  // no travel
    std::array<Leg, kLegs>& legs = legs_[i];
    // Keep the leg under way at `next` (cut for the new speed), or the last one when the axis
    // is already at rest; the new legs follow it.
    int c = n - 1;
    for (int k = 0; k < n; ++k) {
      // A leg that has not begun (added by a request before the same tick) is replaced, not
      // kept: two requests between the same ticks give the same motion in either order.
      if (k > 0 && legs[k].t0 >= next) {
        c = k - 1;
        break;
      }
      if (next < legs[k].end()) {
        c = k;
        break;
      }
    }
    legs[0] = legs[c];
    const double v = held ? 0.0 : limits.rapid_velocity[i];
    if (next < legs[0].end()) cutProfile(legs[0].profile, next - legs[0].t0, v);
    int count = 1;
    double t = std::max(next, legs[0].end());
    double s = legs[0].s0 + legs[0].profile.length;
    const double v_end = legs[0].profile.v_end;
    const double a = limits.acceleration[i];
    const double j = kBetweenStopsJerkShare * limits.jerk[i];
    auto add = [&](double length, double v0, double v1, double v_max) {
      legs[count] = {t, s, planProfile(length, v0, v1, v_max, a, j)};
      t = legs[count].end();
      s += legs[count].profile.length;
      ++count;
    };
    // What is left of the travel; below rounding the axis has arrived.
    const double rest = travel_[i] - s;
    if (held) {
      // Brake to rest as the limits allow, and stand (the cut leg could stop within the
      // travel before, so the brake fits).
      if (v_end > 0.0) add(std::min(rampDistance(0.0, v_end, a, j), rest), v_end, 0.0, v_end);
      stops_short_[i] = travel_[i] - s > 1e-9 * travel_[i];
    } else {
      if (rest > 1e-9 * travel_[i]) {
        const double brake = v_end > v ? rampDistance(v, v_end, a, j) : 0.0;
        if (v_end > v && brake + rampDistance(0.0, v, a, j) <= rest) {
          add(brake, v_end, v, v_end);  // down to the new speed, then on to `to`
          add(travel_[i] - s, v, 0.0, v);
        } else {
          add(rest, v_end, 0.0, std::max(v, v_end));
        }
      }
      stops_short_[i] = false;
    }
    leg_count_[i] = count;
  }
  updateDuration();
}

double AxisRapid::clampTime(double t) const {
  if (!(t > 0.0)) return 0.0;  // also NaN
  return std::min(t, duration_);
}

PathState AxisRapid::legState(int axis, double t) const {
  const int n = leg_count_[axis];
  if (n == 0) return {};
  for (int k = 0; k < n; ++k) {
    const Leg& g = legs_[axis][k];
    if (t < g.end() || k == n - 1) {
      PathState st = g.profile.at(t - g.t0);
      st.s += g.s0;
      return st;
    }
  }
  return {};
}

void AxisRapid::position(double t, AxisValues& out) const {
  out = to_;
  if (t >= duration_) return;  // everything has arrived: `to` bit-exactly
  t = clampTime(t);
  for (int i = 0; i < count_; ++i) {
    if (leg_count_[i] == 0 || t >= axisDuration(i)) continue;  // arrived (or standing): to[i]
    if (t <= 0.0) {
      out[i] = from_[i];
      continue;
    }
    const double lo = std::min(from_[i], to_[i]);
    const double hi = std::max(from_[i], to_[i]);
    double x;
    const SCurveProfile& p = legs_[i][0].profile;
    if (replanned_) {
      x = from_[i] + sign_[i] * legState(i, t).s;
    } else if (t >= p.accel.duration + p.t_cruise) {
      // Braking is measured back from the end (as SCurveProfile::at does), and so is the
      // position: to - distance left, which tends to to[i] continuously.
      x = to_[i] - sign_[i] * p.decel.at(p.duration - t).s;
    } else {
      x = from_[i] + sign_[i] * p.at(t).s;
    }
    out[i] = std::clamp(x, lo, hi);  // rounding never overshoots either end
  }
}

PathState AxisRapid::axisState(int axis, double t) const {
  if (axis < 0 || axis >= count_) return {};
  const PathState s = legState(axis, clampTime(t));
  const double sg = sign_[axis];
  return {sg * s.s, sg * s.v, sg * s.a, sg * s.j};
}

void AxisRapid::velocity(double t, AxisValues& out) const {
  out = AxisValues{};
  if (!(t > 0.0) || t >= duration_) return;
  for (int i = 0; i < count_; ++i) out[i] = sign_[i] * legState(i, t).v;
}

void AxisRapid::acceleration(double t, AxisValues& out) const {
  out = AxisValues{};
  if (!(t > 0.0) || t >= duration_) return;
  for (int i = 0; i < count_; ++i) out[i] = sign_[i] * legState(i, t).a;
}

AxisRapidMotion AxisRapid::pathMotion(double t) const {
  if (t >= duration_) return {};
  t = clampTime(t);
  // With axis vectors v, a, j: |v|' = v.a / |v|, |v|'' = (a.a + v.j) / |v| - (v.a)^2 / |v|^3.
  double vv = 0.0, va = 0.0, aa = 0.0, vj = 0.0, jj = 0.0;
  for (int i = 0; i < count_; ++i) {
    if (leg_count_[i] == 0 || t >= axisDuration(i)) continue;
    const PathState s = legState(i, t);  // the sign cancels in every product
    vv += s.v * s.v;
    va += s.v * s.a;
    aa += s.a * s.a;
    vj += s.v * s.j;
    jj += s.j * s.j;
  }
  if (vv == 0.0) {
    // At rest (the start, or standing under a feed hold): every axis leaves rest with
    // v_i = j_i t^2 / 2, so |v| = |j| t^2 / 2.
    return {0.0, std::sqrt(aa), std::sqrt(jj)};
  }
  const double speed = std::sqrt(vv);
  const double accel = va / speed;
  return {speed, accel, (aa + vj) / speed - accel * accel / speed};
}

}  // namespace ncc::vm::motion
