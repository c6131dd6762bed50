#include "ncc/vm/motion/limits.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncc::vm::motion {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

AxisLimits AxisLimits::from(const MachineConfig& machine) {
  AxisLimits l;
  l.count = std::min(machine.axisCount(), kMaxAxes);
  for (int i = 0; i < l.count; ++i) {
    const AxisConfig& a = machine.axes[i];
    l.feed_velocity[i] = a.max_velocity / 60.0;
    l.rapid_velocity[i] = a.rapid_velocity / 60.0;
    l.acceleration[i] = a.max_acceleration;
    l.jerk[i] = a.max_jerk;
  }
  l.ipo_cycle = machine.ipo_cycle_seconds;
  l.chord_tolerance = machine.chord_tolerance;
  l.corner_tolerance = machine.corner_tolerance;
  return l;
}

SegmentLimits segmentLimits(const PathSegment& path, const AxisLimits& axes, bool rapid,
                            double feed, const ChainShape& chain) {
  SegmentLimits lim{rapid ? kInf : feed, kInf, kInf};
  AxisValues t, q;
  path.maxTangent(t);
  const bool in_chain = chain.curvature > 0.0;
  double kappa = path.maxCurvature();  // curvature bound
  double rate = path.maxCurvatureRate();
  path.normalShare(q);
  if (in_chain) {
    // The chain's curve turns around the line's direction by at most `turn` each side.
    kappa = chain.curvature;
    rate = kappa * kappa;
    // The curve's tangent turns around the line's direction: bound it by 1 on every axis
    // involved, which also makes the limits of neighbouring lines equal (they join one run).
    for (int i = 0; i < axes.count; ++i) {
      q[i] = chain.involved[i];
      t[i] = std::max(t[i], q[i]);
    }
  }
  const bool curved = kappa > 0.0;
  const double T = axes.ipo_cycle;
  const double wiggle_jerk = in_chain ? 4.0 * chain.sagitta / (T * T * T) : 0.0;
  const double wiggle_acc = in_chain ? 2.0 * chain.sagitta / (T * T) : 0.0;
  // The share of the smooth jerk the curvature's rotation (v^3 r) may take at top speed. A
  // blend is short and passed near constant speed, so it gives the rotation more.
  const double rotation_share = path.shape() == PathSegment::Shape::Blend ? 2.0 / 3.0 : 1.0 / 3.0;

  // Path speed: programmed feed, axis speeds, and on curves the centripetal, curvature-rate
  // and chord-error caps.
  for (int i = 0; i < axes.count; ++i) {
    if (t[i] > 0.0)
      lim.velocity = std::min(lim.velocity, (rapid ? axes.rapid_velocity[i] : axes.feed_velocity[i]) / t[i]);
    if (!curved || q[i] == 0.0) continue;
    lim.velocity = std::min(lim.velocity, std::sqrt(kCentripetalShare * axes.acceleration[i] / (kappa * q[i])));
    const double smooth = kSmoothJerkShare * axes.jerk[i] - q[i] * wiggle_jerk;
    lim.velocity = std::min(lim.velocity, std::cbrt(rotation_share * smooth / (rate * q[i])));
  }
  if (curved && axes.chord_tolerance > 0.0) {
    // Chord error of the setpoint polygon: a chord c on curvature k deviates by about
    // k c^2 / 8 (exact for small chords on an arc: c = 2 sqrt(2 r e - e^2)).
    const double e = axes.chord_tolerance;
    double chord = std::sqrt(8.0 * e / kappa);
    if (path.shape() == PathSegment::Shape::Arc && !in_chain) {
      // Exact on the circle; a helix turns at the plane share p of the path speed.
      const double r = path.radius();
      chord = e < r ? 2.0 * std::sqrt(2.0 * r * e - e * e) / path.planeShare() : kInf;
    }
    lim.velocity = std::min(lim.velocity, chord / axes.ipo_cycle);
  }
  const double v = lim.velocity;

  // Tangential acceleration and jerk: what the axis limits leave at that speed.
  TangentialBudget budget;
  for (int i = 0; i < axes.count; ++i) {
    if (t[i] == 0.0 && (!curved || q[i] == 0.0)) continue;
    const double centripetal = curved ? v * v * kappa * q[i] : 0.0;
    const double rotation = curved ? v * v * v * rate * q[i] : 0.0;
    const double acc_left = axes.acceleration[i] - q[i] * wiggle_acc - centripetal;
    const double jerk_left = kSmoothJerkShare * axes.jerk[i] - q[i] * wiggle_jerk - rotation;
    if (t[i] > 0.0) lim.acceleration = std::min(lim.acceleration, acc_left / t[i]);
    // The cross term 3 v a_t k_i (curves) shares jerk_left with j_t t_i.
    budget.add(t[i], curved ? 3.0 * v * kappa * q[i] : 0.0, jerk_left);
  }
  budget.split(v, lim.acceleration, lim.jerk);
  return lim;
}

