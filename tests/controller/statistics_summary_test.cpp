// The run summary's statistics (issue 21): the extents of feed and of rapid motion, rapids
// left out of the contour error, and the source block of the worst contour error.
#include "controller_test_util.h"

namespace ncc {
namespace {

using namespace controller_test;
using vm::TickOutput;
using vm::TickStatus;

vm::RunStatistics run(bytecode::Program program, const MachineConfig& m) {
  std::unique_ptr<vm::Controller> ctl = make(std::move(program), m);
  TickOutput out;
  while (ctl->tick(out) == TickStatus::Running) {
  }
  EXPECT_EQ(ctl->status(), TickStatus::Finished);
  return ctl->statistics();
}

// Monitoring off, so the lag of a slow servo can show without an alarm.
ServoConfig laggingServo() {
  ServoConfig s;
  s.ffw_mode = FeedForwardMode::None;
  s.contour_tol = 1e6;
  s.standstill_pos_tol = 1e6;
  return s;
}

TEST(RunSummaryStatistics, ExtentsOfFeedAndRapidMotionSeparately) {
  const MachineConfig m = defaultMachine();
  bytecode::Assembler a = assemblerFor(m);
  a.rapid(xyz(10, 0, 0))
      .line(xyz(10, 20, -5), 1000.0)
      .line(xyz(30, 20, -5), 1000.0)
      .rapid(xyz(30, 20, 5))
      .op(bytecode::Opcode::End);
  const vm::RunStatistics s = run(a.finish(), m);
  ASSERT_FALSE(s.feed_extents.empty);
  ASSERT_FALSE(s.rapid_extents.empty);
  // Feed: from the end of the first rapid (10, 0, 0) over (10, 20, -5) to (30, 20, -5).
  const AxisValues feed_min = xyz(10, 0, -5), feed_max = xyz(30, 20, 0);
  // Rapid: (0, 0, 0) to (10, 0, 0), and (30, 20, -5) to (30, 20, 5).
  const AxisValues rapid_min = xyz(0, 0, -5), rapid_max = xyz(30, 20, 5);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(s.feed_extents.min[i], feed_min[i], 1e-9) << i;
    EXPECT_NEAR(s.feed_extents.max[i], feed_max[i], 1e-9) << i;
    EXPECT_NEAR(s.rapid_extents.min[i], rapid_min[i], 1e-9) << i;
    EXPECT_NEAR(s.rapid_extents.max[i], rapid_max[i], 1e-9) << i;
  }
}

TEST(RunSummaryStatistics, NoMotionOfAKindLeavesItsExtentsEmpty) {
  const MachineConfig m = defaultMachine();
  bytecode::Assembler a = assemblerFor(m);
  a.rapid(xyz(10, 5, 0)).op(bytecode::Opcode::End);
  const vm::RunStatistics s = run(a.finish(), m);
  EXPECT_TRUE(s.feed_extents.empty);
  EXPECT_FALSE(s.rapid_extents.empty);
}

TEST(RunSummaryStatistics, RapidsAreNoContour) {
  // Non-linear rapids (each axis at its own rapid speed, so the path bends where one axis
  // arrives) on a lagging servo: the actual position leaves the commanded line, but a rapid
  // is no contour.
  const MachineConfig m = machineWith(laggingServo());
  bytecode::Assembler a = assemblerFor(m);
  a.rapid(xyz(100, 30, 0)).rapid(xyz(0, 80, -20)).rapid(xyz(60, 0, 10)).op(bytecode::Opcode::End);
  const vm::RunStatistics s = run(a.finish(), m);
  EXPECT_GT(s.rapid_length, 200.0);
  EXPECT_EQ(s.max_contour_error, 0.0);
  EXPECT_GT(s.max_following_error[0], 1.0);  // the servo does lag
}

TEST(RunSummaryStatistics, WorstContourErrorKeepsItsSourceBlock) {
  ServoConfig servo;
  servo.contour_tol = 1e6;
  servo.standstill_pos_tol = 1e6;
  const MachineConfig m = machineWith(servo);
  bytecode::Assembler a = assemblerFor(m);
  a.at(1, 3).rapid(xyz(0, 0, 0));
  a.at(1, 4).line(xyz(10, 0, 0), 6000.0);
  a.at(1, 5).arc(xyz(10, 0, 0), 0, 1, 0.0, 0.0, 6000.0, 0, bytecode::ArcPlane::XY);
  a.at(1, 6).rapid(xyz(50, 50, 20));
  a.at(1, 7).line(xyz(50, 60, 20), 600.0);
  a.at(1, 8).op(bytecode::Opcode::End);
  const vm::RunStatistics s = run(a.finish(), m);
  EXPECT_GT(s.max_contour_error, 0.001);
  EXPECT_EQ(s.max_contour_error_where.file, 1u);
  EXPECT_EQ(s.max_contour_error_where.line, 5u);  // the arc
}

}  // namespace
}  // namespace ncc
