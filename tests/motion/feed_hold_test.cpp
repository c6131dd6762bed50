// Feed hold (MotionPlanner::setFeedHold): the path brakes to rest on the programmed path,
// stands, and goes on when released; the program time grows by exactly the time held on a
// long line; rapids stop too; a hold before the start keeps the path at its start. The random
// suite holds random programs at random ticks (random_suite_test.cpp).
#include <cmath>

#include "gtest/gtest.h"
#include "motion_test_util.h"
#include "ncc/vm/motion/planner.h"

namespace ncc::vm::motion {
namespace {

using namespace motion_test;

constexpr double kT = 0.001;  // default IPO cycle

// Holds before tick `from`, releases before tick `to`.
PlannerHook holdBetween(uint64_t from, uint64_t to) {
  return [=](uint64_t k, MotionPlanner& planner) {
    if (k == from) planner.setFeedHold(true);
    if (k == to) planner.setFeedHold(false);
  };
}

// Ticks in [from, to) whose setpoint equals the previous one.
uint64_t standingTicks(const Trace& t, uint64_t from, uint64_t to) {
  uint64_t n = 0;
  for (uint64_t k = std::max<uint64_t>(from, 1); k < to && k < t.ticks(); ++k)
    if (t.points[k] == t.points[k - 1]) ++n;
  return n;
}

TEST(FeedHold, StopsOnThePathAndGoesOnWhenReleased) {
  // G01 X600 at F6000: held at 2 s, released at 3 s. The brake (about 0.09 s) ends long
  // before the release, so the path loses exactly the second held: it runs from rest after
  // the release as it ran into the stop, ramp for ramp.
  const MachineConfig m = defaultMachine();
  const std::vector<MotionPrimitive> prog = {line(xyz(0, 0, 0), xyz(600, 0, 0), 6000.0)};
  const Trace plain = run(m, prog);
  const Trace held = run(m, prog, 1024, 50'000'000, false, holdBetween(2000, 3000));
  expectWithinLimits(m, held);
  EXPECT_EQ(held.points.back(), xyz(600, 0, 0));
  // Standing still from the end of the brake to the release, on the line.
  EXPECT_GE(standingTicks(held, 2100, 3000), 890u);
  EXPECT_TRUE(held.infos[2500].idle);  // standing under the hold
  EXPECT_EQ(held.points[2500][1], 0.0);
  EXPECT_NEAR(held.points[2500][0], 200.0, 1.0);
  EXPECT_NEAR(static_cast<double>(held.ticks()) * kT,
              static_cast<double>(plain.ticks()) * kT + 1.0, 1.5 * kT);
}

TEST(FeedHold, StopsRapidsToo) {
  const MachineConfig m = defaultMachine();
  const std::vector<MotionPrimitive> prog = {rapid(xyz(0, 0, 0), xyz(2000, 0, 0))};
  const Trace held = run(m, prog, 1024, 50'000'000, false, holdBetween(1500, 2500));
  expectWithinLimits(m, held);
  EXPECT_GE(standingTicks(held, 1500, 2500), 700u);
  EXPECT_EQ(held.points.back(), xyz(2000, 0, 0));
}

TEST(FeedHold, StopsANonLinearRapidOnEveryAxis) {
  // A per-axis G00 to (2000, 300, 50), held at 1 s while X still cruises (Y and Z have
  // arrived), released at 2 s: X brakes to rest and stands, the run takes the held second
  // longer, and every axis ends exactly on its target. Held again during its braking after
  // the release and released, it still lands.
  const MachineConfig m = defaultMachine();
  MotionPrimitive g00 = rapid(xyz(0, 0, 0), xyz(2000, 300, 50));
  g00.per_axis = true;
  const Trace plain = run(m, {g00});
  const Trace held = run(m, {g00}, 1024, 50'000'000, false, holdBetween(1000, 2000));
  expectWithinLimits(m, held);
  EXPECT_EQ(held.points.back(), g00.to);
  EXPECT_GE(standingTicks(held, 1000, 2000), 700u);  // after a 0.29 s brake from 500 mm/s
  EXPECT_LT(held.points[1500][0], 2000.0);
  EXPECT_EQ(held.points[1500][1], 300.0);
  // Standing under the hold, it reports idle like a held line (it moved before, and will).
  EXPECT_TRUE(held.infos[1500].idle);
  EXPECT_FALSE(held.infos[900].idle);
  EXPECT_FALSE(held.infos[2200].idle);
  // Exactly one second more, like a line: the start from rest mirrors the brake.
  EXPECT_NEAR(static_cast<double>(held.ticks() - plain.ticks()) * kT, 1.0, 1.5 * kT);
  auto twice = [](uint64_t k, MotionPlanner& planner) {
    if (k == 300 || k == 1230) planner.setFeedHold(true);
    if (k == 1200 || k == 1260) planner.setFeedHold(false);
  };
  const Trace again = run(m, {g00}, 1024, 50'000'000, false, twice);
  expectWithinLimits(m, again);
  EXPECT_EQ(again.points.back(), g00.to);
}

// Found in review: a second request before the same tick kept the legs the first one had
// added to a non-linear G00, so the motion depended on their order (through the Controller, a
// release and a rapid turn in one prepare()).
TEST(FeedHold, NonLinearG00SameTickRequestsDoNotDependOnOrder) {
  const MachineConfig m = defaultMachine();
  MotionPrimitive g00 = rapid(xyz(0, 0, 0), xyz(2000, 0, 0));
  g00.per_axis = true;
  auto setup = [](MotionPlanner& p) { p.setOverrides(1.0, 0.3); };
  const Trace release_first = run(m, {g00}, 1024, 50'000'000, false, [](uint64_t k, MotionPlanner& p) {
    if (k == 500) p.setFeedHold(true);
    if (k == 1500) { p.setFeedHold(false); p.setRapidOverride(1.0); }  // the Controller's order
  }, setup);
  const Trace turn_first = run(m, {g00}, 1024, 50'000'000, false, [](uint64_t k, MotionPlanner& p) {
    if (k == 500) p.setFeedHold(true);
    if (k == 1500) { p.setRapidOverride(1.0); p.setFeedHold(false); }
  }, setup);
  EXPECT_EQ(release_first.points, turn_first.points);
  auto stopAt = [&](const PlannerHook& at1500) {
    const Trace t = run(m, {g00}, 1024, 50'000'000, false, [&](uint64_t k, MotionPlanner& p) {
      at1500(k, p);
      if (k == 3000) p.setFeedHold(false);
    });
    return t.points[2500][0];
  };
  const double hold = stopAt([](uint64_t k, MotionPlanner& p) { if (k == 1500) p.setFeedHold(true); });
  const double turn_hold = stopAt([](uint64_t k, MotionPlanner& p) {
    if (k == 1500) { p.setRapidOverride(0.1); p.setFeedHold(true); } });
  EXPECT_NEAR(turn_hold, hold, 1e-9);
}

TEST(FeedHold, PressedWhileAcceleratingStopsAtOnce) {
  // A G00 along X (rapid 500 mm/s) held 20 ms after it starts, in its jerk-up phase: the
  // ramp goes into its jerk-down phase on the next tick and the path brakes from there, at
  // rest within a millimetre. (The first version finished the ramp to 500 mm/s first and
  // stopped 147 mm on.)
  const MachineConfig m = defaultMachine();
  const std::vector<MotionPrimitive> prog = {rapid(xyz(0, 0, 0), xyz(2000, 0, 0))};
  const Trace held = run(m, prog, 1024, 50'000'000, false, holdBetween(20, 1000));
  expectWithinLimits(m, held);
  EXPECT_EQ(standingTicks(held, 200, 1000), 800u);
  EXPECT_LT(held.points[500][0], 1.0);
  EXPECT_EQ(held.points.back(), xyz(2000, 0, 0));
}

TEST(FeedHold, HeldBeforeTheStartStaysAtTheStart) {
  const MachineConfig m = defaultMachine();
  const std::vector<MotionPrimitive> prog = {line(xyz(0, 0, 0), xyz(50, 0, 0), 3000.0)};
  const Trace held = run(m, prog, 1024, 50'000'000, false, holdBetween(0, 500));
  for (uint64_t k = 0; k < 500; ++k) ASSERT_EQ(held.points[k], xyz(0, 0, 0)) << k;
  EXPECT_GT(held.points[700][0], 0.0);
  EXPECT_EQ(held.points.back(), xyz(50, 0, 0));
  EXPECT_EQ(held.ticks(), run(m, prog).ticks() + 500);
}

TEST(FeedHold, ReleasedWhileBrakingAndHeldAgain) {
  // Released 30 ms into the brake, held again 200 ms later, released for good: every limit
  // holds, the path stands twice and ends exactly.
  const MachineConfig m = defaultMachine();
  const std::vector<MotionPrimitive> prog = {line(xyz(0, 0, 0), xyz(400, 0, 0), 6000.0)};
  auto knob = [](uint64_t k, MotionPlanner& planner) {
    if (k == 1000 || k == 1230) planner.setFeedHold(true);
    if (k == 1030 || k == 1800) planner.setFeedHold(false);
  };
  const Trace t = run(m, prog, 1024, 50'000'000, false, knob);
  expectWithinLimits(m, t);
  EXPECT_GE(standingTicks(t, 1230, 1800), 400u);
  EXPECT_EQ(t.points.back(), xyz(400, 0, 0));
}

TEST(FeedHold, ThroughAChainOfShortSegments) {
  // A 10 um chain at F6000 along a gentle wave (100 mm/s where it is held): the brake runs
  // over hundreds of segments in one run (their limits differ by rounding only) and takes
  // 95 ms, like a line; the path then stands until the release. (Split into runs at every
  // rounding step, it ran at 58 mm/s and took 250 ms to stop.)
  const MachineConfig m = defaultMachine();
  std::vector<MotionPrimitive> prog;
  AxisValues p = xyz(0, 0, 0);
  for (int i = 1; i <= 20000; ++i) {
    const AxisValues q = xyz(0.01 * i, 0.0001 * std::sin(0.01 * i), 0);
    prog.push_back(line(p, q, 6000.0));
    p = q;
  }
  const Trace t = run(m, prog, 1024, 50'000'000, false, holdBetween(1000, 1400));
  expectWithinLimits(m, t);
  EXPECT_EQ(standingTicks(t, 1100, 1400), 300u);
  EXPECT_EQ(t.points.back(), p);
}

}  // namespace
}  // namespace ncc::vm::motion
