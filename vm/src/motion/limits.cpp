#include "ncc/vm/motion/limits.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "ncc/vm/motion/distinct_axes.h"
#include "ncc/vm/motion/ramp_envelope.h"

namespace ncc::vm::motion {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The ramp envelope (ramp_envelope.h) is searched when the terms that grow with the speed
// take more than this share of some axis' acceleration or jerk at the top speed: below it
// there is little to gain for its cost (several microseconds).
constexpr double kEnvelopeWorthShare = 0.05;

AxisLimits stretchedLimits(const AxisLimits& axes, double stretch) {
  AxisLimits out = axes;
  for (int i = 0; i < out.count; ++i) {
    out.acceleration[i] /= stretch;
    out.jerk[i] /= stretch;
  }
  return out;
}

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

SegmentLimits segmentLimits(const PathSegment& path, const AxisLimits& machine_axes, bool rapid,
                            double feed, const ChainShape& chain, double jerk_share) {
  // A spiral's s is not quite its arc length: the bounds below assume it is, and hold with
  // the feed and the axis accelerations and jerks divided by its stretch (path.h).
  const bool in_chain = chain.curvature > 0.0;
  const double stretch = in_chain ? chain.stretch : path.parameterStretch();
  std::optional<AxisLimits> stretched;  // constructed only for a spiral
  const AxisLimits& axes =
      stretch == 1.0 ? machine_axes : stretched.emplace(stretchedLimits(machine_axes, stretch));
  // A chain's bow keeps the feed with its speed bound (its stretch is for the norm bounds).
  SegmentLimits lim{rapid ? kInf : feed / (in_chain ? chain.speed : stretch), kInf, kInf};
  AxisValues t, q;
  path.maxTangent(t);
  double kappa = path.maxCurvature();  // curvature bound
  double rate = path.maxCurvatureRate();
  double rate_across = rate;  // the part of the rate not along the tangent
  path.normalShare(q);
  if (in_chain) {
    kappa = chain.curvature;
    rate = chain.rate_along + chain.rate_across;
    rate_across = chain.rate_across;
    // The curve's tangent turns around the line's direction: bound it by the chain's speed
    // bound on every axis involved, which also makes the limits of neighbouring lines equal
    // (they join one run).
    for (int i = 0; i < axes.count; ++i) {
      q[i] = chain.involved[i];
      t[i] = chain.speed * q[i];
    }
  }
  const bool curved = kappa > 0.0;
  const double T = axes.ipo_cycle;
  // The polygon's wiggle along axis i, in its sampled jerk and acceleration (limits.h).
  auto wiggleJerk = [&](int i) { return in_chain ? 4.0 * chain.wiggle[i] / (T * T * T) : 0.0; };
  auto wiggleAcc = [&](int i) { return in_chain ? 2.0 * chain.wiggle[i] / (T * T) : 0.0; };
  // The share of the smooth jerk the curvature's rotation (v^3 r) may take at top speed. A
  // blend is short and passed near constant speed, so it gives the rotation more.
  const double rotation_share = path.shape() == PathSegment::Shape::Blend ? 2.0 / 3.0 : 1.0 / 3.0;

  // Path speed: programmed feed, axis speeds, and on curves the centripetal, curvature-rate
  // and chord-error caps. The centripetal and curvature-rate caps are roots of a ratio per
  // axis; the roots are monotonic, so the cap is the root of the smallest ratio (one cbrt per
  // segment, not one per axis). A ratio whose root is NaN (0/0; a negative one under the
  // square root) caps nothing, as std::min(v, NaN) did.
  double centripetal_ratio = kInf, rotation_ratio = kInf;
  for (int i = 0; i < axes.count; ++i) {
    if (t[i] > 0.0)
      lim.velocity = std::min(lim.velocity, (rapid ? axes.rapid_velocity[i] : axes.feed_velocity[i]) / t[i]);
    if (!curved || q[i] == 0.0) continue;
    const double centripetal = kCentripetalShare * axes.acceleration[i] / (kappa * q[i]);
    if (centripetal >= 0.0) centripetal_ratio = std::min(centripetal_ratio, centripetal);
    const double smooth = jerk_share * axes.jerk[i] - wiggleJerk(i);
    rotation_ratio = std::min(rotation_ratio, rotation_share * smooth / (rate * q[i]));
  }
  lim.velocity = std::min(lim.velocity, std::sqrt(centripetal_ratio));
  lim.velocity = std::min(lim.velocity, std::cbrt(rotation_ratio));
  if (curved && axes.chord_tolerance > 0.0) {
    // Chord error of the setpoint polygon: a chord c on curvature k deviates by about
    // k c^2 / 8 (exact for small chords on an arc: c = 2 sqrt(2 r e - e^2)).
    const double e = axes.chord_tolerance;
    double chord = std::sqrt(8.0 * e / kappa);
    if (path.shape() == PathSegment::Shape::Arc && !in_chain) {
      // Exact on the circle (a spiral: at its smallest radius of curvature); the plane axes
      // move at most maxPlaneSpeed() per unit of s (a helix: less than 1). A circle no larger
      // than e is within e of any chord; a spiral may be larger elsewhere (the general cap).
      const double r = path.radius();
      if (e < r) chord = 2.0 * std::sqrt(2.0 * r * e - e * e) / path.maxPlaneSpeed();
      else if (!path.isSpiral()) chord = kInf;
    }
    lim.velocity = std::min(lim.velocity, chord / axes.ipo_cycle);
  }
  const double v = lim.velocity;

  // Tangential acceleration and jerk: what the axis limits leave at that speed. Two bounds
  // hold for every axis (docs/planner.md, "Limits"), and an axis is within its limit if
  // either is: the sum of the parts' shares, a_t t_i + v^2 k q_i, and the norm of the whole
  // vector, sqrt(a_t^2 + (v^2 k)^2) (the tangent and the normal are orthogonal).
  TangentialBudget budget;
  // A plane circle, or a chain line planned as one: the rotation term lies along the tangent.
  const bool circle = in_chain || path.isPlaneCircle();
  if (path.isPlaneCircle()) rate_across = 0.0;
  RampEnvelope envelope(v, kappa, rate, circle, circle ? rate_across : 0.0);
  const double centripetal = curved ? v * v * kappa : 0.0;
  const double cross = curved ? 3.0 * v * kappa : 0.0;  // the cross term 3 v a_t k, per a_t
  const double rotation = curved ? v * v * v * rate : 0.0;
  const double rotation_across = curved ? v * v * v * rate_across : 0.0;
  double speed_share = 0.0;  // largest share of an axis limit the speed-dependent terms take
  for (int i = 0; i < axes.count; ++i) {
    if (t[i] == 0.0 && (!curved || q[i] == 0.0)) continue;
    const double acc = axes.acceleration[i] - wiggleAcc(i);
    double a_i = kInf;
    if (t[i] > 0.0) a_i = (acc - centripetal * q[i]) / t[i];
    else if (acc < centripetal * q[i]) a_i = -kInf;
    if (curved && q[i] > 0.0 && acc >= centripetal)
      a_i = std::max(a_i, std::sqrt(acc * acc - centripetal * centripetal));
    lim.acceleration = std::min(lim.acceleration, a_i);
    const double jerk = jerk_share * axes.jerk[i] - wiggleJerk(i);
    const bool norm = curved && q[i] > 0.0;
    budget.add({t[i], cross * q[i], jerk - rotation * q[i], norm ? cross : 0.0,
                norm ? (circle ? jerk - rotation_across : jerk - rotation) : 0.0,
                norm && circle ? rotation - rotation_across : 0.0});
    if (curved) {
      envelope.add({t[i], q[i], acc, jerk});
      speed_share = std::max({speed_share, centripetal * q[i] / acc, rotation * q[i] / jerk});
    }
  }
  budget.split(v, lim.acceleration, lim.jerk);
  // On arcs and chains the envelope of the ramps may allow more (a blend is short and passed
  // near constant speed: its ramps happen on the lines around it).
  if (curved && path.shape() != PathSegment::Shape::Blend) {
    speed_share = std::max(speed_share, cross * lim.acceleration / lim.jerk);
    if (speed_share > kEnvelopeWorthShare && (!in_chain || chain.ramp_envelope))
      envelope.widen(lim.acceleration, lim.jerk);
  }
  return lim;
}

void TangentialBudget::add(const Axis& axis) { addDistinctAxis(axes_, count_, axis); }

double TangentialBudget::jerkAt(double a) const {
  double j = kInf;
  for (int k = 0; k < count_; ++k) {
    const Axis& x = axes_[k];
    // Sum form: j t + c a <= J'.
    double allowed = -kInf;
    if (x.tangent > 0.0) allowed = (x.jerk_left - x.cross * a) / x.tangent;
    else if (x.cross * a <= x.jerk_left) allowed = kInf;
    // Norm form: sqrt(j^2 + (m a)^2) <= J''.
    if (x.norm_cross > 0.0 && x.norm_jerk_left >= x.norm_cross * a) {
      const double m = x.norm_cross * a;
      allowed = std::max(allowed, std::sqrt(x.norm_jerk_left * x.norm_jerk_left - m * m) -
                                      x.norm_rotation);
    }
    j = std::min(j, allowed);
  }
  return j;
}

void TangentialBudget::split(double v, double& acceleration, double& jerk) const {
  const double a_max = acceleration;
  if (!(a_max > 0.0) || !(v > 0.0) || !(jerkAt(a_max) < jerkAt(0.0))) {
    // Nothing to share (a line: the jerk does not depend on a_t), or no room at all.
    jerk = std::min(jerk, jerkAt(a_max > 0.0 ? a_max : 0.0));
    return;
  }
  // A ramp over dv = v takes about v / a + a / j(a): the a_t that makes it shortest, by a
  // golden-section search (with either form alone j(a) is concave and decreasing, so the time
  // is unimodal in a), then the largest j_t at that a_t.
  auto time = [&](double a) {
    const double j = jerkAt(a);
    return j > 0.0 ? v / a + a / j : kInf;
  };
  constexpr double kGolden = 0.6180339887498949;
  double lo = 1e-3 * a_max, hi = a_max;
  double x1 = hi - kGolden * (hi - lo), x2 = lo + kGolden * (hi - lo);
  double f1 = time(x1), f2 = time(x2);
  for (int i = 0; i < kSplitSteps; ++i) {
    if (f1 <= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - kGolden * (hi - lo);
      f1 = time(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + kGolden * (hi - lo);
      f2 = time(x2);
    }
  }
  // The search assumes one minimum; where the bound switches forms on some axis there may be
  // two, so also try a_max and each axis' sum-form optimum a = J' / (c + sqrt(J' t / v)).
  double best = f1 <= f2 ? x1 : x2;
  double best_time = std::min(f1, f2);
  auto consider = [&](double a) {
    if (!(a > 0.0 && a <= a_max)) return;
    const double f = time(a);
    if (f < best_time) best_time = f, best = a;
  };
  consider(a_max);
  for (int k = 0; k < count_; ++k) {
    const Axis& x = axes_[k];
    if (x.cross > 0.0 && x.tangent > 0.0 && x.jerk_left > 0.0)
      consider(x.jerk_left / (x.cross + std::sqrt(x.jerk_left * x.tangent / v)));
  }
  const double j = jerkAt(best);
  if (!(j > 0.0)) {  // no a_t with jerk left: creep (the limits stay positive)
    acceleration = 0.5 * a_max;
    jerk = std::min(jerk, std::max(jerkAt(acceleration), 0.0));
    return;
  }
  acceleration = best;
  jerk = std::min(jerk, j);
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
  const double shorter = std::min(a.length(), b.length());
  double v = kInf;
  for (int i = 0; i < axes.count; ++i) {
    const double budget = kJunctionJerkShare * axes.jerk[i];
    // A velocity step dv within one cycle reads as a jerk of about dv / T^2.
    const double kink = std::abs(tb[i] - ta[i]);
    if (kink > 0.0) {
      const double acceleration_budget = kJunctionAccelerationShare * axes.acceleration[i];
      v = std::min(v, budget * T * T / kink);
      // ... and as an acceleration of dv / T, beside the path's (kinkAccelerationLimit).
      v = std::min(v, acceleration_budget * T / kink);
      // Several kinks within one cycle: their steps add like a curvature |dt_i| / L.
      if (shorter > 0.0) {
        v = std::min(v, std::sqrt(acceleration_budget * shorter / kink));
        v = std::min(v, std::sqrt(budget * T * shorter / kink));
      }
    }
    // An acceleration step da reads as a jerk of about da / T.
    const double step = std::abs(kb[i] - ka[i]);
    if (step > 0.0) v = std::min(v, std::sqrt(budget * T / step));
  }
  return v;
}

double kinkAccelerationLimit(const AxisValues& before, const AxisValues& after, double length,
                             double velocity, const AxisLimits& axes) {
  double limit = kInf;
  if (!(velocity > 0.0)) return limit;
  const double T = axes.ipo_cycle;
  const double per_cycle = length > 0.0 ? 1.0 + velocity * T / length : 1.0;
  for (int i = 0; i < axes.count; ++i) {
    const double kink = std::abs(after[i] - before[i]);
    const double tangent = std::max(std::abs(before[i]), std::abs(after[i]));
    if (kink == 0.0 || tangent == 0.0) continue;
    const double room = axes.acceleration[i] - per_cycle * velocity * kink / T;
    limit = std::min(limit, std::max(room, 0.0) / tangent);
  }
  return limit;
}

}  // namespace ncc::vm::motion
