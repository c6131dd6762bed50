// After construction, running the program allocates nothing (real-time discipline).
#include "allocation_counter.h"

#include "gtest/gtest.h"
#include "run.h"

namespace ncc {
namespace {

using bytecode::Assembler;
using bytecode::Opcode;

TEST(Allocation, NextAllocatesNothing) {
  MachineConfig machine = defaultMachine();
  Assembler a(test::xyzHeader());
  Assembler::Label top = a.newLabel();
  Assembler::Label done = a.newLabel();
  a.at(1, 1).push(0.0).store(1);
  a.bind(top).at(1, 2).load(1).push(100.0).op(Opcode::CmpLt).jump(Opcode::JumpIfFalse, done);
  a.at(1, 3).line({10.0, 0.0, 0.0}, 500.0).arc({0.0, 0.0, 0.0}, 0, 1, 5.0, 0.0, 500.0, 0);
  a.at(1, 4).spindleSpeed(1000.0).op(Opcode::SpindleCW).dwell(0.5);
  a.at(1, 5).load(1).push(1.0).op(Opcode::Add).store(1).jump(Opcode::Jump, top);
  a.bind(done).at(1, 6).refCheck(0b111, 1, {0.0, 0.0, 0.0}).op(Opcode::ProgramEndRewind);
  bytecode::Program p = a.finish();
  ASSERT_FALSE(bytecode::verify(p));

  vm::Executor executor(p, machine);
  vm::Event event;
  long events = 0;
  const long before = test::allocationCount();
  while (executor.next(event)) ++events;
  const long during = test::allocationCount() - before;
  EXPECT_EQ(during, 0);
  EXPECT_EQ(events, 100 * 5 + 1);
  EXPECT_FALSE(executor.alarm());
}

}  // namespace
}  // namespace ncc
