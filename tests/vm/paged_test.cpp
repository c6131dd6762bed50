// The executor runs a paged program (bytecode::loadPaged: code and line table read from the
// file through bounded windows) exactly as the same program in memory: the same events at the
// same source positions, across many windows and a loop that jumps back over all of them.
#include <unistd.h>

#include <cstdlib>
#include <sstream>

#include "gtest/gtest.h"
#include "ncc/bytecode/loader.h"
#include "ncc/bytecode/program_file.h"
#include "ncc/bytecode/writer.h"
#include "run.h"

namespace ncc {
namespace {

using bytecode::Assembler;
using bytecode::Opcode;

bytecode::Program paged(const bytecode::Program& program) {
  std::ostringstream out;
  EXPECT_EQ(bytecode::write(program, out), std::nullopt);
  const std::string bytes = out.str();
  char name[] = "/tmp/ncc-vm-paged-XXXXXX";
  const int fd = mkstemp(name);
  unlink(name);
  EXPECT_EQ(::write(fd, bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
  bytecode::Program loaded;
  EXPECT_EQ(bytecode::loadPaged(bytecode::ProgramFile::adopt(fd), loaded), std::nullopt);
  EXPECT_TRUE(loaded.paged.has_value());
  return loaded;
}

TEST(Paged, ExecutorRunsAPagedProgramLikeTheSameInMemory) {
  // #1 = 0; top: 30,000 LINEs (1 MB of code, 480 KB of line table); #1 = #1 + 1;
  // if #1 < 3 goto top; M30.
  Assembler a(test::xyzHeader());
  Assembler::Label top = a.newLabel(), done = a.newLabel();
  a.at(1, 1).push(0.0).store(1);
  a.bind(top);
  for (int i = 0; i < 30000; ++i) a.at(1, 2 + i).line({(i % 100) * 0.1, (i % 7) * 1.0, 0.0}, 500.0);
  a.at(1, 40000).load(1).push(1.0).op(Opcode::Add).store(1);
  a.load(1).push(3.0).op(Opcode::CmpLt).jump(Opcode::JumpIfFalse, done);
  a.jump(Opcode::Jump, top);
  a.bind(done).at(1, 40001).op(Opcode::ProgramEndRewind);
  const bytecode::Program memory = a.finish();
  const bytecode::Program file = paged(memory);

  MachineConfig machine = defaultMachine();
  vm::Executor from_memory(memory, machine), from_file(file, machine);
  const std::vector<vm::Event> expected = test::runAll(from_memory, memory);
  const std::vector<vm::Event> got = test::runAll(from_file, file);
  ASSERT_EQ(got.size(), expected.size());
  ASSERT_GT(expected.size(), 3u * 29000u);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    ASSERT_EQ(got[i].kind, expected[i].kind) << i;
    if (expected[i].kind == vm::Event::Kind::Motion) {
      ASSERT_EQ(got[i].motion.to, expected[i].motion.to) << i;
      ASSERT_EQ(got[i].motion.where.line, expected[i].motion.where.line) << i;
    } else {
      ASSERT_EQ(got[i].machine.code, expected[i].machine.code) << i;
      ASSERT_EQ(got[i].machine.where.line, expected[i].machine.where.line) << i;
    }
  }
  EXPECT_EQ(from_file.variable(1), std::optional<double>(3.0));
  EXPECT_EQ(from_file.alarm(), std::nullopt);
}

}  // namespace
}  // namespace ncc
