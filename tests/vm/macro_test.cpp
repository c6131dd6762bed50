// Variables, arithmetic and jumps (hand-assembled: the compiler does not emit them yet).
#include <limits>

#include "gtest/gtest.h"
#include "run.h"

namespace ncc {
namespace {

using bytecode::Assembler;
using bytecode::Opcode;
using vm::Event;

TEST(Macro, LoopSumsOneToTenAndMovesEachTime) {
  // #1 = 1; #100 = 0; WHILE [#1 LE 10] { #100 = #100 + #1; G01 X#1; #1 = #1 + 1 }
  // (the move is a constant here: motion with computed operands is a later instruction).
  MachineConfig machine = defaultMachine();
  Assembler a(test::xyzHeader());
  Assembler::Label top = a.newLabel();
  Assembler::Label done = a.newLabel();
  a.push(1.0).store(1).push(0.0).store(100);
  a.bind(top).load(1).push(10.0).op(Opcode::CmpLe).jump(Opcode::JumpIfFalse, done);
  a.load(100).load(1).op(Opcode::Add).store(100);
  a.line({5.0, 0.0, 0.0}, 100.0).line({0.0, 0.0, 0.0}, 100.0);
  a.load(1).push(1.0).op(Opcode::Add).store(1);
  a.jump(Opcode::Jump, top);
  a.bind(done).op(Opcode::End);
  bytecode::Program p = a.finish();
  vm::Executor executor(p, machine);
  std::vector<Event> events = test::runAll(executor, p);
  EXPECT_FALSE(executor.alarm());
  EXPECT_EQ(events.size(), 20u);
  EXPECT_EQ(executor.variable(100), 55.0);
  EXPECT_EQ(executor.variable(1), 11.0);
  const std::vector<std::pair<std::string, double>> expected = {{"#1", 11.0}, {"#100", 55.0}};
  EXPECT_EQ(executor.variables(), expected);
}

TEST(Macro, VacantFollowsMacroBRules) {
  MachineConfig machine = defaultMachine();
  Assembler a(test::xyzHeader());
  a.load(2).store(3);                                  // #3 = #2        -> vacant
  a.load(2).push(5.0).op(Opcode::Mul).store(4);        // #4 = #2 * 5    -> 0
  a.load(2).op(Opcode::PushVacant).op(Opcode::CmpEq).store(5);  // #2 EQ #0 -> true
  a.load(2).push(0.0).op(Opcode::CmpEq).store(6);      // #2 EQ 0        -> false
  a.load(2).push(0.0).op(Opcode::CmpGe).store(7);      // #2 GE 0        -> true (vacant = 0)
  a.load(2).push(0.0).op(Opcode::CmpNe).store(8);      // #2 NE 0        -> true
  a.push(7.0).op(Opcode::Neg).store(9);                // -7
  a.push(1.0).store(10).op(Opcode::PushVacant).store(10);  // assigning vacant clears #10
  a.push(9.0).push(4.0).op(Opcode::Sub).store(11);     // 5
  a.push(9.0).push(4.0).op(Opcode::Div).store(12);     // 2.25
  a.push(3.0).push(4.0).op(Opcode::CmpLt).store(13);   // true
  a.push(3.0).push(4.0).op(Opcode::CmpGt).store(14);   // false
  a.push(4.0).push(4.0).op(Opcode::CmpLe).store(15);   // true
  a.push(1.0).op(Opcode::Pop).op(Opcode::End);
  bytecode::Program p = a.finish();
  vm::Executor executor(p, machine);
  test::runAll(executor, p);
  ASSERT_FALSE(executor.alarm());
  EXPECT_EQ(executor.variable(3), std::nullopt);
  EXPECT_EQ(executor.variable(4), 0.0);
  EXPECT_EQ(executor.variable(5), 1.0);
  EXPECT_EQ(executor.variable(6), 0.0);
  EXPECT_EQ(executor.variable(7), 1.0);
  EXPECT_EQ(executor.variable(8), 1.0);
  EXPECT_EQ(executor.variable(9), -7.0);
  EXPECT_EQ(executor.variable(10), std::nullopt);
  EXPECT_EQ(executor.variable(11), 5.0);
  EXPECT_EQ(executor.variable(12), 2.25);
  EXPECT_EQ(executor.variable(13), 1.0);
  EXPECT_EQ(executor.variable(14), 0.0);
  EXPECT_EQ(executor.variable(15), 1.0);
  EXPECT_EQ(executor.variable(0), std::nullopt);
  EXPECT_EQ(executor.variable(999999), std::nullopt);
}

TEST(Macro, VacantConditionIsFalse) {
  MachineConfig machine = defaultMachine();
  Assembler a(test::xyzHeader());
  Assembler::Label skip = a.newLabel();
  a.load(1).jump(Opcode::JumpIfFalse, skip).push(1.0).store(2);
  a.bind(skip).op(Opcode::End);
  bytecode::Program p = a.finish();
  vm::Executor executor(p, machine);
  test::runAll(executor, p);
  EXPECT_EQ(executor.variable(2), std::nullopt);
}

TEST(Macro, DivisionByZeroIsAnAlarmAtItsLine) {
  MachineConfig machine = defaultMachine();
  Assembler a(test::xyzHeader());
  a.at(1, 1).push(1.0).store(1);
  a.at(1, 8, 5).push(1.0).load(2).op(Opcode::Div).store(3);  // #2 vacant: divides by 0
  a.at(1, 9).push(1.0).store(4).op(Opcode::End);
  bytecode::Program p = a.finish();
  vm::Executor executor(p, machine);
  test::runAll(executor, p);
  ASSERT_TRUE(executor.alarm());
  EXPECT_EQ(executor.alarm()->code, "NCC7202");
  EXPECT_EQ(executor.alarm()->where, (SourceLocation{1, 8, 5}));
  EXPECT_EQ(executor.variable(1), 1.0);
  EXPECT_EQ(executor.variable(4), std::nullopt);  // nothing after the alarm ran
}

TEST(Macro, OverflowIsAnAlarm) {
  MachineConfig machine = defaultMachine();
  Assembler a(test::xyzHeader());
  a.push(std::numeric_limits<double>::max()).push(10.0).op(Opcode::Mul).store(1).op(Opcode::End);
  bytecode::Program p = a.finish();
  vm::Executor executor(p, machine);
  test::runAll(executor, p);
  ASSERT_TRUE(executor.alarm());
  EXPECT_EQ(executor.alarm()->code, "NCC7203");
}

}  // namespace
}  // namespace ncc
