// SKIP (G31): the move ends at the first crossing of a probe plane ([machine.probe]), the skip
// position goes to the result variables in work coordinates, and the next move starts there.
#include "gtest/gtest.h"
#include "ncc/machine/probe.h"
#include "run.h"

namespace ncc {
namespace {

using bytecode::Assembler;
using bytecode::Opcode;
using vm::Event;
using vm::MotionPrimitive;

MachineConfig probedAt(int axis, double trigger) {
  MachineConfig machine = defaultMachine();
  machine.probe.axes = static_cast<AxisMask>(1u << axis);
  machine.probe.trigger[axis] = trigger;
  return machine;
}

// RAPID to (10, 10, 10), SKIP to Z-50 at F100 with the work zero at `origin`, RAPID to Z20.
bytecode::Program probingProgram(const AxisValues& origin, uint8_t flags = bytecode::kFlagExactStop) {
  Assembler a(test::xyzHeader());
  a.at(1, 1).rapid({10.0, 10.0, 10.0});
  a.at(1, 2).skip({10.0, 10.0, -50.0}, 100.0, 5061, origin, flags);
  a.at(1, 3).rapid({10.0, 10.0, 20.0});
  a.op(Opcode::End);
  return a.finish();
}

TEST(Skip, StopsWhereTheProbeTriggersAndStoresTheSkipPosition) {
  const bytecode::Program p = probingProgram({0.0, 0.0, -10.0});
  ASSERT_FALSE(bytecode::verify(p));
  const MachineConfig machine = probedAt(2, -42.5);
  vm::Executor executor(p, machine);
  std::vector<Event> events = test::runAll(executor, p);
  ASSERT_EQ(events.size(), 3u);
  const MotionPrimitive& skip = events[1].motion;
  EXPECT_EQ(skip.kind, MotionPrimitive::Kind::Line);
  EXPECT_EQ(skip.to, (AxisValues{10.0, 10.0, -42.5}));
  EXPECT_EQ(skip.feed, 100.0);
  EXPECT_TRUE(skip.exact_stop);  // the look-ahead must not blend through the skip point
  EXPECT_EQ(skip.where.line, 2u);
  // Work coordinates: machine position minus the origin the instruction carries.
  EXPECT_EQ(executor.variable(5061), 10.0);
  EXPECT_EQ(executor.variable(5062), 10.0);
  EXPECT_EQ(executor.variable(5063), -32.5);
  // The next move starts where the skip stopped.
  EXPECT_EQ(events[2].motion.from, (AxisValues{10.0, 10.0, -42.5}));
  EXPECT_FALSE(executor.alarm());
}

TEST(Skip, WithoutASignalTheMoveRunsToItsEnd) {
  const bytecode::Program p = probingProgram({});
  for (const MachineConfig& machine : {defaultMachine(), probedAt(2, -60.0),
                                       probedAt(0, 5.0)}) {
    vm::Executor executor(p, machine);
    std::vector<Event> events = test::runAll(executor, p);
    ASSERT_EQ(events.size(), 3u);
    EXPECT_EQ(events[1].motion.to, (AxisValues{10.0, 10.0, -50.0}));
    EXPECT_EQ(executor.variable(5063), -50.0);
  }
}

TEST(Skip, ASignalOnAtTheStartEndsTheMoveAtOnce) {
  // The start (Z10) is already beyond the plane Z20 in the direction of the move (down).
  const bytecode::Program p = probingProgram({});
  vm::Executor executor(p, probedAt(2, 20.0));
  std::vector<Event> events = test::runAll(executor, p);
  ASSERT_EQ(events.size(), 2u);  // no motion for the skip, then the rapid to Z20
  EXPECT_EQ(events[1].motion.from, (AxisValues{10.0, 10.0, 10.0}));
  EXPECT_EQ(executor.variable(5063), 10.0);
}

TEST(Skip, TheFirstPlaneOnTheDiagonalPathStopsIt) {
  Assembler a(test::xyzHeader());
  a.rapid({10.0, 10.0, 10.0}).skip({-50.0, 10.0, -50.0}, 100.0, 0, {});
  a.op(Opcode::End);
  const bytecode::Program p = a.finish();
  MachineConfig machine = probedAt(2, -42.5);
  machine.probe.axes |= 1u;
  machine.probe.trigger[0] = -20.0;  // met halfway, before Z's plane at 0.875
  vm::Executor executor(p, machine);
  std::vector<Event> events = test::runAll(executor, p);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[1].motion.to, (AxisValues{-20.0, 10.0, -20.0}));
  EXPECT_FALSE(executor.variable(5061));  // no result variables: nothing stored
}

TEST(Skip, InchFlagStoresInches) {
  const bytecode::Program p =
      probingProgram({0.0, 0.0, 0.0}, bytecode::kFlagExactStop | bytecode::kFlagInch);
  vm::Executor executor(p, probedAt(2, -25.4));
  test::runAll(executor, p);
  EXPECT_DOUBLE_EQ(*executor.variable(5063), -1.0);
  EXPECT_DOUBLE_EQ(*executor.variable(5061), 10.0 / 25.4);
}

TEST(Skip, VerifierRefusesResultVariablesBeyondTheCount) {
  Assembler a(test::xyzHeader());
  a.skip({0.0, 0.0, -5.0}, 100.0, 9998, {});  // #9998..#10000: one beyond 10000
  a.op(Opcode::End);
  std::optional<bytecode::Error> e = bytecode::verify(a.finish());
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code, "NCC7103");
}

TEST(Probe, OptionTextAndStopFraction) {
  ProbeConfig probe;
  const std::vector<AxisConfig> axes = defaultMachine().axes;
  EXPECT_FALSE(setProbeFromOption(probe, axes, "Z=-42.5"));
  EXPECT_EQ(probe.axes, 4u);
  EXPECT_EQ(probe.trigger[2], -42.5);
  EXPECT_TRUE(setProbeFromOption(probe, axes, "W=1"));
  EXPECT_TRUE(setProbeFromOption(probe, axes, "Z=abc"));
  EXPECT_TRUE(setProbeFromOption(probe, axes, "Z"));
  EXPECT_TRUE(setProbeFromOption(probe, axes, "Z=inf"));
  EXPECT_TRUE(setProbeFromOption(probe, axes, "Z=2e6"));
  EXPECT_EQ(probe.trigger[2], -42.5);  // a refused text changes nothing
  // Upwards through Z-42.5 from below: the plane is met on the way up as well.
  const std::optional<ProbeHit> up = probeStop(probe, {0, 0, -50}, {0, 0, 0}, 3);
  ASSERT_TRUE(up);
  EXPECT_DOUBLE_EQ(up->fraction, 7.5 / 50.0);
  EXPECT_EQ(up->axis, 2);
  EXPECT_EQ(probeStopPoint(probe, *up, {0, 0, -50}, {0, 0, 0}, 3), (AxisValues{0, 0, -42.5}));
  EXPECT_FALSE(probeStop(probe, {0, 0, 0}, {10, 0, 0}, 3));  // Z does not move
  EXPECT_EQ(probeStop(probe, {0, 0, -42.5}, {0, 0, -50}, 3)->fraction, 0.0);  // on the plane
}

}  // namespace
}  // namespace ncc
