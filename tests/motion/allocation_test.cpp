// After construction, pushing primitives and evaluating ticks allocates nothing.
#include "allocation_counter.h"

#include "gtest/gtest.h"
#include "motion_test_util.h"

namespace ncc::motion_test {
namespace {

TEST(MotionAllocation, TickPathAllocatesNothing) {
  const MachineConfig m = defaultMachine();
  std::vector<MotionPrimitive> prog;
  AxisValues p{};
  for (int i = 1; i <= 500; ++i) {
    const AxisValues q = xyz(0.01 * i, 0, 0);
    prog.push_back(line(p, q, 2000.0));
    p = q;
  }
  prog.push_back(arc(p, p, 0, 1, p[0] - 1.0, 0.0, true, 1000.0));
  prog.push_back(dwell(p, 0.01));
  prog.push_back(rapid(p, xyz(0, 0, 0)));

  vm::motion::MotionPlanner planner(m, 256);
  AxisValues out;
  vm::motion::SetpointInfo info;
  std::size_t next = 0;
  uint64_t ticks = 0;
  const long before = test::allocationCount();
  for (uint64_t k = 0;; ++k) {
    while (next < prog.size() && planner.canAccept()) planner.push(prog[next++]);
    if (next == prog.size()) planner.endOfProgram();
    if (!planner.setpoint(k, out, info)) break;
    ++ticks;
  }
  EXPECT_EQ(test::allocationCount() - before, 0);
  EXPECT_GT(ticks, 100u);
  EXPECT_EQ(out, xyz(0, 0, 0));
}

}  // namespace
}  // namespace ncc::motion_test
