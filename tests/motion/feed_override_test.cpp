// The feed override turned during the run (MotionPlanner::setFeedOverride): analytic cases on
// a long line (the running motion is cut where it cruises, brakes or accelerates to the new
// speed, and the program time is the closed form of that), turns during a ramp, what the
// knob does not touch (G63, rapids), clamping. The random suite turns it on random programs
// (random_suite_test.cpp).
#include <cmath>
#include <limits>

#include "gtest/gtest.h"
#include "motion_test_util.h"
#include "ncc/vm/motion/planner.h"
#include "ncc/vm/motion/scurve.h"

namespace ncc::vm::motion {
namespace {

using namespace motion_test;


// Turns the knob to `value` before tick `at`.
PlannerHook turnAt(uint64_t at, double value) {
  return [=](uint64_t k, MotionPlanner& planner) {
    if (k == at) planner.setFeedOverride(value);
  };
}

TEST(FeedOverride, TurnedDownWhileCruisingBrakesToTheNewSpeed) {
  const MachineConfig m = defaultMachine();
  const double L = 600.0, v = 100.0, half = 50.0;  // F6000, then 50 %
  const Trace t = run(m, {line(xyz(0, 0, 0), xyz(L, 0, 0), 6000.0)}, 1024, 50'000'000, false,
                      turnAt(2000, 0.5));
  EXPECT_EQ(t.points.back(), xyz(L, 0, 0));
  expectWithinLimits(m, t);
  EXPECT_NEAR(speedAlongX(t, 1990), v, 1e-9);
  // Cut at t = 2 s (the next tick), then a brake 100 -> 50 mm/s at a = 0 on both ends.
  const VelocityRamp up = VelocityRamp::make(0.0, v, kDefaultA, kDefaultLineJ);
  const VelocityRamp brake = VelocityRamp::make(half, v, kDefaultA, kDefaultLineJ);
  const VelocityRamp stop = VelocityRamp::make(0.0, half, kDefaultA, kDefaultLineJ);
  const uint64_t settled = 2000 + static_cast<uint64_t>(std::ceil(brake.duration / kDefaultT)) + 1;
  for (uint64_t k = settled; k < settled + 100; ++k) EXPECT_NEAR(speedAlongX(t, k), half, 1e-9) << k;
  for (uint64_t k = 2001; k < settled; ++k) {
    EXPECT_LT(speedAlongX(t, k), v);
    EXPECT_GT(speedAlongX(t, k), half);
  }
  const double cut_s = up.distance + v * (2.0 - up.duration);
  const double expected = 2.0 + brake.duration +
                          (L - cut_s - brake.distance - stop.distance) / half + stop.duration;
  // The end is sampled on the first tick at or after it, plus the stop sample.
  EXPECT_NEAR(static_cast<double>(t.ticks()) * kDefaultT, expected + kDefaultT, 1.5 * kDefaultT);
}

TEST(FeedOverride, TurnedUpAcceleratesToTheNewSpeed) {
  const MachineConfig m = defaultMachine();
  const Trace t = run(m, {line(xyz(0, 0, 0), xyz(600, 0, 0), 6000.0)}, 1024, 50'000'000, false,
                      turnAt(2000, 1.0),
                      [](MotionPlanner& planner) { planner.setOverrides(0.5, 1.0, 1.0); });
  EXPECT_EQ(t.points.back(), xyz(600, 0, 0));
  expectWithinLimits(m, t);
  EXPECT_NEAR(speedAlongX(t, 1990), 50.0, 1e-9);
  const VelocityRamp up = VelocityRamp::make(50.0, 100.0, kDefaultA, kDefaultLineJ);
  const uint64_t settled = 2000 + static_cast<uint64_t>(std::ceil(up.duration / kDefaultT)) + 1;
  for (uint64_t k = settled; k < settled + 100; ++k) EXPECT_NEAR(speedAlongX(t, k), 100.0, 1e-9) << k;
}

TEST(FeedOverride, TurnedDownDuringARampRunsOnToTheNewLimit) {
  // At 30 ms the start ramp to 100 mm/s is in its jerk-up phase (a/j = 44 ms): turned to 50 %,
  // the ramp becomes the same ramp to 50 mm/s (its jerk-up phase ends on time for that, then
  // its jerk-down): the path reaches 50 mm/s in one ramp, exactly as if the override had been
  // 50 % from the start, and never runs up to the old speed first. (Ending the ramp at once,
  // at j * 0.03^2 = 40.5 mm/s, and accelerating again made the turn cost time.)
  const MachineConfig m = defaultMachine();
  const std::vector<MotionPrimitive> prog = {line(xyz(0, 0, 0), xyz(300, 0, 0), 6000.0)};
  const Trace t = run(m, prog, 1024, 50'000'000, false, turnAt(30, 0.5));
  const Trace from_start = run(m, prog, 1024, 50'000'000, false, turnAt(0, 0.5));
  EXPECT_EQ(t.points.back(), xyz(300, 0, 0));
  expectWithinLimits(m, t);
  double top = 0.0;
  for (uint64_t k = 1; k < 400; ++k) top = std::max(top, speedAlongX(t, k));
  EXPECT_LE(top, 50.0 + 1e-9);
  // One ramp: the acceleration never changes sign before 50 mm/s is reached.
  const VelocityRamp ramp = VelocityRamp::make(0.0, 50.0, kDefaultA, kDefaultLineJ);
  const uint64_t reached = static_cast<uint64_t>(std::ceil(ramp.duration / kDefaultT));
  for (uint64_t k = 1; k <= reached; ++k) EXPECT_GE(t.infos[k].acceleration, 0.0) << k;
  for (uint64_t k = reached + 1; k < 500; ++k) EXPECT_NEAR(speedAlongX(t, k), 50.0, 1e-9) << k;
  EXPECT_EQ(t.ticks(), from_start.ticks());
}

TEST(FeedOverride, TurnedDownNearAStopStillLandsOnIt) {
  // Turned down 20 ms before the braking for the exact stop at X50 would start: the stop is
  // planned with the new limits from where the motion is, and lands exactly.
  const MachineConfig m = defaultMachine();
  MotionPrimitive first = line(xyz(0, 0, 0), xyz(50, 0, 0), 6000.0);
  first.exact_stop = true;
  const std::vector<MotionPrimitive> prog = {first, line(xyz(50, 0, 0), xyz(50, 40, 0), 6000.0)};
  const Trace plain = run(m, prog);
  const VelocityRamp up = VelocityRamp::make(0.0, 100.0, kDefaultA, kDefaultLineJ);
  const uint64_t brake_starts =
      static_cast<uint64_t>((up.duration + (50.0 - 2.0 * up.distance) / 100.0) / kDefaultT);
  for (uint64_t before : {20u, 2u}) {
    const Trace t = run(m, prog, 1024, 50'000'000, false, turnAt(brake_starts - before, 0.3));
    expectWithinLimits(m, t);
    EXPECT_NE(std::find(t.points.begin(), t.points.end(), xyz(50, 0, 0)), t.points.end());
    EXPECT_EQ(t.points.back(), xyz(50, 40, 0));
    EXPECT_GT(t.ticks(), plain.ticks());  // the second line runs at 30 %
  }
}

TEST(FeedOverride, LeavesG63AndRapidsAlone) {
  const MachineConfig m = defaultMachine();
  MotionPrimitive tap = line(xyz(0, 0, 0), xyz(0, 0, -300), 6000.0);
  tap.fixed_override = true;  // G63: F / S is the tap's pitch
  const Trace g63 = run(m, {tap}, 1024, 50'000'000, false, turnAt(1000, 0.5));
  EXPECT_NEAR((g63.points[1500][2] - g63.points[1501][2]) / kDefaultT, 100.0, 1e-9);
  const Trace g00 = run(m, {rapid(xyz(0, 0, 0), xyz(2000, 0, 0))}, 1024, 50'000'000, false,
                        turnAt(1000, 0.5));
  const Trace g00_plain = run(m, {rapid(xyz(0, 0, 0), xyz(2000, 0, 0))});
  EXPECT_EQ(fnv1a(g00, 3), fnv1a(g00_plain, 3));
}

TEST(FeedOverride, LeavesAG63TapAloneAfterAMoveItScales) {
  // Approach at the tapping feed, then tap in the same direction (G63): the two are
  // collinear with the same limits, but the knob scales only the approach, so they must not
  // share a run. (They did in the first version: the tap ran at half speed.)
  const MachineConfig m = defaultMachine();
  MotionPrimitive approach = line(xyz(0, 0, 10), xyz(0, 0, 2), 600.0);
  MotionPrimitive tap = line(xyz(0, 0, 2), xyz(0, 0, -20), 600.0);
  tap.fixed_override = true;
  const Trace t = run(m, {approach, tap}, 1024, 50'000'000, false, turnAt(0, 0.5));
  uint64_t in_tap = 0;
  for (uint64_t k = 1; k < t.ticks(); ++k) {
    if (t.points[k][2] < -5.0 && t.points[k][2] > -15.0) {
      EXPECT_NEAR((t.points[k - 1][2] - t.points[k][2]) / kDefaultT, 10.0, 1e-9) << k;
      ++in_tap;
    }
    if (t.points[k][2] > 4.0 && t.points[k][2] < 8.0) {
      EXPECT_NEAR((t.points[k - 1][2] - t.points[k][2]) / kDefaultT, 5.0, 1e-9) << k;
    }
  }
  EXPECT_GT(in_tap, 900u);
}

TEST(FeedOverride, ScaledMovesOfDifferentFShareARun) {
  // A 10 um chain with F alternating 60000 / 60001: the axes cap both, so the segments share
  // one run and the chain accelerates like one line, to about 149 mm/s over these 40 mm (runs
  // split on F made every segment its own run, at about 15 mm/s).
  const MachineConfig m = defaultMachine();
  std::vector<MotionPrimitive> prog;
  for (int i = 0; i < 4000; ++i)
    prog.push_back(line(xyz(0.01 * i, 0, 0), xyz(0.01 * (i + 1), 0, 0), i % 2 == 0 ? 60000.0 : 60001.0));
  const Trace t = run(m, prog);
  double top = 0.0;
  for (const auto& info : t.infos) top = std::max(top, info.velocity);
  EXPECT_GT(top, 100.0);
}

TEST(FeedOverride, ClampedToTheRangeItWasPlannedFor) {
  const MachineConfig m = defaultMachine();
  MotionPlanner planner(m, 64);
  planner.setOverrides(1.0, 1.0, 1.2);
  planner.setFeedOverride(5.0);
  EXPECT_DOUBLE_EQ(planner.feedOverride(), 1.2);
  planner.setFeedOverride(0.0);  // not a feed hold: the lowest override
  EXPECT_DOUBLE_EQ(planner.feedOverride(), 0.001);
  planner.setFeedOverride(std::numeric_limits<double>::quiet_NaN());
  EXPECT_DOUBLE_EQ(planner.feedOverride(), 0.001);
  // Without a maximum the knob cannot go above the start value.
  MotionPlanner fixed(m, 64);
  fixed.setOverrides(0.8, 1.0);
  fixed.setFeedOverride(1.0);
  EXPECT_DOUBLE_EQ(fixed.feedOverride(), 0.8);
}

TEST(FeedOverride, SameTurnsSameSetpoints) {
  const MachineConfig m = defaultMachine();
  const std::vector<MotionPrimitive> prog = {
      line(xyz(0, 0, 0), xyz(80, 0, 0), 6000.0), arc(xyz(80, 0, 0), xyz(80, 20, 0), 0, 1, 80, 10, false, 3000.0),
      line(xyz(80, 20, 0), xyz(0, 20, 0), 6000.0)};
  auto knob = [](uint64_t k, MotionPlanner& planner) {
    if (k % 150 == 0) planner.setFeedOverride(0.2 + 0.1 * static_cast<double>((k / 150) % 9));
  };
  const Trace a = run(m, prog, 1024, 50'000'000, false, knob);
  const Trace b = run(m, prog, 1024, 50'000'000, true, knob);
  EXPECT_EQ(fnv1a(a, 3), fnv1a(b, 3));
  EXPECT_NE(fnv1a(a, 3), fnv1a(run(m, prog), 3));
  expectWithinLimits(m, a);
  EXPECT_EQ(a.points.back(), xyz(0, 20, 0));
}

}  // namespace
}  // namespace ncc::vm::motion
