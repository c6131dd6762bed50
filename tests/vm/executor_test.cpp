// Motion, machine functions, reference checks and the program end.
#include "gtest/gtest.h"
#include "run.h"

namespace ncc {
namespace {

using bytecode::Assembler;
using bytecode::Opcode;
using vm::Event;
using vm::MachineEvent;
using vm::MotionPrimitive;

TEST(Executor, EmitsMotionInMachineCoordinatesFromTheStartPosition) {
  MachineConfig machine = defaultMachine();
  machine.start_position = {0.0, 0.0, 100.0};
  Assembler a(test::xyzHeader());
  a.at(1, 1).rapid({10.0, 20.0, 100.0}, bytecode::kFlagPerAxis);
  a.at(1, 2).line({10.0, 20.0, 50.0}, 300.0, bytecode::kFlagExactStop);
  a.at(1, 3).arc({30.0, 20.0, 50.0}, 0, 1, 20.0, 20.0, 150.0, bytecode::kFlagClockwise);
  a.at(1, 4).dwell(2.5);
  a.at(1, 5).op(Opcode::End);
  bytecode::Program p = a.finish();
  vm::Executor executor(p, machine);
  std::vector<Event> events = test::runAll(executor, p);
  ASSERT_EQ(events.size(), 4u);

  const MotionPrimitive& rapid = events[0].motion;
  EXPECT_EQ(events[0].kind, Event::Kind::Motion);
  EXPECT_EQ(rapid.kind, MotionPrimitive::Kind::Rapid);
  EXPECT_EQ(rapid.from, (AxisValues{0.0, 0.0, 100.0}));
  EXPECT_EQ(rapid.to, (AxisValues{10.0, 20.0, 100.0}));
  EXPECT_TRUE(rapid.per_axis);
  EXPECT_EQ(rapid.where.line, 1u);

  const MotionPrimitive& line = events[1].motion;
  EXPECT_EQ(line.kind, MotionPrimitive::Kind::Line);
  EXPECT_EQ(line.from, rapid.to);
  EXPECT_EQ(line.to[2], 50.0);
  EXPECT_EQ(line.feed, 300.0);
  EXPECT_TRUE(line.exact_stop);
  EXPECT_FALSE(line.feed_per_rev);
  EXPECT_EQ(line.where.line, 2u);

  const MotionPrimitive& arc = events[2].motion;
  EXPECT_EQ(arc.kind, MotionPrimitive::Kind::Arc);
  EXPECT_EQ(arc.plane, vm::Plane::XY);
  EXPECT_TRUE(arc.cw);
  EXPECT_EQ(arc.center[0], 20.0);
  EXPECT_EQ(arc.center[1], 20.0);
  EXPECT_EQ(arc.to, (AxisValues{30.0, 20.0, 50.0}));
  EXPECT_EQ(arc.feed, 150.0);

  const MotionPrimitive& dwell = events[3].motion;
  EXPECT_EQ(dwell.kind, MotionPrimitive::Kind::Dwell);
  EXPECT_EQ(dwell.seconds, 2.5);
  EXPECT_FALSE(dwell.revolutions);
  EXPECT_EQ(dwell.from, dwell.to);

  EXPECT_EQ(executor.position(), (AxisValues{30.0, 20.0, 50.0}));
  EXPECT_TRUE(executor.finished());
  EXPECT_FALSE(executor.alarm());
}

TEST(Executor, SkipsStraightMovesToTheCurrentPosition) {
  MachineConfig machine = defaultMachine();
  Assembler a(test::xyzHeader());
  a.rapid({0.0, 0.0, 0.0}).line({0.0, 0.0, 0.0}, 100.0).line({1.0, 0.0, 0.0}, 100.0);
  a.arc({1.0, 0.0, 0.0}, 0, 1, 0.0, 0.0, 100.0, 0);  // full circle: kept
  a.op(Opcode::End);
  bytecode::Program p = a.finish();
  vm::Executor executor(p, machine);
  std::vector<Event> events = test::runAll(executor, p);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].motion.kind, MotionPrimitive::Kind::Line);
  EXPECT_EQ(events[1].motion.kind, MotionPrimitive::Kind::Arc);
}

TEST(Executor, ReportsMachineFunctionsAndRunsThroughStops) {
  MachineConfig machine = defaultMachine();
  Assembler a(test::xyzHeader());
  a.at(1, 1).toolSelect(12).op(Opcode::ToolChange);
  a.at(1, 2).spindleSpeed(2400.0).op(Opcode::SpindleCW).op(Opcode::CoolantOn);
  a.at(1, 3).op(Opcode::ProgramStop).op(Opcode::OptionalStop).mCode(50);
  a.at(1, 4).rapid({1.0, 0.0, 0.0});
  a.at(1, 5).op(Opcode::CoolantOff).op(Opcode::SpindleStop).op(Opcode::SpindleOrient)
      .op(Opcode::SpindleCCW);
  a.at(1, 6).op(Opcode::ProgramEnd);
  a.at(1, 7).rapid({9.0, 9.0, 9.0}).op(Opcode::End);  // after M02: never runs
  bytecode::Program p = a.finish();
  vm::Executor executor(p, machine);
  std::vector<Event> events = test::runAll(executor, p);

  using K = MachineEvent::Kind;
  const std::vector<std::pair<K, int64_t>> expected = {
      {K::ToolSelect, 12}, {K::ToolChange, 6},   {K::SpindleSpeed, 0}, {K::SpindleCW, 3},
      {K::CoolantOn, 8},   {K::ProgramStop, 0},  {K::OptionalStop, 1}, {K::MCode, 50},
      {K::CoolantOff, 9},  {K::SpindleStop, 5},  {K::SpindleOrient, 19}, {K::SpindleCCW, 4},
      {K::ProgramEnd, 2}};
  std::vector<std::pair<K, int64_t>> actual;
  for (const Event& e : events)
    if (e.kind == Event::Kind::Machine) actual.push_back({e.machine.kind, e.machine.code});
  EXPECT_EQ(actual, expected);
  ASSERT_EQ(events.size(), expected.size() + 1);  // + the one rapid
  EXPECT_EQ(events[2].machine.value, 2400.0);
  EXPECT_EQ(events[5].machine.where.line, 3u);
  EXPECT_EQ(executor.position(), (AxisValues{1.0, 0.0, 0.0}));
  EXPECT_TRUE(executor.finished());
  EXPECT_FALSE(executor.alarm());
  Event after;
  EXPECT_FALSE(executor.next(after));
}

