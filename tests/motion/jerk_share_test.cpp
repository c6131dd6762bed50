// How much of each axis' jerk a move's smooth motion may use (limits.h): the whole of it but
// 1e-4 from rest to rest, 95 % where neither end is a kink passed moving, 90 % otherwise. Read
// from the limits of the runs ContinuousPath queues for X lines of the default machine, whose
// path jerk is the share times 50000 mm/s^3.
#include <vector>

#include "gtest/gtest.h"
#include "motion_test_util.h"
#include "ncc/vm/motion/continuous_path.h"
#include "ncc/vm/motion/lookahead.h"

namespace ncc::vm::motion {
namespace {

using namespace motion_test;

constexpr double kAxisJerk = 50000.0;

// Queues lines through `points` at 100 mm/s, then ends as `end` says, and returns the path
// jerk of the first run.
enum class End { Stop, Unknown };
double firstRunJerk(const std::vector<AxisValues>& points, End end) {
  MachineConfig machine = defaultMachine();
  machine.corner_tolerance = 0.0;  // no blends: a small turn is a kink
  const AxisLimits limits = AxisLimits::from(machine);
  LookAhead queue(64, WindowReach::of(limits));
  ContinuousPath path(limits, queue);
  for (std::size_t i = 1; i < points.size(); ++i)
    path.move(PathSegment::line(points[i - 1], points[i], limits.count), 100.0, 100.0, false, {});
  path.flush(end == End::Stop);
  return queue.run(0).limits.jerk;
}

TEST(JerkShare, LineFromRestToAStopUsesNearlyTheWholeJerk) {
  EXPECT_DOUBLE_EQ(firstRunJerk({xyz(0, 0, 0), xyz(10, 0, 0)}, End::Stop),
                   kBetweenStopsJerkShare * kAxisJerk);
}

TEST(JerkShare, LineIntoAKinkKeepsTheKinksRoom) {
  // Turned by 0.005 rad: below the corner angle, a kink passed moving (at 0.5 mm/s).
  const double turn = 0.005;
  EXPECT_DOUBLE_EQ(
      firstRunJerk({xyz(0, 0, 0), xyz(10, 0, 0), xyz(10 + 10 * std::cos(turn), 10 * std::sin(turn), 0)},
                   End::Stop),
      kSmoothJerkShare * kAxisJerk);
}

TEST(JerkShare, LineWhoseEndIsNotKnownYetKeepsTheKinksRoom) {
  // Queued before what follows is known (a G00 that does not move came next): a feed move
  // may still join it at a kink, so it keeps the room (it took 95 % before).
  EXPECT_DOUBLE_EQ(firstRunJerk({xyz(0, 0, 0), xyz(10, 0, 0)}, End::Unknown),
                   kSmoothJerkShare * kAxisJerk);
}

}  // namespace
}  // namespace ncc::vm::motion
