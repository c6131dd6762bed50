// After construction, tick() allocates nothing (real-time discipline), through a whole
// program and through a servo alarm: a replaced global operator new counts every allocation
// of this binary.
#include <cmath>

#include "allocation_counter.h"

#include "controller_test_util.h"

namespace ncc {
namespace {

using namespace controller_test;

bytecode::Program program(const MachineConfig& m) {
  bytecode::Assembler a = assemblerFor(m);
  a.at(1, 1).rapid(xyz(10, 5, 2));
  for (int i = 1; i <= 2000; ++i)  // more segments than the window holds
    a.at(1, 2).line(xyz(10 + 0.01 * i, 5 + 0.005 * i, 2), 2000.0);
  a.at(1, 3).arc(xyz(30, 15, 2), 0, 1, 30.0, 10.0, 1500.0, 0, bytecode::ArcPlane::XY, 1);
  a.at(1, 4).dwell(0.1).spindleSpeed(1000.0).mCode(8);
  a.at(1, 5).line(xyz(0, 0, 0), 0.5, bytecode::kFlagFeedPerRev);
  a.at(1, 6).op(bytecode::Opcode::ProgramStop).rapid(xyz(0, 0, 50));
  a.op(bytecode::Opcode::ProgramEndRewind).op(bytecode::Opcode::End);
  return a.finish();
}

TEST(ControllerAllocation, TickAllocatesNothing) {
  MachineConfig m = defaultMachine();
  for (AxisConfig& a : m.axes) {
    a.servo.backlash = 0.01;
    a.servo.backlash_compensation = 0.01;
    a.servo.pitch_error = PitchTable{-100.0, 10.0, std::vector<double>(21, 0.001)};
    a.servo.pitch_compensation = a.servo.pitch_error;
  }
  vm::ControllerOptions options;
  options.window_capacity = 256;
  std::unique_ptr<vm::Controller> ctl = make(program(m), m, options);
  const long before = test::allocationCount();
  vm::TickOutput out;
  uint64_t ticks = 0;
  while (ctl->tick(out) == vm::TickStatus::Running) ++ticks;
  const vm::RunStatistics stats = ctl->statistics();
  EXPECT_EQ(test::allocationCount() - before, 0);
  EXPECT_EQ(ctl->status(), vm::TickStatus::Finished);
  EXPECT_GT(ticks, 5000u);
  EXPECT_GT(stats.path_length, 100.0);
}

// The operator turns the feed override knob every 50 ticks (Controller::setFeedOverride, a
// re-plan of the whole window), the rapid override every 70, and holds the feed for 300 of
// every 700 ticks: nothing allocates either.
TEST(ControllerAllocation, OverridesAndFeedHoldAllocateNothing) {
  const MachineConfig m = defaultMachine();
  vm::ControllerOptions options;
  options.window_capacity = 256;
  options.max_feed_override = 1.5;
  std::unique_ptr<vm::Controller> ctl = make(program(m), m, options);
  const long before = test::allocationCount();
  vm::TickOutput out;
  uint64_t ticks = 0;
  for (;;) {
    if (ticks % 50 == 0) ctl->setFeedOverride(0.2 + 0.1 * static_cast<double>((ticks / 50) % 13));
    if (ticks % 70 == 0) ctl->setRapidOverride(0.1 + 0.1 * static_cast<double>((ticks / 70) % 10));
    if (ticks % 700 == 0) ctl->setFeedHold(true);
    if (ticks % 700 == 300) ctl->setFeedHold(false);
    if (ctl->tick(out) != vm::TickStatus::Running) break;
    ++ticks;
  }
  EXPECT_EQ(test::allocationCount() - before, 0);
  EXPECT_EQ(ctl->status(), vm::TickStatus::Finished);
  EXPECT_GT(ticks, 5000u);
}

// The real-time loop (prepare_in_tick = false): neither tick() nor prepare() allocates, on a
// G64 zig-zag whose corners are blended and a polyline whose vertices run as a chain.
TEST(ControllerAllocation, SplitLoopWithBlendsAllocatesNothing) {
  MachineConfig m = defaultMachine();
  m.corner_tolerance = 0.05;
  bytecode::Assembler a = assemblerFor(m);
  a.at(1, 1).rapid(xyz(0, 0, 2));
  for (int i = 1; i <= 400; ++i)  // 30-degree zig-zag: blended corners
    a.at(1, 2).line(xyz(2.0 * i, (i % 2) * 1.15, 2), 1200.0);
  for (int i = 1; i <= 400; ++i)  // gentle polyline: chain vertices and small blends
    a.at(1, 3).line(xyz(800 + 0.05 * i, 1.15 + 0.5 * std::sin(0.01 * i), 2), 2000.0);
  a.op(bytecode::Opcode::ProgramEndRewind).op(bytecode::Opcode::End);
  vm::ControllerOptions options;
  options.window_capacity = 128;
  options.prepare_in_tick = false;
  std::unique_ptr<vm::Controller> ctl = make(a.finish(), m, options);
  const long before = test::allocationCount();
  vm::TickOutput out;
  uint64_t ticks = 0, at_rest = 0;
  ctl->prepare();
  while (ctl->tick(out) == vm::TickStatus::Running) {
    ctl->prepare();
    ++ticks;
    if (out.path_velocity == 0.0 && out.commanded[0] > 1.0) ++at_rest;
  }
  EXPECT_EQ(test::allocationCount() - before, 0);
  EXPECT_EQ(ctl->status(), vm::TickStatus::Finished);
  EXPECT_GT(ticks, 1000u);
  EXPECT_LT(at_rest, 40u);  // the 400 corners are passed moving: blended, not stopped
}

TEST(ControllerAllocation, ServoAlarmAllocatesNothing) {
  ServoConfig servo;
  servo.ffw_mode = FeedForwardMode::None;
  servo.contour_tol = 0.5;
  const MachineConfig m = machineWith(servo);
  bytecode::Assembler a = assemblerFor(m);
  a.line(xyz(100, 0, 0), 6000.0).op(bytecode::Opcode::End);
  std::unique_ptr<vm::Controller> ctl = make(a.finish(), m);
  const long before = test::allocationCount();
  vm::TickOutput out;
  while (ctl->tick(out) == vm::TickStatus::Running) {
  }
  EXPECT_EQ(test::allocationCount() - before, 0);
  ASSERT_NE(ctl->alarm(), nullptr);
  EXPECT_EQ(ctl->alarm()->code, "25050");
}

}  // namespace
}  // namespace ncc
