// The 1-D S-curve profile against closed forms (docs/planner.md) and its limit properties.
#include "ncc/vm/motion/scurve.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "gtest/gtest.h"
#include "motion_test_util.h"

namespace ncc::vm::motion {
namespace {

constexpr double kA = 2000.0;   // mm/s^2
constexpr double kJ = 50000.0;  // mm/s^3; a^2/j = 80 mm/s

using motion_test::restToRestTime;  // the four closed forms (docs/planner.md)

struct Case {
  double length, v_max;
  const char* regime;
};

TEST(SCurve, RestToRestTimeMatchesClosedForm) {
  const Case cases[] = {
      {100.0, 200.0, "v and a reached"},      // T = L/v + v/a + a/j = 0.64
      {100.0, 50.0, "v reached, a not"},      // T = L/v + 2 sqrt(v/j)
      {10.0, 1000.0, "a reached, v not"},     // T = a/j + sqrt((a/j)^2 + 4L/a)
      {0.1, 1000.0, "neither reached"},       // T = 4 cbrt(L / 2j)
      {1.0, 1000.0, "a reached, v not (short)"},
      {2.0, 30.0, "v reached, a not (short)"},
  };
  for (const Case& c : cases) {
    const SCurveProfile p = planProfile(c.length, 0.0, 0.0, c.v_max, kA, kJ);
    const double expected = restToRestTime(c.length, c.v_max, kA, kJ);
    EXPECT_NEAR(p.duration, expected, 1e-12 * expected) << c.regime << " L=" << c.length;
    EXPECT_EQ(p.at(p.duration).s, c.length) << c.regime;
    EXPECT_EQ(p.at(p.duration).v, 0.0);
    EXPECT_TRUE(p.end_reachable);
  }
  // The first case by hand.
  EXPECT_NEAR(planProfile(100.0, 0.0, 0.0, 200.0, kA, kJ).duration, 0.64, 1e-14);
  EXPECT_NEAR(planProfile(0.1, 0.0, 0.0, 1000.0, kA, kJ).duration, 0.04, 1e-14);
}

TEST(SCurve, ReachableVelocityInvertsRampDistance) {
  for (double v : {0.0, 1.0, 30.0, 200.0}) {
    for (double L : {1e-5, 0.01, 0.3, 5.0, 80.0}) {
      const double w = reachableVelocity(v, L, kA, kJ);
      EXPECT_GT(w, v);
      // w = v + dv is stored as an absolute velocity: dv carries the rounding of w (tiny
      // segments at high speed), so the tolerance is a few ulps of w through the slope.
      const double ulp_effect =
          std::abs(rampDistance(v, std::nextafter(w, 1e300), kA, kJ) - rampDistance(v, w, kA, kJ));
      EXPECT_NEAR(rampDistance(v, w, kA, kJ), L, 1e-12 * L + 4.0 * ulp_effect) << "v=" << v << " L=" << L;
    }
  }
}

// Never below the start speed, also where the gain is below its last digit (review 12: the
// trapezoid's root rounded a unit under v; the look-ahead's backward pass relies on it).
TEST(SCurve, ReachableVelocityIsAtLeastTheStart) {
  const double v = 364.96261011721595;
  EXPECT_GE(reachableVelocity(v, 3.28e-9, 0.00143, 1.07e9), v);
  EXPECT_GE(reachableVelocity(9.02e-187, 3.98e-281, 1.86e-123, 6.48e7), 9.02e-187);
  motion_test::Random rng(12);
  for (int n = 0; n < 20000; ++n) {
    const double w = std::exp(rng.uniform(-20.0, 7.0));
    const double L = std::exp(rng.uniform(-25.0, 5.0));
    const double a = std::exp(rng.uniform(-8.0, 10.0)), j = std::exp(rng.uniform(0.0, 22.0));
    EXPECT_GE(reachableVelocity(w, L, a, j), w) << w << " " << L << " " << a << " " << j;
  }
}

TEST(SCurve, UnreachableEndVelocityIsReported) {
  // 0 -> 100 mm/s needs more than 1 mm.
  const SCurveProfile up = planProfile(1.0, 0.0, 100.0, 200.0, kA, kJ);
  EXPECT_FALSE(up.end_reachable);
  EXPECT_NEAR(up.v_end, reachableVelocity(0.0, 1.0, kA, kJ), 1e-12);
  EXPECT_EQ(up.at(up.duration).s, 1.0);
  // Braking 100 -> 0 in 0.1 mm is impossible: reported, not hidden.
  const SCurveProfile down = planProfile(0.1, 100.0, 0.0, 200.0, kA, kJ);
  EXPECT_FALSE(down.end_reachable);
  EXPECT_GT(down.v_end, 0.0);
}

// Dense sampling of random profiles: limits hold, s(T) = L, ends match, no cruise is wasted.
TEST(SCurve, RandomProfilesRespectLimits) {
  motion_test::Random rng(42);
  for (int n = 0; n < 2000; ++n) {
    const double a = rng.uniform(100.0, 5000.0);
    const double j = rng.uniform(1000.0, 200000.0);
    const double v_max = rng.uniform(1.0, 500.0);
    const double L = std::exp(rng.uniform(std::log(1e-5), std::log(200.0)));
    double v0 = rng.uniform(0.0, v_max), v1 = rng.uniform(0.0, v_max);
    if (rng.below(4) == 0) v0 = 0.0;
    if (rng.below(4) == 0) v1 = 0.0;
    // Make the start brakeable, as the look-ahead guarantees. A peak below v_max leaves no
    // cruise beyond the solver tolerance (1e-8 mm).
    v0 = std::min(v0, reachableVelocity(v1, L, a, j));
    const SCurveProfile p = planProfile(L, v0, v1, v_max, a, j);
    ASSERT_GE(p.duration, 0.0);
    EXPECT_EQ(p.at(p.duration).s, L);
    EXPECT_EQ(p.at(0.0).v, v0);
    EXPECT_EQ(p.at(p.duration).v, p.v_end);
    if (p.end_reachable) { EXPECT_EQ(p.v_end, v1); }
    if (p.v_peak < v_max && p.end_reachable) { EXPECT_LT(p.t_cruise * p.v_peak, 1e-8 * (L + 1.0)); }
    double prev_s = 0.0;
    constexpr int kSamples = 400;
    for (int i = 0; i <= kSamples; ++i) {
      const double t = p.duration * i / kSamples;
      const PathState st = p.at(t);
      ASSERT_LE(st.v, v_max * (1.0 + 1e-12)) << n;
      ASSERT_GE(st.v, -1e-12 * v_max) << n;
      ASSERT_LE(std::abs(st.a), a * (1.0 + 1e-9)) << n;
      ASSERT_LE(std::abs(st.j), j) << n;
      ASSERT_GE(st.s, prev_s - 1e-12 * L) << n;
      prev_s = st.s;
    }
    // Continuity: s advances by the integral of v (midpoint rule error ~ j h^3).
    for (int i = 0; i < kSamples; ++i) {
      const double t0 = p.duration * i / kSamples, t1 = p.duration * (i + 1) / kSamples;
      const double h = t1 - t0;
      const double ds = p.at(t1).s - p.at(t0).s;
      // Tolerance: the midpoint rule (j h^3) plus the rounding of a peak velocity barely above
      // a high start velocity (relative 1e-8 of the length, see ReachableVelocity...).
      ASSERT_NEAR(ds, p.at(0.5 * (t0 + t1)).v * h, j * h * h * h + 1e-8 * L + 1e-12) << n;
    }
  }
}

// The peak velocity of a profile without cruise (both ramps meet) against a bisection of
// rampDistance(v_start, vp) + rampDistance(v_end, vp) = L to the last bit: the solver's result
// fits (never longer than L) and is the root to 1e-12. The first case is one from a G64
// blend where the root lies a few ulps above v_end, where the ramp from v_end grows like
// sqrt(vp - v_end) and plain Newton keeps overshooting.
TEST(SCurve, PeakVelocityIsTheRootOfTheRampDistances) {
  struct Peak {
    double length, v_start, v_end, v_max, a, j;
  };
  std::vector<Peak> cases = {
      {0.056217554721197993, 5.6445337265109057, 5.8247252863333134, 6.118743724738235,
       221.52342060619227, 7499.9999999999991},
      {0.035230083809227757, 2.1400070564211555, 3.4035668784600484, 33.000486901272822,
       1005.3724201780287, 31550.148178097916},
  };
  for (int k = 0; k < 200; ++k) {  // deterministic spread of short pieces
    const double u = (k + 0.5) / 200.0;
    cases.push_back({0.01 + 0.2 * u, 15.0 * std::fmod(7.3 * u, 1.0), 15.0 * std::fmod(3.1 * u, 1.0),
                     60.0, 300.0 + 1500.0 * std::fmod(5.7 * u, 1.0), 5000.0 + 40000.0 * u});
  }
  int solved = 0;
  for (const Peak& c : cases) {
    const SCurveProfile p = planProfile(c.length, c.v_start, c.v_end, c.v_max, c.a, c.j);
    if (!p.end_reachable || p.v_peak >= c.v_max) continue;  // not the case under test
    auto distance = [&](double vp) {
      return rampDistance(c.v_start, vp, c.a, c.j) + rampDistance(c.v_end, vp, c.a, c.j);
    };
    double lo = std::max(c.v_start, c.v_end), hi = c.v_max;
    if (distance(lo) >= c.length) continue;  // no ramps to solve for
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (distance(mid) <= c.length ? lo : hi) = mid;
    }
    ++solved;
    EXPECT_LE(distance(p.v_peak), c.length * (1.0 + 1e-15)) << c.length << " " << c.v_start;
    EXPECT_NEAR(p.v_peak, lo, 1e-12 * lo) << c.length << " " << c.v_start;
    EXPECT_NEAR(p.accel.distance + p.v_peak * p.t_cruise + p.decel.distance, c.length,
                1e-12 * c.length);
  }
  EXPECT_GT(solved, 50);  // the spread really exercises the solver
}

// Braking to rest over exactly the braking distance, short by rounding: the profile stops
// (v_end 0), it does not give up part-way. The braking distance is not monotone in the end
// velocity (a short triangular ramp brakes more gently), so the bisection this falls back on
// once ended at 4.99 mm/s in the first case, a G64 window end reached at 8.08 mm/s.
TEST(SCurve, StopThatFitsUpToRoundingEndsAtRest) {
  struct Stop {
    double v0, a, j;
  };
  for (const Stop& c : {Stop{8.084809, 410.762, 14936.0}, Stop{100.0, 2000.0, 50000.0},
                        Stop{3.0, 500.0, 100000.0}}) {
    const double exact = rampDistance(0.0, c.v0, c.a, c.j);
    for (double shortfall : {0.0, 1e-15, 1e-13, 1e-10}) {
      const double length = exact * (1.0 - shortfall);
      EXPECT_EQ(lowestReachableVelocity(c.v0, length, c.a, c.j), 0.0) << c.v0 << " " << shortfall;
      const SCurveProfile p = planProfile(length, c.v0, 0.0, c.v0, c.a, c.j);
      EXPECT_EQ(p.v_end, 0.0) << c.v0 << " " << shortfall;
    }
    // Genuinely too short: the lowest reachable velocity, and braking to it fits.
    const double half = 0.5 * exact;
    const double w = lowestReachableVelocity(c.v0, half, c.a, c.j);
    EXPECT_GT(w, 0.0);
    EXPECT_LE(rampDistance(w, c.v0, c.a, c.j), half * (1.0 + 1e-12));
  }
}

// The room an open run keeps for braking to an exit not known yet is the longest brake to any
// exit speed: a jerk-limited brake to a lower speed can need more path than one to rest
// (from 43.9 mm/s at 2000 mm/s^2 and 45000 mm/s^3: 1.448 mm to 6.04 mm/s, 1.371 mm to rest).
TEST(SCurve, BrakingReserveIsTheLongestBrakeToAnyExit) {
  EXPECT_GT(rampDistance(6.03518, 43.8884, 2000.0, 45000.0),
            rampDistance(0.0, 43.8884, 2000.0, 45000.0));
  for (const double a : {50.0, 2000.0, 20000.0}) {
    for (const double j : {1000.0, 45000.0, 1e6}) {
      for (const double v : {0.5, 43.8884, 500.0}) {
        const double reserve = brakingReserve(v, a, j);
        double longest = 0.0;
        for (int k = 0; k <= 4000; ++k)
          longest = std::max(longest, rampDistance(v * k / 4000.0, v, a, j));
        // Never short of any exit's brake (the grid's), and not longer than the true maximum
        // (within the grid's spacing of it).
        EXPECT_GE(reserve, longest * (1.0 - 1e-12)) << a << " " << j << " " << v;
        EXPECT_LE(reserve, longest * (1.0 + 1e-6)) << a << " " << j << " " << v;
        EXPECT_GE(reserve, rampDistance(0.0, v, a, j));
      }
    }
  }
}

}  // namespace
}  // namespace ncc::vm::motion
