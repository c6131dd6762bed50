// The encoder streams: heap use does not grow with the number of blocks, and a long program
// still loads, verifies and maps every instruction back to its line.
#include <malloc.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "gtest/gtest.h"
#include "ncc/backend/bytecode_writer.h"
#include "ncc/bytecode/loader.h"
#include "ncc/bytecode/verifier.h"

namespace ncc {
namespace {

ir::Block lineBlock(uint32_t file, uint32_t line) {
  ir::Block b;
  b.loc = SourceLocation{file, line, 1};
  const double x = static_cast<double>(line % 1000);
  b.ops.push_back(ir::Linear{{x, -x, 1.0}, ir::Space::Machine, 500.0, false});
  return b;
}

size_t heapInUse() { return mallinfo2().uordblks; }

TEST(Streaming, HeapDoesNotGrowWithProgramLength) {
  // One file per process: two test runs on one machine (a CI clone next to a build) must not
  // write and remove each other's file.
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("ncc_streaming_test_" + std::to_string(::getpid()) + ".ncb");
  MachineConfig machine = defaultMachine();
  SourceManager sources;
  const uint32_t file = sources.addBuffer("long.nc", "");
  constexpr uint32_t kBlocks = 200000;
  size_t after_warmup = 0;
  size_t at_end = 0;
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    backend::BytecodeWriter writer(out, machine, Dialect::FanucM, sources);
    for (uint32_t line = 1; line <= kBlocks; ++line) {
      writer.accept(lineBlock(file, line));
      if (line == 1000) after_warmup = heapInUse();
    }
    at_end = heapInUse();
    writer.finish();
    ASSERT_TRUE(writer.ok());
  }
  // 199,000 more blocks are ~13 MB of code and ~3 MB of line table, all outside the heap.
  EXPECT_LT(at_end, after_warmup + 64 * 1024);

  bytecode::Program program;
  std::optional<bytecode::Error> e = bytecode::loadFile(path, program);
  ASSERT_FALSE(e) << e->message;
  e = bytecode::verify(program);
  ASSERT_FALSE(e) << e->message;
  EXPECT_EQ(program.lines.size(), kBlocks);
  const uint32_t last_line_offset = program.lines.back().offset;
  ASSERT_NE(program.lineFor(last_line_offset), nullptr);
  EXPECT_EQ(program.lineFor(last_line_offset)->line, kBlocks);
  EXPECT_EQ(program.lineFor(last_line_offset - 1)->line, kBlocks - 1);
  std::filesystem::remove(path);
}

TEST(Streaming, RepeatedLocationAddsNoLineEntry) {
  MachineConfig machine = defaultMachine();
  SourceManager sources;
  const uint32_t file = sources.addBuffer("p.nc", "");
  std::ostringstream out;
  backend::BytecodeWriter writer(out, machine, Dialect::FanucM, sources);
  writer.accept(lineBlock(file, 5));
  writer.accept(lineBlock(file, 5));  // e.g. two blocks expanded from one source line
  writer.accept(lineBlock(file, 6));
  writer.finish();
  const std::string s = out.str();
  bytecode::Program program;
  ASSERT_FALSE(bytecode::load(std::vector<uint8_t>(s.begin(), s.end()), program));
  ASSERT_EQ(program.lines.size(), 2u);
  EXPECT_EQ(program.lines[0].line, 5u);
  EXPECT_EQ(program.lines[1].line, 6u);
}

}  // namespace
}  // namespace ncc
