// Bowed chains (continuous_path.h, path_bow.cpp): the chords of a smooth chain drawn as cubics
// that meet with one tangent at each vertex. The bow itself (its ends, its bounds), and random
// CAM-like chains through the planner: every sampled limit, the corner tolerance, exact ends.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "gtest/gtest.h"
#include "motion_test_util.h"
#include "ncc/vm/motion/path.h"

namespace ncc::motion_test {
namespace {

using vm::motion::PathSegment;

double norm(const AxisValues& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

AxisValues unit(const AxisValues& v) {
  const double n = norm(v);
  AxisValues u{};
  for (std::size_t i = 0; i < v.size(); ++i) u[i] = v[i] / n;
  return u;
}

// A random chord, end tangents within `turn` radians of it and curvature vectors normal to
// them of up to 4 turn / length, in 3 axes.
struct RandomBow {
  AxisValues from, to, t0, t1, k0, k1;
};
RandomBow randomBow(Random& rng, double turn) {
  RandomBow b;
  b.from = xyz(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
  const double length = std::exp(rng.uniform(std::log(1e-4), std::log(5.0)));
  const AxisValues c = unit(xyz(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
  for (int i = 0; i < 3; ++i) b.to[i] = b.from[i] + length * c[i];
  auto tilt = [&]() {
    AxisValues t = c;
    const double a = turn * rng.uniform(0.0, 1.0);
    const AxisValues d = xyz(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    for (int i = 0; i < 3; ++i) t[i] += std::tan(a) * d[i];
    return unit(t);
  };
  b.t0 = tilt();
  b.t1 = rng.below(4) == 0 ? c : tilt();
  auto bend = [&](const AxisValues& t) {
    AxisValues k = xyz(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    double along = 0.0;
    for (int i = 0; i < 3; ++i) along += k[i] * t[i];
    const double size = rng.uniform(0.0, 4.0) * turn / length;
    for (int i = 0; i < 3; ++i) k[i] -= along * t[i];
    const AxisValues u = unit(k);
    for (int i = 0; i < 3; ++i) k[i] = size * u[i];
    return k;
  };
  b.k0 = bend(b.t0);
  b.k1 = rng.below(4) == 0 ? AxisValues{} : bend(b.t1);
  return b;
}

TEST(Bow, MeetsItsEndsWithItsTangentsAndCurvaturesAtUnitSpeed) {
  Random rng(11);
  for (int k = 0; k < 2000; ++k) {
    const RandomBow r = randomBow(rng, 0.1);
    const PathSegment b = PathSegment::bow(r.from, r.to, r.t0, r.t1, r.k0, r.k1, 3);
    ASSERT_EQ(b.shape(), PathSegment::Shape::Bow);
    AxisValues p, t;
    b.position(0.0, p);
    EXPECT_EQ(p, r.from);
    b.position(b.length(), p);
    EXPECT_EQ(p, r.to);
    // dx/ds at the ends, by finite differences of the position: the tangents, at speed 1.
    const double h = 1e-6 * b.length();
    AxisValues a, c;
    b.position(h, a);
    b.position(0.0, c);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR((a[i] - c[i]) / h, r.t0[i], 1e-5) << k;
    b.position(b.length() - h, a);
    b.position(b.length(), c);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR((c[i] - a[i]) / h, r.t1[i], 1e-5) << k;
    b.tangent(0.0, t);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(t[i], r.t0[i], 1e-12);
    AxisValues bend;
    b.curvature(0.0, bend);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(bend[i], r.k0[i], 1e-9 * (norm(r.k0) + 1.0)) << k;
    b.curvature(b.length(), bend);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(bend[i], r.k1[i], 1e-9 * (norm(r.k1) + 1.0)) << k;
  }
  // Tangents along the chord: a line.
  const AxisValues c = unit(xyz(1, 2, 3));
  EXPECT_EQ(PathSegment::bow(xyz(0, 0, 0), xyz(1, 2, 3), c, c, {}, {}, 3).shape(),
            PathSegment::Shape::Line);
}

TEST(Bow, BoundsHoldAlongTheCurve) {
  // Dense samples of |dx/ds|, |dx_i/ds|, |d2x/ds2|, its axis shares, |d3x/ds3| and the
  // stretch's inequality |a x' + v^2 x''| <= stretch sqrt(a^2 + (v^2 K)^2) against the bounds.
  Random rng(12);
  double tightest_speed = 0.0, tightest_curvature = 0.0;
  for (int k = 0; k < 3000; ++k) {
    const RandomBow r = randomBow(rng, k % 2 == 0 ? 0.1 : 1e-3);
    const PathSegment b = PathSegment::bow(r.from, r.to, r.t0, r.t1, r.k0, r.k1, 3);
    if (b.shape() != PathSegment::Shape::Bow) continue;
    AxisValues tangent_bound, normal_share;
    b.maxTangent(tangent_bound);
    b.normalShare(normal_share);
    const double K = b.maxCurvature(), stretch = b.parameterStretch();
    const double L = b.length(), h = 1e-3 * L;
    double speed_max = 0.0, curvature_max = 0.0;
    for (int j = 1; j < 200; ++j) {
      const double s = L * j / 200.0;
      AxisValues p0, p1, p2, k2;
      b.position(s - h, p0);
      b.position(s, p1);
      b.position(s + h, p2);
      b.curvature(s, k2);
      AxisValues v{};
      for (int i = 0; i < 3; ++i) v[i] = (p2[i] - p0[i]) / (2 * h);
      const double speed = norm(v), curvature = norm(k2);
      speed_max = std::max(speed_max, speed);
      curvature_max = std::max(curvature_max, curvature);
      EXPECT_LE(speed, b.maxSpeed() * (1 + 1e-9)) << k;
      EXPECT_LE(curvature, K * (1 + 1e-12)) << k;
      for (int i = 0; i < 3; ++i) {
        EXPECT_LE(std::abs(v[i]), tangent_bound[i] + 1e-9) << k;
        EXPECT_LE(std::abs(k2[i]), K * normal_share[i] * (1 + 1e-12) + 1e-300) << k;
      }
      for (double ratio : {0.0, 0.3, 1.0, 3.0, 1e3}) {
        // a_t = ratio * v^2 K: both signs.
        for (double sign : {1.0, -1.0}) {
          double sum = 0.0;
          for (int i = 0; i < 3; ++i) {
            const double x = sign * ratio * K * v[i] / speed * speed + k2[i];
            sum += x * x;
          }
          EXPECT_LE(std::sqrt(sum), stretch * K * std::sqrt(ratio * ratio + 1.0) * (1 + 1e-9)) << k;
        }
      }
    }
    tightest_speed = std::max(tightest_speed, (speed_max - 1.0) / (b.maxSpeed() - 1.0 + 1e-300));
    tightest_curvature = std::max(tightest_curvature, curvature_max / K);
    // |d3x/ds3| by differences of the curvature.
    for (int j = 1; j < 100; ++j) {
      const double s = L * j / 100.0;
      AxisValues ka, kb;
      b.curvature(s - h, ka);
      b.curvature(s + h, kb);
      AxisValues d{};
      for (int i = 0; i < 3; ++i) d[i] = (kb[i] - ka[i]) / (2 * h);
      EXPECT_LE(norm(d), b.maxCurvatureRate() * (1 + 1e-6)) << k;
    }
  }
  // The bounds are not loose: the curvature's within 10 % of its bound on some bow.
  EXPECT_GT(tightest_curvature, 0.9);
}

// A machine for the chains: IPO cycle, corner tolerance and axis limits drawn at random.
MachineConfig randomMachine(Random& rng) {
  MachineConfig m = defaultMachine();
  m.ipo_cycle_seconds = std::array{0.0005, 0.001, 0.002, 0.004}[rng.below(4)];
  m.corner_tolerance = std::exp(rng.uniform(std::log(1e-4), std::log(0.05)));
  for (int i = 0; i < 3; ++i) {
    m.axes[i].max_acceleration *= std::exp(rng.uniform(std::log(0.2), std::log(3.0)));
    m.axes[i].max_jerk *= std::exp(rng.uniform(std::log(0.1), std::log(10.0)));
  }
  return m;
}

// A smooth curve written as chords: an ellipse, a spiral, a wave or a helix, chords of 2 um to
// 0.5 mm (constant, or varying like a CAM system's), exact or rounded to 0.1 um or 1 um.
std::vector<MotionPrimitive> randomChain(Random& rng, double feed) {
  const int kind = static_cast<int>(rng.below(4));
  const double a = rng.uniform(1.0, 30.0), b = rng.uniform(0.2, 1.0) * a;
  const double mean_chord = std::exp(rng.uniform(std::log(0.002), std::log(0.5)));
  const bool varying = rng.below(2) == 0;
  const double rounding = std::array{0.0, 1e-4, 1e-3}[rng.below(3)];
  const double sweep = rng.uniform(0.5, 6.0);
  auto point = [&](double u) {  // u in [0, 1]
    const double th = sweep * u;
    switch (kind) {
      case 0: return xyz(a * std::cos(th), b * std::sin(th), 0.0);
      case 1: return xyz((a - 0.8 * a * u) * std::cos(th), (a - 0.8 * a * u) * std::sin(th), 0.0);
      case 2: return xyz(a * th, b * 0.3 * std::sin(th * 2.0) + 0.1 * b * std::sin(th * 5.0), 0.0);
      default: return xyz(a * std::cos(th), a * std::sin(th), b * 0.2 * th);
    }
  };
  // Length of the curve, roughly, for the number of chords.
  double length = 0.0;
  for (int i = 1; i <= 1000; ++i) length += distance(point((i - 1) / 1000.0), point(i / 1000.0));
  std::vector<MotionPrimitive> prog;
  AxisValues p = point(0.0);
  double u = 0.0;
  while (u < 1.0 && prog.size() < 1500) {
    const double chord = varying ? mean_chord * std::exp(rng.uniform(-1.0, 1.0)) : mean_chord;
    u = std::min(1.0, u + chord / length);
    AxisValues q = point(u);
    if (rounding > 0.0)
      for (int i = 0; i < 3; ++i) q[i] = std::round(q[i] / rounding) * rounding;
    if (q == p) continue;
    prog.push_back(line(p, q, feed));
    p = q;
  }
  return prog;
}

TEST(BowChains, RandomCurvesKeepTheLimitsAndTheTolerance) {
  // Random smooth curves in chords on random machines: every sampled limit, every setpoint
  // within the corner tolerance of the programmed polygon, the exact end.
  Random rng(21);
  Worst overall;
  double worst_deviation = 0.0;
  for (int k = 0; k < 24; ++k) {
    const MachineConfig m = randomMachine(rng);
    const double feed = std::exp(rng.uniform(std::log(1000.0), std::log(20000.0)));
    const std::vector<MotionPrimitive> prog = randomChain(rng, feed);
    if (prog.empty()) continue;
    const Trace t = run(m, prog, 4096);
    ASSERT_GT(t.ticks(), 0u);
    const Worst w = check(m, t);
    EXPECT_LE(w.velocity, 1.0 + kTolerance) << "case " << k;
    EXPECT_LE(w.acceleration, 1.0 + kTolerance) << "case " << k;
    EXPECT_LE(w.jerk, 1.0 + kTolerance) << "case " << k;
    EXPECT_EQ(t.points.back(), prog.back().to) << "case " << k;
    const double deviation = worstDeviation(t, prog);
    EXPECT_LE(deviation, m.corner_tolerance * (1 + 1e-9)) << "case " << k;
    worst_deviation = std::max(worst_deviation, deviation / m.corner_tolerance);
    overall.velocity = std::max(overall.velocity, w.velocity);
    overall.acceleration = std::max(overall.acceleration, w.acceleration);
    overall.jerk = std::max(overall.jerk, w.jerk);
  }
  std::printf("bowed chains: worst ratio to axis limit v %.6f a %.6f j %.6f, deviation %.3f of "
              "the tolerance\n",
              overall.velocity, overall.acceleration, overall.jerk, worst_deviation);
}

// An ellipse (a = 10, b) in chords of about `chord` mm at `feed`, from rest to rest.
std::vector<MotionPrimitive> ellipse(double b, double chord, double feed) {
  std::vector<MotionPrimitive> prog;
  const int n = static_cast<int>(2.0 * std::numbers::pi * 10.0 / chord);
  AxisValues p = xyz(10.0, 0.0, 0.0);
  for (int i = 1; i <= n; ++i) {
    const double t = 2.0 * std::numbers::pi * i / n;
    const AxisValues q = i == n ? xyz(10.0, 0.0, 0.0) : xyz(10.0 * std::cos(t), b * std::sin(t), 0.0);
    prog.push_back(line(p, q, feed));
    p = q;
  }
  return prog;
}

// A chain run through the planner on `m`, checked against every axis limit and the corner
// tolerance of its chords.
Trace runChain(const MachineConfig& m, const std::vector<MotionPrimitive>& prog) {
  Trace t = run(m, prog, 4096);
  expectWithinAxisLimits(m, t);
  EXPECT_LE(worstDeviation(t, prog), m.corner_tolerance);
  return t;
}

// A circle r 10 in chords of about `chord` mm at F6000, the vertices rounded to `rounding`.
std::vector<MotionPrimitive> roundedCircle(double chord, double rounding) {
  const double r = 10.0;
  return polygonCircle(r, static_cast<int>(std::lround(2.0 * std::numbers::pi * r / chord)),
                       6000.0, rounding);
}

TEST(BowChains, CoarseChordsOfACircleRunLikeTheArc) {
  // R 10 in 0.2 mm chords at F6000: bowed, the chain runs like the arc itself (the quintics
  // through the vertices with the circle's tangents and curvature are the circle within
  // 1e-10 mm). Without a corner tolerance the polygon's vertices (0.02 rad) are kinks, passed
  // at about 4 mm/s: 20 times slower.
  const MachineConfig m = defaultMachine();
  const double r = 10.0;
  const std::vector<MotionPrimitive> prog =
      polygonCircle(r, static_cast<int>(std::lround(2.0 * std::numbers::pi * r / 0.2)), 6000.0);
  const Trace bowed = run(m, prog, 4096);
  const Trace the_arc = run(m, {arc(xyz(r, 0, 0), xyz(r, 0, 0), 0, 1, 0.0, 0.0, false, 6000.0)});
  MachineConfig no_tolerance = m;
  no_tolerance.corner_tolerance = 0.0;
  const Trace polygon = run(no_tolerance, prog, 4096);
  EXPECT_LT(static_cast<double>(bowed.ticks()), 1.02 * static_cast<double>(the_arc.ticks()));
  EXPECT_GT(static_cast<double>(polygon.ticks()), 10.0 * static_cast<double>(bowed.ticks()));
  expectWithinAxisLimits(m, bowed);
  EXPECT_EQ(bowed.points.back(), prog.back().to);
  // Within the sagitta, c^2 / 8 r = 0.5 um, of the chords.
  EXPECT_LE(worstDeviation(bowed, prog), 5.01e-4);
}

TEST(BowChains, AnEllipseInCoarseChordsRunsAtItsCurvaturesSpeed) {
  // Ellipses (a = 10, b = 5 and 2) in 0.05 mm chords at F6000: the chords turn by up to 0.02
  // rad, too much for the polygon (its vertices were blended: 4.4 and 4.5 s); bowed, about
  // 1.6 and 1.7 s.
  const MachineConfig m = defaultMachine();
  for (double b : {5.0, 2.0}) {
    EXPECT_LT(runChain(m, ellipse(b, 0.05, 6000.0)).ticks(), 1800u) << b;
  }
}

TEST(BowChains, AnEllipseInFineChordsRunsAsFastAsInCoarseOnes) {
  // The same ellipse (b = 5) in 0.005 mm chords: each bow takes the lower of two bounds
  // (bowShape), and where they are close the choice flips from bow to bow, so the limits of
  // neighbouring bows alternate between a faster and a slower set. The fast ones made runs of
  // one bow, each ending at a = 0, and the speed could not ramp: 1.9 s (written with 9
  // decimals to `ncc run`: 3.6 s, a third of the bows runs of their own). A faster short
  // segment now joins the run before it while the faster tail is no longer than the rest
  // (LookAhead, tooShortToSplit): 1.55 s (1.34 s with no bound, which made feed steps up
  // crawl: LookAhead.AFeedStepUpDoesNotDragTheFastStretch).
  // Chords of equal length, as CAM systems write them (ellipse() steps the angle evenly),
  // the coordinates in whole nanometres (written with 9 decimals: exact, they take 1.2 s).
  const MachineConfig m = defaultMachine();
  auto nm = [](double x) { return std::round(x * 1e9) / 1e9; };
  std::vector<MotionPrimitive> prog;
  AxisValues p = xyz(10.0, 0.0, 0.0);
  for (double t = 0.0; t < 2.0 * std::numbers::pi;) {
    t += 0.005 / std::hypot(10.0 * std::sin(t), 5.0 * std::cos(t));
    const AxisValues q = t >= 2.0 * std::numbers::pi
                             ? xyz(10.0, 0.0, 0.0)
                             : xyz(nm(10.0 * std::cos(t)), nm(5.0 * std::sin(t)), 0.0);
    prog.push_back(line(p, q, 6000.0));
    p = q;
  }
  EXPECT_LT(runChain(m, prog).ticks(), 1700u);
}

TEST(BowChains, AWaveThroughItsInflectionsIsOneChain) {
  // A sine wave (amplitude 0.5 mm, 3.14 mm long) in 0.05 mm chords at F3000, the curve of the
  // six-axis benchmark: its curvature changes sign every half wave. The noise rule looks at
  // the second difference of the polygon's curvature, small there too, so the wave is bowed
  // through: 3.0 s. (With the first difference against the curvature's size, each half wave
  // was a chain of its own, ending straight at the inflection: 4.9 s; blended, 3.8 s.)
  const MachineConfig m = defaultMachine();
  std::vector<MotionPrimitive> prog;
  AxisValues p{};
  for (int i = 1; i <= 400; ++i) {
    const AxisValues q = xyz(0.05 * i, 0.5 * std::sin(0.1 * i), 0.0);
    prog.push_back(line(p, q, 3000.0));
    p = q;
  }
  EXPECT_LT(runChain(m, prog).ticks(), 3200u);
}

TEST(BowChains, ABowedChainStaysBowedThroughModerateNoise) {
  // A circle r 10 in 0.2 mm chords rounded to 0.1 um: the rounding moves the second
  // difference of the polygon's curvature to about a tenth of the curvature, around the noise
  // rule's threshold, so some vertices passed it and others did not, and bows (curvature k)
  // and blends (curvature 0 at their ends) alternated: 3.5 s. Once bowing, a chain now goes
  // on while the change is within half the curvature (kSmoothKeep): 1.8 s.
  EXPECT_LT(runChain(defaultMachine(), roundedCircle(0.2, 1e-4)).ticks(), 2000u);
}

TEST(BowChains, NoisyChordsAreSmoothedByBlends) {
  // A circle r 10 in 0.05 mm chords rounded to 1 um, as a CAM system writes it: the rounding
  // moves the polygon's curvature by many times itself from vertex to vertex. Bowed through
  // its points, the path would follow the noise (10 to 14 s); the noise rule leaves the
  // vertices to the blends (within the tolerance, off the points), as before bows: 8 s (the
  // polygon without a tolerance: 31 s).
  EXPECT_LT(runChain(defaultMachine(), roundedCircle(0.05, 1e-3)).ticks(), 8200u);
}

}  // namespace
}  // namespace ncc::motion_test
