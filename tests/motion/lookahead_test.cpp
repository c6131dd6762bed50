// Runs of segments with slightly different limits (LookAhead::push): a join that lowers a
// run's limits must never lower what the motion under way is committed to. The two cases are
// from the review of a first version, which lowered runs already planned for.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "gtest/gtest.h"
#include "motion_test_util.h"

namespace ncc::vm::motion {
namespace {

using namespace motion_test;

TEST(LookAhead, JoinedSlowSegmentIsNotEnteredAboveItsSpeed) {
  // A fast line, 10 um at F3000 (a run entered at 50 mm/s), then 10 um at F1500, too short to
  // be worth a run of its own, and 5 mm more at F1500. The F1500 part must never run above
  // 25 mm/s: a run that joins it takes its speed limit and, with it, a lower junction limit.
  // (Keeping the F3000 run's junction limit, the first version entered it at 50 mm/s.)
  const MachineConfig m = defaultMachine();
  std::vector<MotionPrimitive> prog;
  AxisValues p = xyz(0, 0, 0);
  auto go = [&](double x, double f) {
    const AxisValues q = xyz(x, 0, 0);
    prog.push_back(line(p, q, f));
    p = q;
  };
  go(20.0, 6000.0);
  go(20.01, 3000.0);
  go(20.02, 1500.0);
  for (int i = 1; i <= 500; ++i) go(20.02 + 0.01 * i, 1500.0);
  for (const bool ahead : {false, true}) {
    const Trace t = run(m, prog, 1024, 1'000'000, ahead);
    expectWithinLimits(m, t);
    EXPECT_EQ(t.points.back(), prog.back().to);
    double peak = 0.0;
    for (std::size_t k = 0; k < t.ticks(); ++k)
      if (t.points[k][0] >= 20.02) peak = std::max(peak, t.infos[k].velocity);
    EXPECT_LE(peak, 25.0 * (1.0 + 1e-9)) << ahead;
    EXPECT_GT(peak, 24.9) << ahead;
  }
}

TEST(LookAhead, PreparationThatFallsBehindStillStopsWithinTheQueue) {
  // Arcs of one circle (0.23 mm each) at F2925, F2925, F2925, F9608, repeated, with an
  // 18-segment window. The caller stops pushing for 2 s from tick `stall` on (a preparation
  // that fell behind): the path must brake to rest within what is queued, within every limit.
  // Joins that lowered the limits of runs already planned for made that stop impossible
  // (4.4x the acceleration limit).
  MachineConfig m = defaultMachine();
  const double r = 16.0966, seg = 0.2348;
  const double feeds[4] = {2925, 2925, 2925, 9608};
  std::vector<MotionPrimitive> prog;
  double th = -std::numbers::pi / 2;
  AxisValues p = xyz(0, 0, 0);
  for (int i = 0; i < 60; ++i) {
    th += seg / r;
    const AxisValues q = xyz(r * std::cos(th), r + r * std::sin(th), 0);
    prog.push_back(arc(p, q, 0, 1, 0.0, r, false, feeds[i % 4]));
    p = q;
  }
  Worst worst;
  for (uint64_t stall = 1; stall < 700; stall += 3) {
    const Trace t = run(m, prog, 18, 100'000, false, {}, {},
                        [stall](uint64_t k) { return k < stall || k >= stall + 2000; });
    ASSERT_EQ(t.points.back(), prog.back().to) << stall;
    const Worst w = check(m, t);
    worst.velocity = std::max(worst.velocity, w.velocity);
    worst.acceleration = std::max(worst.acceleration, w.acceleration);
    worst.jerk = std::max(worst.jerk, w.jerk);
  }
  EXPECT_LE(worst.velocity, 1.0 + kTolerance);
  EXPECT_LE(worst.acceleration, 1.0 + kTolerance);
  EXPECT_LE(worst.jerk, 1.0 + kTolerance);
}

// A feed step up: a short slow segment, then a fast stretch in fine segments, fifty times
// along X. A faster segment may join the slow run as a short one (tooShortToSplit), so that
// bows whose limits alternate make runs (BowChains.AnEllipseInFineChordsRunsAsFastAsInCoarseOnes),
// but only while the faster tail is no longer than the rest of the run: with no bound the fast
// stretch ran at the slow speed for as long as the short-run rule allowed, 4656 ticks at
// 100 % (4315 before the rule) and 17,813 at a 10 % feed override (8363). Review 9.
TEST(LookAhead, AFeedStepUpDoesNotDragTheFastStretch) {
  const MachineConfig m = defaultMachine();
  std::vector<MotionPrimitive> prog;
  double x = 0.0;
  for (int step = 0; step < 50; ++step) {
    prog.push_back(line(xyz(x, 0, 0), xyz(x + 0.05, 0, 0), 3000.0));
    x += 0.05;
    for (int k = 0; k < 100; ++k, x += 0.05)
      prog.push_back(line(xyz(x, 0, 0), xyz(x + 0.05, 0, 0), 30000.0));
  }
  for (const double override_share : {1.0, 0.1}) {
    const Trace t = run(m, prog, 4096, 50'000'000, false, {}, [&](MotionPlanner& planner) {
      planner.setOverrides(override_share, 1.0, 1.0);
    });
    expectWithinLimits(m, t);
    EXPECT_EQ(t.points.back(), prog.back().to);
    EXPECT_LT(t.ticks(), override_share == 1.0 ? 4400u : 9000u) << override_share;
  }
}

// No run limit below the machine's weakest axis: WindowReach::lengthFor takes those.
constexpr double kAxisLimits = std::numeric_limits<double>::infinity();

// Pushes 0.1 mm lines along X at `feed` from `x` while the planner wants more; returns the
// path pushed (mm) and moves `x` on.
double readAhead(MotionPlanner& planner, double& x, double feed) {
  const double start = x;
  while (planner.canAccept()) {
    EXPECT_TRUE(planner.push(line(xyz(x, 0, 0), xyz(x + 0.1, 0, 0), feed)));
    x += 0.1;
  }
  return x - start;
}

// Pushes 2 mm moves at `feed` zigzagging at right angles while the planner wants more (each
// corner a stop, with corner_tolerance 0); returns the path pushed (mm).
double readZigzag(MotionPlanner& planner, double feed) {
  AxisValues p{};
  double pushed = 0.0;
  for (int i = 0; planner.canAccept(); ++i) {
    const AxisValues q = xyz(p[0] + (i % 2 == 0 ? 2.0 : 0.0), p[1] + (i % 2 == 0 ? 0.0 : 2.0), 0);
    EXPECT_TRUE(planner.push(line(p, q, feed)));
    p = q;
    pushed += 2.0;
  }
  return pushed;
}

// The look-ahead reads as far as the queued moves need: twice the braking reserve of the
// fastest of them plus four cycles of travel (planner.md, "Window by braking distance"), here
// past the stops at the zigzag's corners, counted from where the path is. Before, it read
// for the rapid speed of every axis at once, whatever was queued: 0.3 m (4.5 ms of planning
// before the first tick of tick_bench's program, 1024 segments of 2.4 KB).
TEST(LookAhead, ReadsAheadTheBrakingDistanceOfWhatIsQueued) {
  MachineConfig m = defaultMachine();
  m.corner_tolerance = 0.0;
  const WindowReach reach = WindowReach::of(AxisLimits::from(m));
  for (const double feed : {6000.0, 30000.0}) {
    const double at = reach.lengthFor(feed / 60.0, kAxisLimits, kAxisLimits);  // 10.7, 150 mm
    MotionPlanner planner(m, 1 << 14);
    const double read = readZigzag(planner, feed);
    EXPECT_GE(read, at) << feed;
    EXPECT_LE(read, at + 3 * 2.0) << feed;  // the move held back, the last one, the rounding
  }
}

// A run that may start before the next preparation is never the last one queued: a segment
// that lowers its limits could not join it once it runs (joinsLast), as it would with the
// whole program known, and would make a run of its own (review 10). A feed step down, and a
// lower F above the axis cap (only the limit the override scales is lower): each runs as it
// does with the whole program queued (with a window that stopped at the reach: 958 ticks
// against 950, and 1440 against 1420).
TEST(LookAhead, ASegmentThatLowersARunJoinsItBeforeItStarts) {
  const MachineConfig m = defaultMachine();
  const std::vector<std::vector<MotionPrimitive>> programs = {
      {line(xyz(0, 0, 0), xyz(10, 0, 0), 3000.0), line(xyz(10, 0, 0), xyz(10, 30, 0), 3000.0),
       line(xyz(10, 30, 0), xyz(10, 30.2, 0), 2990.0),
       line(xyz(10, 30.2, 0), xyz(10, 30.4, 0), 2980.0),
       line(xyz(10, 30.4, 0), xyz(10, 30.6, 0), 2970.0)},
      {line(xyz(0, 0, 0), xyz(0, 100, 0), 10000.0), line(xyz(0, 100, 0), xyz(0, -100, 0), 40000.0),
       line(xyz(0, -100, 0), xyz(0, -100.033, 0), 36000.0),
       line(xyz(0, -100.033, 0), xyz(0, -100.066, 0), 35000.0)},
  };
  for (const std::vector<MotionPrimitive>& prog : programs) {
    const Trace windowed = run(m, prog);
    const Trace whole = runWholeQueued(m, prog);
    ASSERT_EQ(windowed.ticks(), whole.ticks());
    for (uint64_t k = 0; k < whole.ticks(); ++k)
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(windowed.points[k][i], whole.points[k][i], 1e-12);
  }
}

// A run that ends at rest cuts the window: what follows it needs only its own reach, however
// fast the moves before it were, and only once the path comes near it: the reach counts from
// where the path is, so the moves after a stop are queued at the path's pace, not all at once
// when the stop is queued. (RandomSuite.TheWindowReadsAsFarAsThePlanNeeds checks that they are
// there in time.)
TEST(LookAhead, AStopCutsTheReach) {
  const MachineConfig m = defaultMachine();
  const WindowReach reach = WindowReach::of(AxisLimits::from(m));
  MotionPlanner planner(m, 1 << 14);
  // F6000 lines, a dwell, F3000 lines: the path is at the first line's start, the dwell 20 mm
  // ahead, beyond the reach of either feed (10.7 and 3.8 mm).
  double x = 0.0;
  for (int i = 0; i < 200; ++i, x += 0.1)
    ASSERT_TRUE(planner.push(line(xyz(x, 0, 0), xyz(x + 0.1, 0, 0), 6000.0)));
  ASSERT_TRUE(planner.push(dwell(xyz(x, 0, 0), 0.5)));
  ASSERT_LT(reach.lengthFor(100.0, kAxisLimits, kAxisLimits), 15.0);
  // After the dwell: the first move is wanted (the path holds each move back until the next
  // one shows how it ends), then nothing, since the dwell is far.
  EXPECT_TRUE(planner.canAccept());
  const double after = readAhead(planner, x, 3000.0);
  EXPECT_LE(after, 0.25);
  // Before any tick, a rapid of 300 mm (it ends at rest) with the same lines after it: not
  // wanted either, however fast the rapid.
  MotionPlanner rapid_first(m, 1 << 14);
  ASSERT_TRUE(rapid_first.push(rapid(xyz(0, 0, 0), xyz(300, 0, 0))));
  double y = 300.0;
  EXPECT_LE(readAhead(rapid_first, y, 6000.0), 0.25);
}

}  // namespace
}  // namespace ncc::vm::motion
