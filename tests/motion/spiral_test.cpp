// Spirals: arcs whose end radius differs from their start radius (FANUC accepts the difference
// up to a parameter, and CAM output rounds most arc centres), interpolated with the radius
// linear in the angle. Their parameter is not exactly the arc length; the planner must keep
// them within the axis limits anyway.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "motion_test_util.h"
#include "ncc/vm/motion/limits.h"
#include "ncc/vm/motion/path.h"

namespace ncc::motion_test {
namespace {

using vm::motion::PathSegment;

// Counter-clockwise (clockwise if `cw`) around the origin in XY from (r, 0) through `sweep`
// radians to radius r + dr, Z rising dz.
PathSegment spiral(double r, double dr, double sweep, bool cw = false, double dz = 0.0) {
  const double end_angle = cw ? -sweep : sweep;
  return PathSegment::arc(xyz(r, 0, 0),
                          xyz((r + dr) * std::cos(end_angle), (r + dr) * std::sin(end_angle), dz), 3,
                          0, 1, 0.0, 0.0, cw, 0);
}

// The length of the polygon through n + 1 points of p, equally spaced in s.
double polygonLength(const PathSegment& p, int n) {
  double sum = 0.0;
  AxisValues a, b;
  p.position(0.0, a);
  for (int k = 1; k <= n; ++k) {
    p.position(p.length() * k / n, b);
    sum += distance(a, b);
    a = b;
  }
  return sum;
}

// |v| over X Y Z.
double norm3(const AxisValues& v) { return distance(v, AxisValues{}); }

// What sampling a spiral finds, by central differences of position (speed) and of
// curvature() (its rate), and the part of curvature() along the tangent.
struct Sampled {
  double speed = 0.0, min_speed = INFINITY, curvature = 0.0, rate = 0.0, along = 0.0;
  AxisValues tangent{}, normal{};  // largest |dx_i/ds|, |d2x_i/ds2|
};
Sampled sample(const PathSegment& p) {
  Sampled out;
  constexpr int kSamples = 400;
  const double h = p.length() * 1e-5;
  for (int k = 1; k < kSamples; ++k) {
    const double s = p.length() * k / kSamples;
    AxisValues a, b, ka, kb, k0, t;
    p.position(s - h, a);
    p.position(s + h, b);
    p.curvature(s - h, ka);
    p.curvature(s + h, kb);
    p.curvature(s, k0);
    p.tangent(s, t);
    double speed2 = 0.0, rate2 = 0.0, along = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double d = (b[i] - a[i]) / (2.0 * h), r = (kb[i] - ka[i]) / (2.0 * h);
      out.tangent[i] = std::max(out.tangent[i], std::abs(d));
      out.normal[i] = std::max(out.normal[i], std::abs(k0[i]));
      speed2 += d * d;
      rate2 += r * r;
      along += k0[i] * t[i];
    }
    out.speed = std::max(out.speed, std::sqrt(speed2));
    out.min_speed = std::min(out.min_speed, std::sqrt(speed2));
    out.curvature = std::max(out.curvature, norm3(k0));
    out.rate = std::max(out.rate, std::sqrt(rate2));
    out.along = std::max(out.along, std::abs(along));
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

// |dx/ds| at the ends, by one-sided differences.
double endSpeed(const PathSegment& p, bool at_start) {
  const double h = p.length() * 1e-7;
  AxisValues a, b;
  p.position(at_start ? 0.0 : p.length() - h, a);
  p.position(at_start ? h : p.length(), b);
  return distance(a, b) / h;
}

TEST(Spiral, ParameterIsTheArcLengthAtTheEnds) {
  // 0.001 rad at radius 0.2 is 0.0002 mm of arc, but the radius grows 0.01 mm: the length is
  // about the radial travel (the mean radius' arc made |dx/ds| 34); a spiral shrinking 2 %
  // over 2.7 rad; the same rising 3 mm; a CAM centre's rounding.
  const PathSegment cases[] = {spiral(0.2, 0.01, 0.001), spiral(0.32, -0.0068, 2.7, true),
                               spiral(0.32, -0.0068, 2.7, true, 3.0), spiral(10.0, 1e-4, 1.0)};
  for (const PathSegment& p : cases) {
    // s runs at most a hair ahead of the arc length between the ends (5e-6 on the helix).
    const double arc_length = polygonLength(p, 20000);
    EXPECT_GE(p.length(), arc_length * (1.0 - 1e-9));
    EXPECT_LE(p.length(), arc_length * (1.0 + 1e-5));
    // Unit speed at both ends: no velocity step where it joins its neighbours.
    EXPECT_NEAR(endSpeed(p, true), 1.0, 1e-6);
    EXPECT_NEAR(endSpeed(p, false), 1.0, 1e-6);
    const Sampled sampled = sample(p);
    EXPECT_LE(sampled.speed, 1.0 + 1e-9);
    EXPECT_GE(sampled.min_speed, 0.99);
  }
}

TEST(Spiral, BoundsHoldTheSampledDerivatives) {
  // From a radius change much smaller than the arc to much larger, flat and helical.
  Random rng(7);
  for (int n = 0; n < 300; ++n) {
    const double r = std::exp(rng.uniform(std::log(0.2), std::log(40.0)));
    const double sweep = std::exp(rng.uniform(std::log(1e-3), std::log(6.2)));
    const double dr = rng.uniform(-0.05, 0.05);
    const double dz = rng.below(2) == 0 ? 0.0 : rng.uniform(-3.0, 3.0);
    const PathSegment p = spiral(r, dr, sweep, rng.below(2) == 0, dz);
    const Sampled sampled = sample(p);
    const auto where = [&] {
      return ::testing::Message() << "r " << r << " dr " << dr << " sweep " << sweep << " dz " << dz;
    };
    AxisValues tangent, normal;
    p.maxTangent(tangent);
    p.normalShare(normal);
    const double k = p.maxCurvature();
    for (int i = 0; i < 3; ++i) {
      EXPECT_LE(sampled.tangent[i], tangent[i] * (1.0 + 1e-6) + 1e-9) << where() << " axis " << i;
      EXPECT_LE(sampled.normal[i], normal[i] * k * (1.0 + 1e-9) + 1e-12) << where() << " axis " << i;
    }
    EXPECT_LE(sampled.curvature, k * (1.0 + 1e-9)) << where();
    EXPECT_LE(sampled.rate, p.maxCurvatureRate() * (1.0 + 1e-4)) << where();
    // The part of d2x/ds2 along the tangent is what the stretch pays for.
    EXPECT_LE(sampled.along, (p.parameterStretch() - 1.0) * k * (1.0 + 1e-6) + 1e-12) << where();
    // radius(): the smallest radius of curvature, which the chord error is computed from.
    const double sampled_radius = sampledRadiusOfCurvature(p);
    EXPECT_LE(p.radius(), sampled_radius * (1.0 + 1e-3)) << where();
    EXPECT_GE(p.radius(), sampled_radius * 0.99) << where();
  }
}

TEST(Spiral, PartIsTheSpiralBetweenItsEnds) {
  // A piece of a spiral (what corner blends leave of it) runs on the same spiral between the
  // parent's points at s0 and s1, at unit speed at its own ends, for about s1 - s0.
  const PathSegment p = spiral(0.32, -0.0068, 2.7, true, 3.0);
  const double s0 = 0.3 * p.length(), s1 = 0.8 * p.length();
  const PathSegment piece = p.part(s0, s1);
  AxisValues a, b;
  p.position(s0, a);
  piece.position(0.0, b);
  EXPECT_EQ(a, b);
  p.position(s1, a);
  piece.position(piece.length(), b);
  EXPECT_EQ(a, b);
  EXPECT_NEAR(piece.length(), s1 - s0, 1e-5 * (s1 - s0));
  EXPECT_NEAR(endSpeed(piece, true), 1.0, 1e-6);
  EXPECT_NEAR(endSpeed(piece, false), 1.0, 1e-6);
  for (int k = 0; k <= 50; ++k) {
    piece.position(piece.length() * k / 50, b);
    EXPECT_LT(p.distanceTo(b), 1e-9) << "k " << k;
  }
}

TEST(Spiral, GeometricCurvatureIsTheCurvesOwn) {
  // |x' x x''| / |x'|^3 by central differences of position, whatever the parameter's speed;
  // curvature() is |x'|^2 times it plus a part along the tangent (2.5 % off on the spiral of
  // the test below: a corner blend matched to it met the spiral with a curvature step).
  Random rng(11);
  for (int n = 0; n < 60; ++n) {
    const double r = std::exp(rng.uniform(std::log(0.3), std::log(20.0)));
    const double dr = rng.uniform(-0.3, 0.3) * r;
    const double dz = rng.below(2) == 0 ? 0.0 : rng.uniform(-3.0, 3.0);
    const PathSegment p = spiral(r, dr, rng.uniform(0.3, 3.0), rng.below(2) == 0, dz);
    for (int k = 1; k < 20; ++k) {
      const double s = p.length() * k / 20, h = p.length() * 1e-4;
      AxisValues a, b, c, kappa, t;
      p.position(s - h, a);
      p.position(s, b);
      p.position(s + h, c);
      double d1[3], d2[3];
      for (int i = 0; i < 3; ++i) {
        d1[i] = (c[i] - a[i]) / (2.0 * h);
        d2[i] = (c[i] - 2.0 * b[i] + a[i]) / (h * h);
      }
      const double cross[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                               d1[0] * d2[1] - d1[1] * d2[0]};
      const double speed = std::sqrt(d1[0] * d1[0] + d1[1] * d1[1] + d1[2] * d1[2]);
      const double sampled =
          std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]) /
          (speed * speed * speed);
      p.geometricCurvature(s, kappa);
      p.tangent(s, t);
      EXPECT_NEAR(norm3(kappa), sampled, 1e-5 * sampled) << "r " << r << " dr " << dr << " k " << k;
      EXPECT_NEAR(kappa[0] * t[0] + kappa[1] * t[1] + kappa[2] * t[2], 0.0, 1e-12 * sampled);
    }
  }
}

TEST(Spiral, CornerBlendsJoinATrimmedSpiralWithoutASpeedStep) {
  // Found by review: a line, a spiral from R 1 to R 0.5 over 1 rad, and a line 0.05 rad off its
  // end tangent, with G64 blends at both corners, at T = 0.5 ms. The blend joins the spiral
  // inside it, where its parent's parameter ran at 0.987 of the path speed: the axes' speed
  // stepped by 1.3 % and read 8.5x the jerk limit.
  MachineConfig m = defaultMachine();
  m.ipo_cycle_seconds = 0.0005;
  m.corner_tolerance = 0.01;
  const double start = -0.5 * std::numbers::pi, end = start + 1.0;
  const AxisValues a = xyz(-1, -1, 0), b = xyz(0, -1, 0);
  const AxisValues c = xyz(0.5 * std::cos(end), 0.5 * std::sin(end), 0);
  // The spiral's end tangent (dr/dphi = -0.5, counter-clockwise), turned by 0.05 rad.
  const double tx = -0.5 * std::cos(end) - 0.5 * std::sin(end);
  const double ty = -0.5 * std::sin(end) + 0.5 * std::cos(end);
  const double n = std::hypot(tx, ty), turn = 0.05;
  const double dx = (tx * std::cos(turn) - ty * std::sin(turn)) / n;
  const double dy = (tx * std::sin(turn) + ty * std::cos(turn)) / n;
  const std::vector<MotionPrimitive> program = {
      line(a, b, 600.0), arc(b, c, 0, 1, 0.0, 0.0, false, 3000.0),
      line(c, xyz(c[0] + dx, c[1] + dy, 0), 3000.0)};
  const Trace t = run(m, program);
  expectWithinLimits(m, t);
  EXPECT_EQ(t.points.back(), program.back().to);
}

TEST(Spiral, ChordErrorIsCappedBelowTheToleranceRadius) {
  // A spiral whose smallest radius of curvature is below the chord tolerance but which is
  // much larger at its other end: a circle that small is within the tolerance of any chord,
  // this spiral is not, so the general cap sqrt(8 e / k) / T holds (it had none; on stiff
  // axes nothing else held the speed down).
  vm::motion::AxisLimits axes;
  axes.count = 3;
  for (int i = 0; i < 3; ++i) {
    axes.feed_velocity[i] = 1e6;
    axes.acceleration[i] = 1e6;
    axes.jerk[i] = 1e9;
  }
  axes.ipo_cycle = 0.004;
  axes.chord_tolerance = 0.005;
  const PathSegment p = spiral(0.001, 0.05, 6.0);
  ASSERT_LT(p.radius(), axes.chord_tolerance);
  const vm::motion::SegmentLimits limits = vm::motion::segmentLimits(
      p, axes, false, 1e6, vm::motion::ChainShape{}, vm::motion::kSmoothJerkShare);
  EXPECT_LE(limits.velocity,
            std::sqrt(8.0 * axes.chord_tolerance / p.maxCurvature()) / axes.ipo_cycle * (1.0 + 1e-12));
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

// A program of spirals (in any plane, some helical, some with an extra turn), lines between
// some of them, and exact stops: the corners are blended (corner tolerance 0.01 mm).
std::vector<MotionPrimitive> spiralProgram(Random& rng, int axes, int pieces) {
  std::vector<MotionPrimitive> program;
  AxisValues at{};
  const auto feed = [&] { return rng.below(3) == 0 ? rng.uniform(8000, 40000) : rng.uniform(200, 8000); };
  const auto emit = [&](MotionPrimitive m) {
    m.where.line = static_cast<uint32_t>(program.size() + 1);
    program.push_back(m);
    at = m.to;
  };
  const auto addLine = [&] {
    AxisValues to = at;
    const double length = std::exp(rng.uniform(std::log(0.005), std::log(20.0)));
    for (int i = 0; i < axes; ++i)
      if (i < 3 || rng.below(3) == 0) to[i] += length * rng.uniform(-1, 1);
    emit(line(at, to, feed()));
  };
  const auto addSpiral = [&] {
    static constexpr int kPlanes[3][2] = {{0, 1}, {2, 0}, {1, 2}};
    const int* plane = kPlanes[rng.below(3)];
    const double r = std::exp(rng.uniform(std::log(0.2), std::log(40.0)));
    const double sweep = rng.below(4) == 0 ? std::exp(rng.uniform(std::log(1e-3), std::log(0.3)))
                                           : rng.uniform(0.3, 6.28);
    const bool cw = rng.below(2) == 0;
    const double start = rng.uniform(0, 2 * std::numbers::pi);
    const double c1 = at[plane[0]] - r * std::cos(start), c2 = at[plane[1]] - r * std::sin(start);
    const double end = start + (cw ? -sweep : sweep);
    const double r1 = r + (rng.below(5) == 0 ? 0.0 : rng.uniform(-0.01, 0.01));
    AxisValues to = at;
    to[plane[0]] = c1 + r1 * std::cos(end);
    to[plane[1]] = c2 + r1 * std::sin(end);
    if (rng.below(2) == 0)
      for (int i = 0; i < axes; ++i)
        if (i != plane[0] && i != plane[1] && rng.below(2) == 0) to[i] += rng.uniform(-3, 3);
    emit(arc(at, to, plane[0], plane[1], c1, c2, cw, feed(), rng.below(6) == 0 ? 1 : 0));
  };
  for (int k = 0; k < pieces; ++k) {
    const int kind = rng.below(10);
    if (kind < 5) addSpiral();
    else if (kind < 8) addLine();
    else if (kind == 8) addSpiral(), addLine(), addSpiral();
    else if (!program.empty()) program.back().exact_stop = true;
  }
  return program;
}

TEST(Spiral, ChainsOfSpiralsStayWithinTheAxisLimits) {
  // Where a spiral joins a corner blend its speed must be 1, as the blend's is: with r linear
  // in s, one shrinking 2 % over 7 rad ended at 0.989 and its corner blend read 1.109x the
  // jerk limit (and 2 of these 100 programs failed).
  Worst worst;
  for (uint64_t seed = 1; seed <= 100; ++seed) {
    const int axes = 3 + static_cast<int>(seed % 4);
    MachineConfig m = unequalAxes();
    for (int i = 3; i < axes; ++i) {
      AxisConfig a;
      a.name = std::string(1, "UVW"[i - 3]);
      a.max_velocity = 5000.0 + 2000.0 * i;
      a.rapid_velocity = 2.0 * a.max_velocity;
      a.max_acceleration = 1000.0 * i;
      a.max_jerk = 20000.0 * i;
      m.axes.push_back(a);
    }
    Random rng(seed);
    const std::vector<MotionPrimitive> program = spiralProgram(rng, axes, 25);
    const Trace t = run(m, program);
    const Worst w = check(m, t);
    worst.velocity = std::max(worst.velocity, w.velocity);
    worst.acceleration = std::max(worst.acceleration, w.acceleration);
    worst.jerk = std::max(worst.jerk, w.jerk);
    ASSERT_FALSE(t.points.empty());
    EXPECT_EQ(t.points.back(), program.back().to) << "seed " << seed;
    for (const MotionPrimitive& p : program) {
      if (p.exact_stop) {
        EXPECT_NE(std::find(t.points.begin(), t.points.end(), p.to), t.points.end())
            << "seed " << seed << " line " << p.where.line;
      }
    }
  }
  EXPECT_LE(worst.velocity, 1.0 + kTolerance);
  EXPECT_LE(worst.acceleration, 1.0 + kTolerance);
  EXPECT_LE(worst.jerk, 1.0 + kTolerance);
}

}  // namespace
}  // namespace ncc::motion_test
