#include "ncc/vm/motion/axis_rapid.h"

#include <algorithm>
#include <cmath>

namespace ncc::vm::motion {
namespace {

bool positiveFinite(double x) { return x > 0.0 && std::isfinite(x); }

}  // namespace

bool AxisRapid::possible(const AxisValues& from, const AxisValues& to, const AxisLimits& limits) {
  for (int i = 0; i < std::clamp(limits.count, 0, kMaxAxes); ++i) {
    if (!std::isfinite(from[i]) || !std::isfinite(to[i])) return false;
    if (to[i] == from[i]) continue;  // a standing axis needs no limits
    if (!positiveFinite(limits.rapid_velocity[i]) || !positiveFinite(limits.acceleration[i]) ||
        !positiveFinite(kSmoothJerkShare * limits.jerk[i]))
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
    if (to[i] == from[i]) continue;  // standing axis: empty profile, sign 0
    const double v = limits.rapid_velocity[i];
    const double a = limits.acceleration[i];
    const double j = kSmoothJerkShare * limits.jerk[i];
    r.sign_[i] = to[i] > from[i] ? 1.0 : -1.0;
    r.profiles_[i] = planProfile(std::abs(to[i] - from[i]), 0.0, 0.0, v, a, j);
    r.duration_ = std::max(r.duration_, r.profiles_[i].duration);
  }
  if (!r.valid_) {
    // Deterministic and harmless: no motion profile at all (the caller rejects the move).
    r.sign_ = {};
    r.profiles_ = {};
    r.duration_ = 0.0;
  }
  return r;
}

double AxisRapid::clampTime(double t) const {
  if (!(t > 0.0)) return 0.0;  // also NaN
  return std::min(t, duration_);
}

void AxisRapid::position(double t, AxisValues& out) const {
  out = to_;
  if (t >= duration_) return;  // everything has arrived: `to` bit-exactly
  t = clampTime(t);
  for (int i = 0; i < count_; ++i) {
    const SCurveProfile& p = profiles_[i];
    if (t >= p.duration) continue;  // arrived (or standing): to[i]
    if (t <= 0.0) {
      out[i] = from_[i];
      continue;
    }
    const double lo = std::min(from_[i], to_[i]);
    const double hi = std::max(from_[i], to_[i]);
    const double t_brake = p.accel.duration + p.t_cruise;
    double x;
    if (t >= t_brake) {
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
  const PathState s = profiles_[axis].at(clampTime(t));
  const double sg = sign_[axis];
  return {sg * s.s, sg * s.v, sg * s.a, sg * s.j};
}

void AxisRapid::velocity(double t, AxisValues& out) const {
  out = AxisValues{};
  if (!(t > 0.0) || t >= duration_) return;
  for (int i = 0; i < count_; ++i) out[i] = sign_[i] * profiles_[i].at(t).v;
}

void AxisRapid::acceleration(double t, AxisValues& out) const {
  out = AxisValues{};
  if (!(t > 0.0) || t >= duration_) return;
  for (int i = 0; i < count_; ++i) out[i] = sign_[i] * profiles_[i].at(t).a;
}

AxisRapidMotion AxisRapid::pathMotion(double t) const {
  if (t >= duration_) return {};
  t = clampTime(t);
  // With axis vectors v, a, j: |v|' = v.a / |v|, |v|'' = (a.a + v.j) / |v| - (v.a)^2 / |v|^3.
  double vv = 0.0, va = 0.0, aa = 0.0, vj = 0.0, jj = 0.0;
  for (int i = 0; i < count_; ++i) {
    if (t >= profiles_[i].duration) continue;
    const PathState s = profiles_[i].at(t);  // the sign cancels in every product
    vv += s.v * s.v;
    va += s.v * s.a;
    aa += s.a * s.a;
    vj += s.v * s.j;
    jj += s.j * s.j;
  }
  if (vv == 0.0) {
    // At rest (the start): every axis leaves rest with v_i = j_i t^2 / 2, so |v| = |j| t^2 / 2.
    return {0.0, std::sqrt(aa), std::sqrt(jj)};
  }
  const double speed = std::sqrt(vv);
  const double accel = va / speed;
  return {speed, accel, (aa + vj) / speed - accel * accel / speed};
}

}  // namespace ncc::vm::motion
