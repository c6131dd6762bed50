// IR SetVariable -> bytecode (PUSH or PUSH_VACANT, then STORE) -> the VM: the variable holds
// what the program wrote, in program order among the moves.
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "gtest/gtest.h"
#include "ncc/backend/bytecode_writer.h"
#include "ncc/bytecode/disassembler.h"
#include "ncc/bytecode/instruction.h"
#include "ncc/bytecode/loader.h"
#include "ncc/bytecode/verifier.h"
#include "ncc/vm/executor.h"

namespace ncc {
namespace {

ir::Block block(uint32_t file, uint32_t line, ir::Operations ops) {
  ir::Block b;
  b.loc = SourceLocation{file, line, 1};
  b.ops = std::move(ops);
  return b;
}

// #100 = 2.5, #101 = 7, a move, #101 = #0 (vacant again), #102 = -0.001, M30.
bytecode::Program compileAssignments(const MachineConfig& machine) {
  SourceManager sources;
  const uint32_t file = sources.addBuffer("vars.nc", "");
  DiagnosticEngine diags(&sources);
  std::ostringstream out;
  backend::BytecodeWriter writer(out, machine, Dialect::FanucM, sources, &diags);
  writer.accept(block(file, 1, {ir::SetVariable{100, 2.5, false, {}}}));
  writer.accept(block(file, 2, {ir::SetVariable{101, 7.0, false, {}},
                                ir::Rapid{{1.0, 2.0, 3.0}, ir::Space::Machine,
                                          ir::RapidType::Linear}}));
  writer.accept(block(file, 3, {ir::SetVariable{101, 0.0, true, {}},
                                ir::SetVariable{102, -0.001, false, {}}}));
  writer.accept(block(file, 4, {ir::MachineFunction{ir::MachineFunction::Kind::ProgramEndRewind}}));
  writer.finish();
  EXPECT_TRUE(writer.ok());
  EXPECT_TRUE(diags.diagnostics().empty());
  const std::string bytes = out.str();
  bytecode::Program program;
  std::optional<bytecode::Error> error = bytecode::load(
      std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()),
      program);
  EXPECT_FALSE(error) << error->code << ": " << error->message;
  return program;
}

TEST(SetVariable, CompilesToPushAndStore) {
  const MachineConfig machine = defaultMachine();
  const bytecode::Program program = compileAssignments(machine);
  bytecode::VerifyOptions options;
  options.machine = &machine;
  std::optional<bytecode::Error> error = bytecode::verify(program, options);
  ASSERT_FALSE(error) << error->code << ": " << error->message;

  std::vector<std::string> listed;
  for (uint32_t offset = 0; offset < program.code.size();) {
    bytecode::Instruction in;
    uint32_t size = 0;
    ASSERT_EQ(bytecode::decode(program.code, offset, program.axisCount(), in, size),
              bytecode::DecodeStatus::Ok);
    std::string text = bytecode::opcodeInfo(in.op).mnemonic;
    if (in.op == bytecode::Opcode::Push) text += " " + bytecode::formatNumber(in.value);
    if (in.op == bytecode::Opcode::Store) text += " #" + std::to_string(in.variable);
    listed.push_back(text);
    offset += size;
  }
  EXPECT_EQ(listed, (std::vector<std::string>{"PUSH 2.5", "STORE #100", "PUSH 7", "STORE #101",
                                              "RAPID", "PUSH_VACANT", "STORE #101",
                                              "PUSH -0.001", "STORE #102",
                                              "PROGRAM_END_REWIND", "END"}));
}

TEST(SetVariable, TheVmEndsWithTheVariablesSet) {
  const MachineConfig machine = defaultMachine();
  const bytecode::Program program = compileAssignments(machine);
  vm::Executor executor(program, machine);
  vm::Event event;
  int events = 0;
  while (executor.next(event)) ++events;
  ASSERT_FALSE(executor.alarm()) << executor.alarm()->code;
  EXPECT_TRUE(executor.finished());
  EXPECT_EQ(events, 2);  // the rapid and M30: an assignment is no event
  EXPECT_EQ(executor.variable(100), 2.5);
  EXPECT_EQ(executor.variable(101), std::nullopt);  // PUSH_VACANT made it vacant again
  EXPECT_EQ(executor.variable(102), -0.001);
  EXPECT_EQ(executor.variables(),
            (std::vector<std::pair<std::string, double>>{{"#100", 2.5}, {"#102", -0.001}}));
}

}  // namespace
}  // namespace ncc
