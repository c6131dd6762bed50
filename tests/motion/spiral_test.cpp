// Spirals: arcs whose end radius differs from their start radius (FANUC accepts the difference
// up to a parameter, and CAM output rounds most arc centres), interpolated with the radius
// linear in the angle. Their parameter is not exactly the arc length; the planner must keep
// them within the axis limits anyway.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "gtest/gtest.h"
#include "motion_test_util.h"
#include "ncc/vm/motion/path.h"

namespace ncc::motion_test {
namespace {

using vm::motion::PathSegment;

// Counter-clockwise (clockwise if `cw`) around the origin in XY from (r, 0) through `sweep`
// radians to radius r + dr.
PathSegment spiral(double r, double dr, double sweep, bool cw = false) {
  const double end_angle = cw ? -sweep : sweep;
  return PathSegment::arc(xyz(r, 0, 0), xyz((r + dr) * std::cos(end_angle), (r + dr) * std::sin(end_angle), 0),
                          3, 0, 1, 0.0, 0.0, cw, 0);
}

// |dx/ds| by central differences over the whole segment: its largest value, and per axis.
struct SampledSpeed {
  double speed = 0.0;
  AxisValues axis{};
};
SampledSpeed sampledSpeed(const PathSegment& p) {
  SampledSpeed out;
  constexpr int kSamples = 400;
  const double h = p.length() * 1e-6;
  for (int k = 1; k < kSamples; ++k) {
    const double s = p.length() * k / kSamples;
    AxisValues a, b;
    p.position(s - h, a);
    p.position(s + h, b);
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double d = (b[i] - a[i]) / (2.0 * h);
      out.axis[i] = std::max(out.axis[i], std::abs(d));
      sum += d * d;
    }
    out.speed = std::max(out.speed, std::sqrt(sum));
  }
  return out;
}

// The smallest radius of curvature |x'|^3 / |x' x x''| in the plane, by central differences.
double sampledRadiusOfCurvature(const PathSegment& p) {
  double smallest = INFINITY;
  constexpr int kSamples = 400;
  const double h = p.length() * 1e-3;
  for (int k = 0; k <= kSamples; ++k) {
    const double s = std::clamp(p.length() * k / kSamples, h, p.length() - h);
    AxisValues a, b, c;
    p.position(s - h, a);
    p.position(s, b);
    p.position(s + h, c);
    const double dx = (c[0] - a[0]) / (2.0 * h), dy = (c[1] - a[1]) / (2.0 * h);
    const double ddx = (c[0] - 2.0 * b[0] + a[0]) / (h * h), ddy = (c[1] - 2.0 * b[1] + a[1]) / (h * h);
    const double speed = std::hypot(dx, dy);
    smallest = std::min(smallest, speed * speed * speed / std::abs(dx * ddy - dy * ddx));
  }
  return smallest;
}

TEST(Spiral, LengthCountsTheRadialTravel) {
  // 0.001 rad at radius 0.2 is 0.0002 mm of arc, but the radius grows 0.01 mm: the length is
  // the radial travel's, and s moves the point at about unit speed. The length of the mean
  // radius' arc alone made |dx/ds| 34.
  const PathSegment p = spiral(0.2, 0.01, 0.001);
  EXPECT_NEAR(p.length(), std::hypot(0.205 * 0.001, 0.01), 1e-12);
  const SampledSpeed sampled = sampledSpeed(p);
  EXPECT_NEAR(sampled.speed, 1.0, 0.01);
  // The bounds the planner uses hold the sampled values.
  AxisValues bound;
  p.maxTangent(bound);
  for (int i = 0; i < 2; ++i) EXPECT_LE(sampled.axis[i], bound[i] * (1.0 + 1e-6)) << "axis " << i;
  EXPECT_GE(p.parameterStretch(), sampled.speed * (1.0 - 1e-6));
}

TEST(Spiral, BoundsHoldTheSampledSpeed) {
  // From a radius change much smaller than the arc to much larger, and a full turn.
  Random rng(7);
  for (int k = 0; k < 200; ++k) {
    const double r = std::exp(rng.uniform(std::log(0.2), std::log(40.0)));
    const double sweep = std::exp(rng.uniform(std::log(1e-3), std::log(6.2)));
    const double dr = rng.uniform(-0.05, 0.05);
    const PathSegment p = spiral(r, dr, sweep, rng.below(2) == 0);
    const SampledSpeed sampled = sampledSpeed(p);
    AxisValues bound;
    p.maxTangent(bound);
    for (int i = 0; i < 2; ++i)
      EXPECT_LE(sampled.axis[i], bound[i] * (1.0 + 1e-6)) << "r " << r << " dr " << dr << " sweep " << sweep;
    EXPECT_GE(p.parameterStretch(), sampled.speed * (1.0 - 1e-6)) << "r " << r << " dr " << dr << " sweep " << sweep;
    // radius(): the smallest radius of curvature, which the chord error is computed from.
    const double sampled_radius = sampledRadiusOfCurvature(p);
    EXPECT_LE(p.radius(), sampled_radius * (1.0 + 1e-3)) << "r " << r << " dr " << dr << " sweep " << sweep;
    EXPECT_GE(p.radius(), sampled_radius * 0.99) << "r " << r << " dr " << dr << " sweep " << sweep;
  }
}

MachineConfig unequalAxes() {
  MachineConfig m = defaultMachine();
  m.axes[0].max_velocity = 12000.0;
  m.axes[1].max_velocity = 10000.0;
  setAxisLimits(m, 1, 3000.0, 80000.0);
  m.axes[2].max_velocity = 6000.0;
  setAxisLimits(m, 2, 1500.0, 30000.0);
  m.corner_tolerance = 0.01;
  return m;
}

TEST(Spiral, SingleSpiralsStayWithinTheAxisLimits) {
  // Spirals run from rest to rest: every setpoint within the axis limits and the end met
  // exactly. First two found by review: a short arc whose radius changes by more than its
  // length (its |dx/ds| was 34; 6.8x the jerk limit) and a long one at a high feed (1.000005x
  // the velocity limit); then random ones.
  const MachineConfig m = unequalAxes();
  struct Case {
    double r, dr, sweep, feed;
  };
  std::vector<Case> cases = {{0.2, 0.01, 0.001, 6000.0}, {30.0, 0.01, 6.0, 20000.0}};
  Random rng(99);
  for (int k = 0; k < 600; ++k) {
    Case c;
    c.r = std::exp(rng.uniform(std::log(0.2), std::log(40.0)));
    c.sweep = std::exp(rng.uniform(std::log(1e-3), std::log(6.2)));
    c.dr = rng.uniform(-0.01, 0.01);
    c.feed = rng.uniform(200, 40000);
    cases.push_back(c);
  }
  Worst worst;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const auto [r, dr, sweep, feed] = cases[k];
    const bool cw = k % 2 == 1;
    const double end_angle = cw ? -sweep : sweep;
    const AxisValues to = xyz((r + dr) * std::cos(end_angle), (r + dr) * std::sin(end_angle), 0);
    MotionPrimitive a = arc(xyz(r, 0, 0), to, 0, 1, 0, 0, cw, feed);
    a.exact_stop = true;
    const Trace t = run(m, {a});
    const Worst w = check(m, t);
    worst.velocity = std::max(worst.velocity, w.velocity);
    worst.acceleration = std::max(worst.acceleration, w.acceleration);
    worst.jerk = std::max(worst.jerk, w.jerk);
    ASSERT_FALSE(t.points.empty());
    EXPECT_EQ(t.points.back(), to) << "r " << r << " dr " << dr << " sweep " << sweep;
  }
  EXPECT_LE(worst.velocity, 1.0 + kTolerance);
  EXPECT_LE(worst.acceleration, 1.0 + kTolerance);
  EXPECT_LE(worst.jerk, 1.0 + kTolerance);
}

}  // namespace
}  // namespace ncc::motion_test
