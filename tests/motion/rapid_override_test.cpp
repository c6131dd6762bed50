// The rapid override turned during the run (MotionPlanner::setRapidOverride): a linear G00 is
// cut where it cruises and brakes to the new speed (the program time is the closed form of
// that), a turn up from a lower start reaches the full rapid speed, feed moves are left alone,
// a non-linear G00 under way re-plans its axis profiles at once.
// The random suite turns it on random programs (random_suite_test.cpp).
#include <cmath>
#include <limits>

#include "gtest/gtest.h"
#include "motion_test_util.h"
#include "ncc/vm/motion/axis_rapid.h"
#include "ncc/vm/motion/planner.h"
#include "ncc/vm/motion/scurve.h"

namespace ncc::vm::motion {
namespace {

using namespace motion_test;

constexpr double kRapid = 500.0;  // default rapid speed, mm/s

// Turns the rapid override to `value` before tick `at`.
PlannerHook rapidAt(uint64_t at, double value) {
  return [=](uint64_t k, MotionPlanner& planner) {
    if (k == at) planner.setRapidOverride(value);
  };
}

TEST(RapidOverride, TurnedDownWhileCruisingBrakesToTheNewSpeed) {
  const MachineConfig m = defaultMachine();
  const double L = 2000.0, slow = 0.25 * kRapid;
  const Trace t = run(m, {rapid(xyz(0, 0, 0), xyz(L, 0, 0))}, 1024, 50'000'000, false,
                      rapidAt(1000, 0.25));
  EXPECT_EQ(t.points.back(), xyz(L, 0, 0));
  expectWithinLimits(m, t);
  EXPECT_NEAR(speedAlongX(t, 990), kRapid, 1e-9);
  // Cut at t = 1 s (the next tick), then a brake 500 -> 125 mm/s at a = 0 on both ends.
  const VelocityRamp up = VelocityRamp::make(0.0, kRapid, kDefaultA, kDefaultMovingJ);
  const VelocityRamp brake = VelocityRamp::make(slow, kRapid, kDefaultA, kDefaultMovingJ);
  const VelocityRamp stop = VelocityRamp::make(0.0, slow, kDefaultA, kDefaultMovingJ);
  const uint64_t settled = 1000 + static_cast<uint64_t>(std::ceil(brake.duration / kDefaultT)) + 1;
  for (uint64_t k = settled; k < settled + 100; ++k) EXPECT_NEAR(speedAlongX(t, k), slow, 1e-9) << k;
  const double cut_s = up.distance + kRapid * (1.0 - up.duration);
  const double expected = 1.0 + brake.duration +
                          (L - cut_s - brake.distance - stop.distance) / slow + stop.duration;
  EXPECT_NEAR(static_cast<double>(t.ticks()) * kDefaultT, expected + kDefaultT, 1.5 * kDefaultT);
}

TEST(RapidOverride, TurnedUpFromALowerStartReachesTheFullRapid) {
  // Planned at 100 % whatever the start: from 25 % the knob may go to 100 % at once.
  const MachineConfig m = defaultMachine();
  const Trace t = run(m, {rapid(xyz(0, 0, 0), xyz(2000, 0, 0))}, 1024, 50'000'000, false,
                      rapidAt(1500, 1.0),
                      [](MotionPlanner& planner) { planner.setOverrides(1.0, 0.25); });
  EXPECT_EQ(t.points.back(), xyz(2000, 0, 0));
  expectWithinLimits(m, t);
  EXPECT_NEAR(speedAlongX(t, 1490), 0.25 * kRapid, 1e-9);
  const VelocityRamp up = VelocityRamp::make(0.25 * kRapid, kRapid, kDefaultA, kDefaultMovingJ);
  const uint64_t settled = 1500 + static_cast<uint64_t>(std::ceil(up.duration / kDefaultT)) + 1;
  for (uint64_t k = settled; k < settled + 100; ++k) EXPECT_NEAR(speedAlongX(t, k), kRapid, 1e-9) << k;
}

TEST(RapidOverride, LeavesFeedMovesAlone) {
  const MachineConfig m = defaultMachine();
  const std::vector<MotionPrimitive> prog = {line(xyz(0, 0, 0), xyz(300, 0, 0), 6000.0)};
  EXPECT_EQ(run(m, prog, 1024, 50'000'000, false, rapidAt(500, 0.1)).points, run(m, prog).points);
}

TEST(RapidOverride, NonLinearG00TakesItAtOnce) {
  // Two per-axis G00 of 300 mm. Turned to 50 % at 0.2 s, while the first accelerates: its
  // ramp goes into its jerk-down phase at once, brakes to 250 mm/s, cruises there and stops
  // on X300; the second runs as a 250 mm/s rapid.
  const MachineConfig m = defaultMachine();
  MotionPrimitive first = rapid(xyz(0, 0, 0), xyz(300, 0, 0));
  MotionPrimitive second = rapid(xyz(300, 0, 0), xyz(600, 0, 0));
  first.per_axis = second.per_axis = true;
  const Trace plain = run(m, {first, second});
  const Trace turned = run(m, {first, second}, 1024, 50'000'000, false, rapidAt(200, 0.5));
  EXPECT_EQ(turned.points.back(), xyz(600, 0, 0));
  expectWithinLimits(m, turned);
  // The first: up to 0.2 s unchanged; the ramp ends at a = 0 from there (v = 2000 * 0.2
  // minus the jerk phase's share), brakes to 250 and cruises.
  for (uint64_t k = 1; k <= 200; ++k) EXPECT_EQ(turned.points[k], plain.points[k]) << k;
  const SCurveProfile whole = planProfile(300.0, 0.0, 0.0, kRapid, kDefaultA, kDefaultLineJ);
  SCurveProfile cut = whole;
  ASSERT_TRUE(cutProfile(cut, 0.2, 0.5 * kRapid));
  const VelocityRamp brake = VelocityRamp::make(0.5 * kRapid, cut.v_end, kDefaultA, kDefaultLineJ);
  const SCurveProfile rest =
      planProfile(300.0 - cut.length - brake.distance, 0.5 * kRapid, 0.0, 0.5 * kRapid, kDefaultA, kDefaultLineJ);
  const double arrival = cut.duration + brake.duration + rest.duration;
  const auto arrived = [](const Trace& t) {
    for (uint64_t k = 0; k < t.ticks(); ++k)
      if (t.points[k][0] == 300.0) return k;
    return t.ticks();
  };
  EXPECT_NEAR(static_cast<double>(arrived(turned)) * kDefaultT, arrival, 1.5 * kDefaultT);
  const uint64_t cruising = static_cast<uint64_t>((cut.duration + brake.duration) / kDefaultT) + 5;
  for (uint64_t k = cruising; k < cruising + 50; ++k)
    EXPECT_NEAR(speedAlongX(turned, k), 0.5 * kRapid, 1e-9) << k;
  // The second: the half-speed profile (both runs wait the same in-position time).
  AxisLimits full = AxisLimits::from(m);
  AxisLimits half = full;
  for (int i = 0; i < half.count; ++i) half.rapid_velocity[i] *= 0.5;
  const double slow_second = AxisRapid::make(second.from, second.to, half).duration();
  const double full_second = AxisRapid::make(second.from, second.to, full).duration();
  EXPECT_NEAR(static_cast<double>((turned.ticks() - arrived(turned)) - (plain.ticks() - arrived(plain))) * kDefaultT,
              slow_second - full_second, 2.0 * kDefaultT);
}

TEST(RapidOverride, ClampedToAtMost100Percent) {
  MotionPlanner planner(defaultMachine(), 64);
  planner.setRapidOverride(1.5);
  EXPECT_EQ(planner.rapidOverride(), 1.0);
  planner.setRapidOverride(0.0);
  EXPECT_GT(planner.rapidOverride(), 0.0);
  planner.setRapidOverride(std::numeric_limits<double>::quiet_NaN());
  EXPECT_GT(planner.rapidOverride(), 0.0);
  planner.setRapidOverride(0.3);
  EXPECT_EQ(planner.rapidOverride(), 0.3);
}

}  // namespace
}  // namespace ncc::vm::motion