void TangentialBudget::add(double tangent, double cross, double jerk_left) {
  if (count_ >= kMaxAxes) return;
  rows_[count_++] = {tangent, cross, jerk_left};
}

double TangentialBudget::jerkAt(double a) const {
  double j = kInf;
  for (int k = 0; k < count_; ++k) {
    const Row& r = rows_[k];
    if (r.tangent > 0.0) j = std::min(j, (r.jerk_left - r.cross * a) / r.tangent);
  }
  return j;
}

void TangentialBudget::split(double v, double& acceleration, double& jerk) const {
  // The largest a_t that leaves every axis some jerk (j_t > 0), and no more than `acceleration`.
  double a_max = acceleration;
  for (int k = 0; k < count_; ++k)
    if (rows_[k].cross > 0.0) a_max = std::min(a_max, rows_[k].jerk_left / rows_[k].cross);
  if (!(a_max > 0.0) || !(v > 0.0)) {
    // Nothing to share (or no room at all): the plain limits.
    acceleration = std::min(acceleration, a_max);
    jerk = std::min(jerk, jerkAt(0.0));
    return;
  }
  // A ramp over dv = v takes about v / a + a / j(a). Candidates: for each axis, the a that
  // minimises it were that axis alone binding, a = J' / (c + sqrt(J' t / v)) (docs/planner.md),
  // and a_max itself; the best feasible one wins. On a line (c = 0) this is a_max with the
  // full jerk.
  double best_a = 0.0, best_time = kInf, best_j = 0.0;
  auto consider = [&](double a) {
    a = std::min(a, a_max);
    if (!(a > 0.0)) return;
    const double j = jerkAt(a);
    if (!(j > 0.0)) return;
    const double time = v / a + a / j;
    if (time < best_time) {
      best_time = time;
      best_a = a;
      best_j = j;
    }
  };
  consider(a_max);
  for (int k = 0; k < count_; ++k) {
    const Row& r = rows_[k];
    if (r.cross > 0.0 && r.tangent > 0.0 && r.jerk_left > 0.0)
      consider(r.jerk_left / (r.cross + std::sqrt(r.jerk_left * r.tangent / v)));
  }
  if (best_time == kInf) {  // no a with positive jerk left: creep (limits stay positive)
    acceleration = std::min(acceleration, 0.5 * a_max);
    jerk = std::min(jerk, std::max(jerkAt(acceleration), 0.0));
    return;
  }
  acceleration = best_a;
  jerk = std::min(jerk, best_j);
}

double junctionVelocity(const PathSegment& a, const PathSegment& b, const AxisLimits& axes) {
  AxisValues ta, tb, ka, kb;
  a.tangent(a.length(), ta);
  b.tangent(0.0, tb);
  double dot = 0.0;
  for (int i = 0; i < axes.count; ++i) dot += ta[i] * tb[i];
  if (dot < std::cos(kCornerAngle)) return 0.0;
  a.curvature(a.length(), ka);
  b.curvature(0.0, kb);
  const double T = axes.ipo_cycle;
  double v = kInf;
  for (int i = 0; i < axes.count; ++i) {
    const double budget = kJunctionJerkShare * axes.jerk[i];
    // A velocity step dv within one cycle reads as a jerk of about dv / T^2.
    const double kink = std::abs(tb[i] - ta[i]);
    if (kink > 0.0) v = std::min(v, budget * T * T / kink);
    // An acceleration step da reads as a jerk of about da / T.
    const double step = std::abs(kb[i] - ka[i]);
    if (step > 0.0) v = std::min(v, std::sqrt(budget * T / step));
  }
  return v;
}

}  // namespace ncc::vm::motion
