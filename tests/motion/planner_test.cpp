// The planner and interpolator on analytic cases: rest-to-rest line time, a circle at
// constant F, 10 um chains at the programmed F, dwell, feed per revolution, exact stops.
#include "ncc/vm/motion/planner.h"

#include <cmath>
#include <numbers>

#include "gtest/gtest.h"
#include "motion_test_util.h"
#include "ncc/vm/motion/scurve.h"

namespace ncc::vm::motion {
namespace {

using namespace motion_test;

// Runs one primitive through `planner` to its end; returns the highest path speed and leaves
// the last setpoint in `end`.
double topSpeed(MotionPlanner& planner, const MotionPrimitive& mv, AxisValues& end) {
  EXPECT_TRUE(planner.push(mv));
  planner.endOfProgram();
  SetpointInfo info;
  double top = 0.0;
  for (uint64_t k = 0; planner.setpoint(k, end, info); ++k) top = std::max(top, info.velocity);
  return top;
}

TEST(Planner, RestToRestLineTimeMatchesClosedForm) {
  const MachineConfig m = defaultMachine();  // a = 2000, j = 50000, T = 1 ms
  // From rest to rest: the line's path jerk is the whole axis jerk (kBetweenStopsJerkShare).
  const double a = 2000.0, j = kBetweenStopsJerkShare * 50000.0;
  for (double L : {0.05, 0.5, 5.0, 50.0, 200.0}) {
    const double v = 100.0;  // F6000 along X
    const Trace t = run(m, {line(xyz(0, 0, 0), xyz(L, 0, 0), 6000.0)});
    const double T = planProfile(L, 0.0, 0.0, v, a, j).duration;
    // Closed form (both limits reached when L is long, docs/planner.md).
    if (L >= 50.0) { EXPECT_NEAR(T, L / v + v / a + a / j, 1e-12); }
    if (L == 0.05) { EXPECT_NEAR(T, 4.0 * std::cbrt(L / (2.0 * j)), 1e-12); }
    // The setpoints: tick k samples t = k ms for k*T <= T_end, then one more tick holds the
    // end point exactly (the stop sample).
    const uint64_t expected_ticks = static_cast<uint64_t>(std::floor(T / 0.001)) + 2;
    EXPECT_EQ(t.ticks(), expected_ticks) << "L=" << L;
    EXPECT_EQ(t.points.back(), xyz(L, 0, 0));
  }
}

TEST(Planner, FullCircleAtConstantFeed) {
  const MachineConfig m = defaultMachine();
  const double r = 10.0, F = 600.0, v = F / 60.0;
  const AxisValues s = xyz(r, 0, 0);
  const Trace t = run(m, {arc(s, s, 0, 1, 0.0, 0.0, false, F)});
  ASSERT_GT(t.ticks(), 6000u);  // 62.8 mm at 10 mm/s
  uint64_t cruise = 0;
  for (uint64_t k = 0; k < t.ticks(); ++k) {
    const AxisValues& p = t.points[k];
    ASSERT_NEAR(std::hypot(p[0], p[1]), r, 1e-9) << k;
    if (k > 0 && t.infos[k].velocity == v && t.infos[k - 1].velocity == v) {
      // Path speed from the angle between consecutive setpoints.
      const double a0 = std::atan2(t.points[k - 1][1], t.points[k - 1][0]);
      const double a1 = std::atan2(p[1], p[0]);
      double d = a1 - a0;
      if (d < 0) d += 2.0 * std::numbers::pi;
      ASSERT_NEAR(d * r / 0.001, v, 1e-9 * v) << k;
      ++cruise;
    }
  }
  EXPECT_GT(cruise, 6000u);
  EXPECT_EQ(t.points.back(), s);
}

TEST(Planner, CollinearMicroSegmentsReachProgrammedFeed) {
  // 2000 x 10 um along a fixed diagonal at F3000 (50 mm/s = 5 segments per tick).
  const MachineConfig m = defaultMachine();
  std::vector<MotionPrimitive> prog;
  const AxisValues dir = xyz(1.0 / std::sqrt(5.0), 2.0 / std::sqrt(5.0), 0.0);
  AxisValues p{};
  for (int i = 1; i <= 2000; ++i) {
    AxisValues q = xyz(dir[0] * 0.01 * i, dir[1] * 0.01 * i, 0.0);
    prog.push_back(line(p, q, 3000.0));
    p = q;
  }
  const Trace t = run(m, prog);
  double top = 0.0;
  uint32_t most = 0;
  uint64_t at_feed = 0;
  for (const auto& info : t.infos) {
    top = std::max(top, info.velocity);
    most = std::max(most, info.segments_finished);
    if (std::abs(info.velocity - 50.0) < 1e-9) ++at_feed;
  }
  EXPECT_NEAR(top, 50.0, 1e-9);
  EXPECT_GE(most, 5u);
  EXPECT_GT(at_feed, 300u);  // 20 mm at 50 mm/s = 400 ms, minus the ramps
  EXPECT_EQ(t.points.back(), p);
}

// 10 um chains whose neighbouring segments differ a little in their limits: along a gentle
// wave (the direction, and with it each line's limits, changes by 1e-9 at every vertex), and
// with F alternating between 5000 and 5100 every segment (a CAM feed optimiser's output).
// Such segments join runs (taking the lower limits), so the path runs at its feed: split at
// every change, the runs were too short to accelerate in (the wave crawled at 57 mm/s, the
// alternating feeds at 15 mm/s). A feed hold stops them like a plain line.
std::vector<MotionPrimitive> microChain(bool alternating_feed) {
  std::vector<MotionPrimitive> prog;
  AxisValues p{};
  for (int i = 1; i <= 20000; ++i) {
    const AxisValues q = xyz(0.01 * i, 0.0001 * std::sin(0.01 * i), 0);
    prog.push_back(line(p, q, alternating_feed ? (i % 2 == 1 ? 5000.0 : 5100.0) : 6000.0));
    p = q;
  }
  return prog;
}

TEST(Planner, MicroSegmentsOfSlightlyDifferentLimitsRunAtFeed) {
  const MachineConfig m = defaultMachine();
  for (const bool alternating : {false, true}) {
    const std::vector<MotionPrimitive> prog = microChain(alternating);
    const double feed = alternating ? 5000.0 / 60.0 : 100.0;
    const Trace t = run(m, prog, 1024, 400'000);
    expectWithinLimits(m, t);
    EXPECT_EQ(t.points.back(), prog.back().to);
    uint64_t at_feed = 0;
    for (uint64_t k = 300; k < 2000; ++k)
      if (std::abs(t.infos[k].velocity - feed) < 1e-9) ++at_feed;
    EXPECT_EQ(at_feed, 1700u) << alternating;
    // Feed hold at 1 s: at rest within the time a plain line needs from that speed (its
    // S-curve brake, 0.09 s from 100 mm/s; with mixed runs a little more).
    auto hold = [](uint64_t k, MotionPlanner& planner) {
      if (k == 1000) planner.setFeedHold(true);
    };
    const Trace held = run(m, prog, 1024, 1400, false, hold);
    expectWithinLimits(m, held);
    uint64_t moving = 0;
    for (uint64_t k = 1000; k < held.ticks(); ++k)
      if (held.points[k] != held.points[k - 1]) ++moving;
    EXPECT_LE(moving, alternating ? 140u : 96u) << alternating;
  }
}

TEST(Planner, ChainWithoutKinksKeepsOnlyTheCurvatureStepsShareOfTheJerk) {
  // 100 mm of 0.05 mm chords on a circle of r 20000 at F6000 from rest to rest, on axes of
  // 5000 mm/s^3 (the ramps are jerk-limited: 2 sqrt(v/j) each). The kink rule would pass
  // each 2.5 urad vertex at 70 mm/s only, so every vertex is a chain vertex (its turn planned
  // as the chain's curvature), none a kink passed moving: the lines keep only the curvature
  // step's 5 % of the jerk (kKinkFreeJerkShare), not the 10 % a kink needs too. The polygon's
  // wiggle takes another 1.5 %.
  MachineConfig m = defaultMachine();
  for (int i = 0; i < 3; ++i) m.axes[i].max_jerk = 5000.0;
  const double r = 20000.0, chord = 0.05, v = 100.0;
  const int n = 2000;
  std::vector<MotionPrimitive> prog;
  AxisValues p = xyz(r, 0, 0);
  for (int i = 1; i <= n; ++i) {
    const double th = chord * i / r;
    const AxisValues q = xyz(r * std::cos(th), r * std::sin(th), 0);
    prog.push_back(line(p, q, 6000.0));
    p = q;
  }
  const Trace t = run(m, prog);
  expectWithinLimits(m, t);
  EXPECT_EQ(t.points.back(), prog.back().to);
  const double L = chord * n, A = 2000.0, J = 5000.0;
  const double seconds = static_cast<double>(t.ticks() - 1) * kDefaultT;
  // Within 2 % of the share (the limits are rounded down to a 2^(1/64) grid; the wiggle) and
  // two ticks; faster than 90 % of the jerk alone would allow.
  EXPECT_LE(seconds, restToRestTime(L, v, A, 0.98 * kKinkFreeJerkShare * J) + 2 * kDefaultT);
  EXPECT_LT(seconds, restToRestTime(L, v, A, kSmoothJerkShare * J) - 0.003);
}

TEST(Planner, TinyArcKeepsItsOwnSpeedCapBelowTheFloor) {
  // Arcs of 1 to 0.2 um radius (5 extra turns) on X and Y of 1 mm/s^2 and 10 mm/s^3: the
  // curvature caps the speed below 1 mm/min, the slowest speed anything is planned with. The
  // arc keeps its cap; lifted to the floor it reached 11.6x the jerk limit (review). Also with
  // the feed override turned every 50 ms, which must not lift it either.
  MachineConfig m = defaultMachine();
  m.corner_tolerance = 0.0;
  setAxisLimits(m, 0, 1.0, 10.0);
  setAxisLimits(m, 1, 1.0, 10.0);
  auto knob = [](uint64_t k, MotionPlanner& p) {
    if (k % 50 == 0) p.setFeedOverride(k % 100 ? 0.3 : 0.9);
  };
  for (const double r : {1.0e-3, 0.5e-3, 0.2e-3}) {
    const std::vector<MotionPrimitive> prog = {
        line(xyz(-0.01, 0, 0), xyz(0, 0, 0), 1000.0),
        arc(xyz(0, 0, 0), xyz(r, r, 0), 0, 1, 0.0, r, false, 1000.0, 5),
        line(xyz(r, r, 0), xyz(r, 0.01, 0), 1000.0)};
    for (const bool turned : {false, true}) {
      const Trace t = run(m, prog, 1024, 10'000'000, false, turned ? PlannerHook(knob) : PlannerHook());
      expectWithinLimits(m, t);
      EXPECT_EQ(t.points.back(), prog.back().to) << r;
    }
  }
}

TEST(Planner, TinyChainKeepsItsOwnSpeedCapBelowTheFloor) {
  // The same for a chain: a polygon of 2.9 nm chords around a circle of 0.3 um radius, F1e6, on
  // X of 8.65 mm/s^2 and 83.7 mm/s^3 (review fuzz, seed 174). The lines are planned as the
  // chain's curve, whose curvature caps the speed at 0.012 mm/s; lifted to the floor, with
  // the acceleration and jerk budgeted at the cap, it reached 1.07x X's jerk limit.
  MachineConfig m = defaultMachine();
  m.corner_tolerance = 0.0;
  setAxisLimits(m, 0, 8.654, 83.65);
  setAxisLimits(m, 1, 4994.0, 127416.0);
  setAxisLimits(m, 2, 706.0, 28.8);
  const double cx = 1.6075e-4, cy = 2.4888e-4, r = 2.9593e-4, from = -1.0201, step = 0.0096973;
  auto on = [&](int i) {
    return xyz(cx + r * std::cos(from + step * i), cy + r * std::sin(from + step * i), 0);
  };
  std::vector<MotionPrimitive> prog;
  for (int i = 0; i < 238; ++i) prog.push_back(line(on(i), on(i + 1), 1e6));
  const Trace t = run(m, prog, 1024, 10'000'000);
  expectWithinLimits(m, t);
  EXPECT_EQ(t.points.back(), prog.back().to);
}

TEST(Planner, DwellHoldsPositionAndExactStopIsSampled) {
  const MachineConfig m = defaultMachine();
  const AxisValues a = xyz(0, 0, 0), b = xyz(3.3, 1.1, 0), c = xyz(5.0, 1.1, 0.7);
  const Trace t = run(m, {line(a, b, 1200.0, /*exact_stop=*/true), dwell(b, 0.25),
                          line(b, c, 1200.0)});
  uint64_t at_b = 0;
  for (const AxisValues& p : t.points) at_b += p == b ? 1 : 0;
  // The dwell: 250 ticks standing exactly on b, plus the exact stop's in-position sample and
  // the stop sample.
  EXPECT_GE(at_b, 251u);
  EXPECT_LE(at_b, 253u);
  EXPECT_EQ(t.points.back(), c);
}

TEST(Planner, FeedPerRevolutionUsesSpindleSpeed) {
  const MachineConfig m = defaultMachine();
  MotionPlanner planner(m, 64);
  planner.setSpindleSpeed(1000.0);
  MotionPrimitive mv = line(xyz(0, 0, 0), xyz(100, 0, 0), 0.1);  // 0.1 mm/rev * 1000 rpm
  mv.feed_per_rev = true;
  AxisValues end;
  EXPECT_NEAR(topSpeed(planner, mv, end), 100.0 / 60.0, 1e-12);
}

TEST(Planner, NonLinearRapidMovesEachAxisOnItsOwn) {
  // X100 Y10 with equal limits: Y arrives first, X continues alone (a dog-leg), and the move
  // takes X's rest-to-rest time at the rapid speed (500 mm/s, 2000 mm/s^2, 50000 mm/s^3).
  const MachineConfig m = defaultMachine();
  MotionPrimitive g00 = rapid(xyz(0, 0, 0), xyz(100, 10, 0));
  g00.per_axis = true;
  const Trace t = run(m, {g00});
  const double v = 500.0, a = 2000.0, j = 50000.0;
  const double expected = 100.0 / v + v / a + a / j;  // v_max and a_max reached
  EXPECT_NEAR(static_cast<double>(t.ticks() - 1) * 0.001, expected, 0.0011);
  EXPECT_EQ(t.points.back(), xyz(100, 10, 0));
  bool dog_leg = false;
  for (const AxisValues& p : t.points) dog_leg |= p[1] == 10.0 && p[0] < 90.0;
  EXPECT_TRUE(dog_leg);
  const Worst w = check(m, t);
  EXPECT_LE(w.velocity, 1.0 + kTolerance);
  EXPECT_LE(w.acceleration, 1.0 + kTolerance);
  EXPECT_LE(w.jerk, 1.0 + kTolerance);
  // The linear rapid keeps Y in proportion.
  const Trace linear = run(m, {rapid(xyz(0, 0, 0), xyz(100, 10, 0))});
  for (const AxisValues& p : linear.points) EXPECT_NEAR(p[1], p[0] / 10.0, 1e-9);
}

TEST(Planner, LinearRapidsLeaveRoomForAKinkInTheirRun) {
  // Five linear rapids, each turned by 4e-5 rad from the one before: a kink, and limits close
  // enough to share one run, which passes the kinks at full acceleration. Each kink's velocity
  // step needs room in that acceleration (without: 1.0245x Z's limit; review).
  MachineConfig m = defaultMachine();
  for (int i = 0; i < 3; ++i) m.axes[i].max_jerk = 1e6;
  m.axes[2].max_acceleration = 400.0;
  std::vector<MotionPrimitive> prog;
  AxisValues p{};
  double th = 0.2;
  for (int i = 0; i < 5; ++i) {
    if (i > 0) th += 40e-6;
    const AxisValues q = xyz(p[0] + 10 * std::cos(th), p[1] + 5, p[2] + 10 * std::sin(th));
    prog.push_back(rapid(p, q));  // linear (per_axis false)
    p = q;
  }
  const Trace t = run(m, prog);
  expectWithinLimits(m, t);
  EXPECT_EQ(t.points.back(), p);
}

TEST(Planner, StaticOverridesScaleFeedAndRapid) {
  const MachineConfig m = defaultMachine();
  const auto top = [&](double feed_ovr, double rapid_ovr, const MotionPrimitive& mv) {
    MotionPlanner planner(m, 64);
    planner.setOverrides(feed_ovr, rapid_ovr);
    AxisValues end;
    const double v = topSpeed(planner, mv, end);
    EXPECT_EQ(end, mv.to);
    return v;
  };
  const MotionPrimitive g01 = line(xyz(0, 0, 0), xyz(100, 0, 0), 3000.0);
  EXPECT_NEAR(top(0.5, 1.0, g01), 25.0, 1e-9);
  EXPECT_NEAR(top(1.5, 1.0, g01), 75.0, 1e-9);
  EXPECT_NEAR(top(2.0, 1.0, line(xyz(0, 0, 0), xyz(900, 0, 0), 20000.0)), 500.0, 1e-9);  // axis limit
  const MotionPrimitive g00 = rapid(xyz(0, 0, 0), xyz(400, 0, 0));
  EXPECT_NEAR(top(1.0, 0.25, g00), 125.0, 1e-9);
  MotionPrimitive per_axis = g00;
  per_axis.per_axis = true;
  EXPECT_NEAR(top(1.0, 0.25, per_axis), 125.0, 1e-9);
  EXPECT_NEAR(top(0.5, 0.5, g00), 250.0, 1e-9);  // the feed override leaves rapids alone
  // G63 tapping mode (MotionPrimitive::fixed_override): the programmed F at any override.
  MotionPrimitive tap = line(xyz(0, 0, 0), xyz(0, 0, -100), 3000.0);
  tap.fixed_override = true;
  EXPECT_NEAR(top(0.5, 1.0, tap), 50.0, 1e-9);
  EXPECT_NEAR(top(2.0, 1.0, tap), 50.0, 1e-9);
}

}  // namespace
}  // namespace ncc::vm::motion
