// Issue 21 in the VM: travel limits stop the run with the dialect's stored-stroke alarm before
// the move, and every run ends: the simulated-time limit (ControllerOptions::max_seconds,
// NCC7208) at its tick, or at once for a block that cannot end before it.
#include <cmath>
#include <vector>

#include "controller_test_util.h"
#include "gtest/gtest.h"
#include "ncc/bytecode/format.h"
#include "ncc/vm/run_limits.h"

namespace ncc {
namespace {

using controller_test::assemblerFor;
using controller_test::make;
using controller_test::xyz;
using vm::TickOutput;
using vm::TickStatus;

// Ticks until the run stops (at most `max_ticks`).
std::vector<TickOutput> runAll(vm::Controller& ctl, uint64_t max_ticks = 2'000'000) {
  std::vector<TickOutput> out;
  TickOutput t;
  while (out.size() < max_ticks && ctl.tick(t) == TickStatus::Running) out.push_back(t);
  return out;
}

MachineConfig travelMachine() {
  MachineConfig m = defaultMachine();
  m.axes[0].min_travel = -10.0;
  m.axes[0].max_travel = 10.0;
  m.axes[1].min_travel = -4.0;
  m.axes[1].max_travel = 20.0;
  return m;
}

TEST(TravelAlarm, StopsBeforeTheMoveWithTheDialectsNumber) {
  struct Case {
    Dialect dialect;
    const char* plus;
  };
  for (const Case& c : {Case{Dialect::FanucM, "OT0500"}, Case{Dialect::SiemensIsoM, "10720"},
                        Case{Dialect::MazakM, "NCC7210"}}) {
    const MachineConfig m = travelMachine();
    bytecode::Assembler a = assemblerFor(m);
    a.at(1, 1).rapid(xyz(5, 0, 0));
    a.at(1, 2, 4).rapid(xyz(50, 0, 0));
    a.at(1, 3).op(bytecode::Opcode::ProgramEndRewind).op(bytecode::Opcode::End);
    bytecode::Program p = a.finish();
    p.header.dialect = c.dialect;
    std::unique_ptr<vm::Controller> ctl = make(std::move(p), m);
    const std::vector<TickOutput> ticks = runAll(*ctl);
    ASSERT_EQ(ctl->status(), TickStatus::Alarm);
    EXPECT_EQ(ctl->alarm()->code, c.plus);
    EXPECT_EQ(ctl->alarm()->where.line, 2u);
    EXPECT_EQ(ctl->alarm()->where.column, 4u);
    EXPECT_NE(ctl->alarm()->message.find("axis X would reach 50, beyond max_travel 10"),
              std::string::npos)
        << ctl->alarm()->message;
    // The move before ran to its end; the one beyond never started.
    ASSERT_FALSE(ticks.empty());
    EXPECT_EQ(ticks.back().commanded[0], 5.0);
    for (const TickOutput& t : ticks) ASSERT_LE(t.commanded[0], 5.0);
    // The travel was never passed.
    EXPECT_EQ(ctl->statistics().violations[0].travel, 0);
  }
}

TEST(TravelAlarm, ArcWhoseExtentLeavesTheTravel) {
  const MachineConfig m = travelMachine();
  bytecode::Assembler a = assemblerFor(m);
  a.at(1, 1).rapid(xyz(-5, 0, 0));
  // G03 X5 Y0 I5 J0: through Y-5, below min_travel -4.
  a.at(1, 2).arc(xyz(5, 0, 0), 0, 1, 0.0, 0.0, 600.0, 0);
  a.at(1, 3).op(bytecode::Opcode::ProgramEndRewind).op(bytecode::Opcode::End);
  std::unique_ptr<vm::Controller> ctl = make(a.finish(), m);
  runAll(*ctl);
  ASSERT_EQ(ctl->status(), TickStatus::Alarm);
  EXPECT_EQ(ctl->alarm()->code, "OT0501");
  EXPECT_EQ(ctl->alarm()->where.line, 2u);
  EXPECT_NE(ctl->alarm()->message.find("axis Y would reach -5, beyond min_travel -4"),
            std::string::npos)
      << ctl->alarm()->message;
}

TEST(TravelAlarm, ArcWithinTheTravelRunsToItsEnd) {
  const MachineConfig m = travelMachine();
  bytecode::Assembler a = assemblerFor(m);
  a.at(1, 1).rapid(xyz(-5, 0, 0));
  a.at(1, 2).arc(xyz(5, 0, 0), 0, 1, 0.0, 0.0, 600.0, bytecode::kFlagClockwise);  // over the top
  a.at(1, 3).op(bytecode::Opcode::ProgramEndRewind).op(bytecode::Opcode::End);
  std::unique_ptr<vm::Controller> ctl = make(a.finish(), m);
  runAll(*ctl);
  EXPECT_EQ(ctl->status(), TickStatus::Finished);
}

TEST(RunLimits, MachineCheckRefusesStartOutsideTravelAndAbsurdValues) {
  bytecode::Error error;
  MachineConfig m = travelMachine();
  m.start_position[0] = 11.0;
  bytecode::Assembler a = assemblerFor(m);
  a.op(bytecode::Opcode::End);
  EXPECT_EQ(vm::Controller::create(a.finish(), m, error), nullptr);
  EXPECT_EQ(error.code, "NCC7115");
  EXPECT_NE(error.message.find("start_position of X"), std::string::npos) << error.message;
  struct Spoil {
    const char* name;
    void (*apply)(MachineConfig&);
  };
  const Spoil spoils[] = {
      {"ipo_cycle", [](MachineConfig& c) { c.ipo_cycle_seconds = 1e-300; }},
      {"max_jerk of X", [](MachineConfig& c) { c.axes[0].max_jerk = 1e-300; }},
      {"max_acceleration of X", [](MachineConfig& c) { c.axes[0].max_acceleration = 1e-300; }},
      {"max_velocity of X", [](MachineConfig& c) { c.axes[0].max_velocity = 1e-300; }},
      {"chord_tolerance", [](MachineConfig& c) { c.chord_tolerance = 1e-300; }},
      {"corner_tolerance", [](MachineConfig& c) { c.corner_tolerance = 1e-300; }},
      {"min_travel of Y", [](MachineConfig& c) { c.axes[1].min_travel = -1e300; }},
  };
  for (const Spoil& s : spoils) {
    MachineConfig c = defaultMachine();
    s.apply(c);
    bytecode::Assembler b = assemblerFor(c);
    b.op(bytecode::Opcode::End);
    EXPECT_EQ(vm::Controller::create(b.finish(), c, error), nullptr) << s.name;
    EXPECT_EQ(error.code, "NCC7115") << s.name;
    EXPECT_NE(error.message.find(s.name), std::string::npos) << error.message;
  }
}

TEST(RunLimits, TheClockStopsTheRunInItsBlock) {
  // A feed hold that is never released: the run would tick for ever.
  const MachineConfig m = defaultMachine();
  bytecode::Assembler a = assemblerFor(m);
  a.at(1, 1).line(xyz(1, 0, 0), 600.0);
  a.at(1, 2).op(bytecode::Opcode::ProgramEndRewind).op(bytecode::Opcode::End);
  vm::ControllerOptions options;
  options.max_seconds = 2.5;
  std::unique_ptr<vm::Controller> ctl = make(a.finish(), m, options);
  std::vector<TickOutput> ticks;
  TickOutput t;
  while (ticks.size() < 100'000 && ctl->tick(t) == TickStatus::Running) {
    ticks.push_back(t);
    if (ticks.size() == 10) ctl->setFeedHold(true);
  }
  ASSERT_EQ(ctl->status(), TickStatus::Alarm);
  EXPECT_EQ(ctl->alarm()->code, "NCC7208");
  EXPECT_EQ(ctl->alarm()->where.line, 1u);
  EXPECT_EQ(ticks.size(), 2500u);  // ticks 0..2499: up to 2.499 s
  EXPECT_NE(ctl->alarm()->message.find("simulated time limit 2.5 s reached in this block"),
            std::string::npos)
      << ctl->alarm()->message;
  // A limit the program stays within changes nothing.
  bytecode::Assembler b = assemblerFor(m);
  b.at(1, 1).line(xyz(1, 0, 0), 600.0);
  b.at(1, 2).op(bytecode::Opcode::ProgramEndRewind).op(bytecode::Opcode::End);
  options.max_seconds = 60.0;
  std::unique_ptr<vm::Controller> ok = make(b.finish(), m, options);
  runAll(*ok);
  EXPECT_EQ(ok->status(), TickStatus::Finished);
}

TEST(RunLimits, ALongDwellStopsOnceTheMovesBeforeItHaveRun) {
  const MachineConfig m = defaultMachine();
  bytecode::Assembler a = assemblerFor(m);
  a.at(1, 1).rapid(xyz(10, 0, 0));
  a.at(1, 2).dwell(1e5);  // the verifier's largest dwell (docs/bytecode.md)
  a.at(1, 3).op(bytecode::Opcode::ProgramEndRewind).op(bytecode::Opcode::End);
  vm::ControllerOptions options;
  options.max_seconds = 3600.0;
  std::unique_ptr<vm::Controller> ctl = make(a.finish(), m, options);
  ASSERT_NE(ctl, nullptr);
  const std::vector<TickOutput> ticks = runAll(*ctl);
  ASSERT_EQ(ctl->status(), TickStatus::Alarm);
  EXPECT_EQ(ctl->alarm()->code, "NCC7208");
  EXPECT_EQ(ctl->alarm()->where.line, 2u);
  EXPECT_LT(ticks.size(), 5000u);  // the rapid, not 100 hours
  EXPECT_EQ(ticks.back().commanded[0], 10.0);
}

TEST(RunLimits, AnArcOfTheMostTurnsStopsAtOnceUnderATighterLimit) {
  const MachineConfig m = defaultMachine();
  bytecode::Assembler a = assemblerFor(m);
  a.at(1, 1).rapid(xyz(10, 0, 0));
  // The verifier's most extra turns (999, docs/bytecode.md): over 12,000 s at any speed.
  a.at(1, 2).arc(xyz(10, 0, 0), 0, 1, 0.0, 0.0, 1000.0, 0, bytecode::ArcPlane::XY, 999);
  a.at(1, 3).op(bytecode::Opcode::ProgramEndRewind).op(bytecode::Opcode::End);
  vm::ControllerOptions options;
  options.max_seconds = 3600.0;
  std::unique_ptr<vm::Controller> ctl = make(a.finish(), m, options);
  ASSERT_NE(ctl, nullptr);
  runAll(*ctl);
  ASSERT_EQ(ctl->status(), TickStatus::Alarm);
  EXPECT_EQ(ctl->alarm()->code, "NCC7208");
  EXPECT_EQ(ctl->alarm()->where.line, 2u);
}

TEST(RunLimits, AnArcWhoseEndIsOffItsCircleIsRefused) {
  // From X655.36 around (0, 0) to X10: the verifier cannot see the start, the executor can.
  const MachineConfig m = defaultMachine();
  bytecode::Assembler a = assemblerFor(m);
  a.at(1, 1).rapid(xyz(655.36, 0, 0));
  a.at(1, 2).arc(xyz(10, 0, 0), 0, 1, 0.0, 0.0, 1000.0, 0, bytecode::ArcPlane::XY, 0);
  a.at(1, 3).op(bytecode::Opcode::ProgramEndRewind).op(bytecode::Opcode::End);
  std::unique_ptr<vm::Controller> ctl = make(a.finish(), m, vm::ControllerOptions{});
  ASSERT_NE(ctl, nullptr);
  const std::vector<TickOutput> ticks = runAll(*ctl);
  ASSERT_EQ(ctl->status(), TickStatus::Alarm);
  EXPECT_EQ(ctl->alarm()->code, "NCC7211");
  EXPECT_EQ(ctl->alarm()->where.line, 2u);
  EXPECT_EQ(ctl->alarm()->message,
            "the arc's end point is not on its circle: start radius 655.36, end radius 10 "
            "(difference above arc_radius_tolerance 0.01; was the file edited?)");
  EXPECT_EQ(ticks.back().commanded[0], 655.36);
  // Within arc_radius_tolerance (0.01 mm) the arc is a slight spiral, as compiled.
  bytecode::Assembler b = assemblerFor(m);
  b.at(1, 1).rapid(xyz(10, 0, 0));
  b.at(1, 2).arc(xyz(-10.009, 0, 0), 0, 1, 0.0, 0.0, 1000.0, 0, bytecode::ArcPlane::XY, 0);
  b.at(1, 3).op(bytecode::Opcode::ProgramEndRewind).op(bytecode::Opcode::End);
  std::unique_ptr<vm::Controller> spiral = make(b.finish(), m, vm::ControllerOptions{});
  ASSERT_NE(spiral, nullptr);
  runAll(*spiral);
  EXPECT_NE(spiral->status(), TickStatus::Alarm);
}

TEST(RunLimits, MinimumSecondsIsALowerBound) {
  MachineConfig m = defaultMachine();
  vm::MotionPrimitive dwell;
  dwell.kind = vm::MotionPrimitive::Kind::Dwell;
  dwell.seconds = 7.0;
  EXPECT_EQ(vm::minimumSeconds(dwell, m, 1.0), 7.0);
  dwell.revolutions = true;
  EXPECT_EQ(vm::minimumSeconds(dwell, m, 1.0), 0.0);
  vm::MotionPrimitive line;
  line.kind = vm::MotionPrimitive::Kind::Line;
  line.to = xyz(100, 0, 0);
  line.feed = 600.0;  // 10 mm/s, 20 mm/s at a 200 % override
  EXPECT_DOUBLE_EQ(vm::minimumSeconds(line, m, 2.0), 5.0);
  line.feed_per_rev = true;  // no spindle speed known: the machine's top speed
  EXPECT_DOUBLE_EQ(vm::minimumSeconds(line, m, 2.0), 100.0 / vm::topPathSpeed(m));
  EXPECT_DOUBLE_EQ(vm::topPathSpeed(m), std::sqrt(3.0) * 500.0);
}

}  // namespace
}  // namespace ncc
