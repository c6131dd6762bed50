// Runs of segments with slightly different limits (LookAhead::push): a join that lowers a
// run's limits must never lower what the motion under way is committed to. The two cases are
// from the review of a first version, which lowered runs already planned for.
#include <algorithm>
#include <cmath>
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

}  // namespace
}  // namespace ncc::vm::motion
