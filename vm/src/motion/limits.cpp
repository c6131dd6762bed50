#include "ncc/vm/motion/limits.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncc::vm::motion {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Arc budgets (see limits.h): acceleration split between tangential and centripetal, smooth
// jerk split in three.
constexpr double kArcAccelShare = 0.5;
constexpr double kArcJerkShare = kSmoothJerkShare / 3.0;
constexpr double kJunctionJerkShare = 0.5 * (1.0 - kSmoothJerkShare);

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
  return l;
}

SegmentLimits segmentLimits(const PathSegment& path, const AxisLimits& axes, bool rapid,
                            double feed) {
  SegmentLimits lim{rapid ? kInf : feed, kInf, kInf};
  AxisValues t;
  path.maxTangent(t);
  const bool arc = path.shape() == PathSegment::Shape::Arc;
  const double accel_share = arc ? kArcAccelShare : 1.0;
  const double jerk_share = arc ? kArcJerkShare : kSmoothJerkShare;
  for (int i = 0; i < axes.count; ++i) {
    if (t[i] == 0.0) continue;
    const double v_axis = rapid ? axes.rapid_velocity[i] : axes.feed_velocity[i];
    lim.velocity = std::min(lim.velocity, v_axis / t[i]);
    lim.acceleration = std::min(lim.acceleration, accel_share * axes.acceleration[i] / t[i]);
    lim.jerk = std::min(lim.jerk, jerk_share * axes.jerk[i] / t[i]);
  }
  if (arc) {
    // Per plane axis: |d2x/ds2| <= p^2 / r (centripetal), |d3x/ds3| <= p^3 / r^2, with p the
    // plane share of the path speed (a helix turns slower than its path speed).
    const double r = path.radius();
    const double p = path.planeShare();
    const double k1 = p * p / r;
    const double k2 = p * p * p / (r * r);
    double a_plane = kInf, j_plane = kInf;
    for (int i = 0; i < axes.count; ++i) {
      if (t[i] == 0.0) continue;
      a_plane = std::min(a_plane, axes.acceleration[i]);
      j_plane = std::min(j_plane, axes.jerk[i]);
    }
    lim.velocity = std::min(lim.velocity, std::sqrt(kArcAccelShare * a_plane / k1));
    lim.velocity = std::min(lim.velocity, std::cbrt(kArcJerkShare * j_plane / k2));
    // Chord error: a chord of length c on radius r deviates by e when c = 2 sqrt(2 r e - e^2).
    const double e = axes.chord_tolerance;
    if (e > 0.0 && e < r) {
      const double chord = 2.0 * std::sqrt(2.0 * r * e - e * e);
      lim.velocity = std::min(lim.velocity, chord / (p * axes.ipo_cycle));
    }
    // Cross term 3 v a_t k1 of the axis jerk.
    lim.acceleration = std::min(lim.acceleration, kArcJerkShare * j_plane / (3.0 * lim.velocity * k1));
  }
  return lim;
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