TEST(Executor, M30EndsTheRun) {
  MachineConfig machine = defaultMachine();
  Assembler a(test::xyzHeader());
  a.op(Opcode::ProgramEndRewind).rapid({1, 1, 1}).op(Opcode::End);
  bytecode::Program p = a.finish();
  vm::Executor executor(p, machine);
  std::vector<Event> events = test::runAll(executor, p);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].machine.kind, MachineEvent::Kind::ProgramEndRewind);
  EXPECT_EQ(events[0].machine.code, 30);
}

TEST(Executor, ReferenceCheckPassesAtTheReferencePoint) {
  MachineConfig machine = defaultMachine();
  Assembler a(test::xyzHeader());
  a.rapid({0.0, 5.0, 0.0}).refCheck(0b101, 1, {0.0, 0.0, 0.0}).op(Opcode::End);  // X, Z only
  bytecode::Program p = a.finish();
  vm::Executor executor(p, machine);
  test::runAll(executor, p);
  EXPECT_FALSE(executor.alarm());
}

TEST(Executor, ReferenceCheckMismatchRaisesAnAlarmAtItsLine) {
  MachineConfig machine = defaultMachine();
  Assembler a(test::xyzHeader());
  a.at(1, 1).rapid({0.0, 0.0, 10.0});
  a.at(1, 2, 4).refCheck(0b111, 1, {0.0, 0.0, 0.0});
  a.at(1, 3).rapid({5.0, 5.0, 5.0}).op(Opcode::End);
  bytecode::Program p = a.finish();
  vm::Executor executor(p, machine);
  std::vector<Event> events = test::runAll(executor, p);
  EXPECT_EQ(events.size(), 1u);  // the rapid after the check never runs
  ASSERT_TRUE(executor.alarm());
  EXPECT_EQ(executor.alarm()->code, "NCC7201");
  EXPECT_EQ(executor.alarm()->message,
            "G27 reference position check failed: axis Z is at 10, reference point is 0");
  EXPECT_EQ(executor.alarm()->where, (SourceLocation{1, 2, 4}));
  EXPECT_TRUE(executor.finished());
}

TEST(Executor, StepLimitStopsAnEndlessLoop) {
  MachineConfig machine = defaultMachine();
  Assembler a(test::xyzHeader());
  Assembler::Label top = a.newLabel();
  Assembler::Label end = a.newLabel();
  a.bind(top).push(1.0).jump(Opcode::JumpIfFalse, end).jump(Opcode::Jump, top);
  a.bind(end).op(Opcode::End);
  bytecode::Program p = a.finish();
  vm::Executor executor(p, machine);
  executor.setStepLimit(1000);
  test::runAll(executor, p);
  ASSERT_TRUE(executor.alarm());
  EXPECT_EQ(executor.alarm()->code, "NCC7204");
  EXPECT_EQ(executor.steps(), 1000u);
}

TEST(Executor, AxisMismatchWithTheMachineIsAnAlarmNotACrash) {
  MachineConfig machine = defaultMachine();
  machine.axes.pop_back();
  Assembler a(test::xyzHeader());
  a.rapid({1, 2, 3}).op(Opcode::End);
  bytecode::Program p = a.finish();
  vm::Executor executor(p, machine);
  Event e;
  EXPECT_FALSE(executor.next(e));
  ASSERT_TRUE(executor.alarm());
  EXPECT_EQ(executor.alarm()->code, "NCC7206");
}

TEST(Executor, UnverifiedHostileCodeStopsWithAnAlarm) {
  MachineConfig machine = defaultMachine();
  // Stack underflow, a jump into nowhere, and a truncated instruction: none verified.
  std::vector<std::vector<uint8_t>> bodies = {
      {static_cast<uint8_t>(Opcode::Add)},
      {static_cast<uint8_t>(Opcode::Jump), 0xFF, 0xFF, 0x00, 0x00},
      {static_cast<uint8_t>(Opcode::Line), 0x00, 0x01},
      {static_cast<uint8_t>(Opcode::Store), 0x00, 0x00, 0x00, 0x00},
  };
  for (const std::vector<uint8_t>& body : bodies) {
    bytecode::Program p = bytecode::Assembler(test::xyzHeader()).finish();
    p.code = body;
    EXPECT_TRUE(bytecode::verify(p));  // the verifier would have refused it
    vm::Executor executor(p, machine);
    Event e;
    while (executor.next(e)) {
    }
    ASSERT_TRUE(executor.alarm());
    EXPECT_EQ(executor.alarm()->code, "NCC7205");
  }
}

}  // namespace
}  // namespace ncc
