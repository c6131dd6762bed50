// A paged program (loader.h, loadPaged) reads the same code and line entries through
// CodeView's bounded windows as an in-memory one, whatever the order of the reads; and the
// paged loader refuses what the in-memory loader refuses.
#include <random>

#include "gtest/gtest.h"
#include "ncc/bytecode/checksum.h"
#include "ncc/bytecode/code_view.h"
#include "ncc/bytecode/loader.h"
#include "ncc/bytecode/verifier.h"
#include "test_programs.h"

namespace ncc {
namespace {

using bytecode::Assembler;
using bytecode::CodeView;
using bytecode::Opcode;

// Many windows of code and of line table: 40,000 LINEs of 34 bytes (1.3 MB) with a loop back
// over all of them and a line entry each.
bytecode::Program longProgram() {
  Assembler a(test::xyzHeader());
  Assembler::Label top = a.newLabel();
  a.at(1, 1).push(0.0).store(1);
  a.bind(top);
  for (int i = 0; i < 40000; ++i) a.at(1, 2 + i).line({i * 0.001, (i % 7) * 0.01, 0.0}, 1000.0);
  a.at(1, 50000).load(1).push(1.0).op(Opcode::Add).store(1);
  a.load(1).push(2.0).op(Opcode::CmpLt).jump(Opcode::JumpIfFalse, top);  // back to the top once
  a.at(1, 50001).op(Opcode::ProgramEndRewind);
  return a.finish();
}

TEST(Paged, LongProgramLoadsAndVerifiesLikeInMemory) {
  const bytecode::Program memory = longProgram();
  ASSERT_GT(memory.code.size(), 4 * CodeView::kPageSize);
  std::optional<bytecode::Program> file = test::paged(memory);
  ASSERT_TRUE(file.has_value());
  ASSERT_TRUE(file->paged.has_value());
  EXPECT_TRUE(file->code.empty());
  EXPECT_TRUE(file->lines.empty());
  EXPECT_EQ(file->codeSize(), memory.code.size());
  EXPECT_EQ(file->paged->line_count, memory.lines.size());
  EXPECT_EQ(file->header, memory.header);
  EXPECT_EQ(file->strings, memory.strings);
  EXPECT_EQ(file->units, memory.units);
  EXPECT_EQ(bytecode::verify(memory), std::nullopt);
  EXPECT_EQ(bytecode::verify(*file), std::nullopt);
}

TEST(Paged, ReadsTheSameInstructionsAndLinesInAnyOrder) {
  const bytecode::Program memory = longProgram();
  std::optional<bytecode::Program> file = test::paged(memory);
  ASSERT_TRUE(file.has_value());
  CodeView in_memory(memory), paged(*file);
  // Every instruction start and its line, forward, as the executor reads.
  std::vector<uint32_t> starts;
  std::size_t forward_hint = 0;
  for (uint32_t offset = 0; offset < memory.code.size();) {
    const bytecode::LineEntry* expected = memory.lineFor(offset);
    ASSERT_NE(expected, nullptr);
    ASSERT_EQ(paged.lineFor(offset, forward_hint), *expected) << offset;
    bytecode::Instruction a, b;
    uint32_t size_a = 0, size_b = 0;
    ASSERT_EQ(in_memory.decode(offset, 3, a, size_a), bytecode::DecodeStatus::Ok);
    ASSERT_EQ(paged.decode(offset, 3, b, size_b), bytecode::DecodeStatus::Ok);
    ASSERT_EQ(size_a, size_b);
    ASSERT_EQ(a.op, b.op);
    ASSERT_EQ(a.axes, b.axes);
    starts.push_back(offset);
    offset += size_a;
  }
  // Random offsets (jumps far back and forth): instructions, line entries and lineFor.
  std::mt19937 random(21);
  std::size_t hint_a = 0, hint_b = 0;
  for (int k = 0; k < 2000; ++k) {
    const uint32_t offset = starts[random() % starts.size()];
    bytecode::Instruction a, b;
    uint32_t size_a = 0, size_b = 0;
    in_memory.decode(offset, 3, a, size_a);
    paged.decode(offset, 3, b, size_b);
    ASSERT_EQ(a.axes, b.axes) << offset;
    ASSERT_EQ(in_memory.lineFor(offset, hint_a), paged.lineFor(offset, hint_b)) << offset;
    const std::size_t i = random() % memory.lines.size();
    ASSERT_EQ(paged.line(i), memory.lines[i]);
  }
  // The code's end cuts an instruction short, in memory and paged alike.
  bytecode::Instruction in;
  uint32_t size = 0;
  EXPECT_EQ(paged.decode(file->codeSize(), 3, in, size), bytecode::DecodeStatus::Truncated);
  EXPECT_EQ(paged.line(memory.lines.size()), std::nullopt);
}

TEST(Paged, RefusesWhatTheInMemoryLoaderRefuses) {
  const std::vector<uint8_t> good = test::serialise(test::smallProgram());
  auto both = [](std::vector<uint8_t> bytes) {
    bytecode::Program p;
    std::optional<bytecode::Error> memory = bytecode::load(bytes, p);
    char name[] = "/tmp/ncc-paged-test-XXXXXX";
    const int fd = mkstemp(name);
    unlink(name);
    EXPECT_EQ(::write(fd, bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
    std::optional<bytecode::Error> paged =
        bytecode::loadPaged(bytecode::ProgramFile::adopt(fd), p);
    EXPECT_EQ(memory.has_value(), paged.has_value());
    if (memory && paged) {
      EXPECT_EQ(memory->code, paged->code);
      EXPECT_EQ(memory->message, paged->message);
    }
    return paged ? paged->code : std::string("ok");
  };
  EXPECT_EQ(both(good), "ok");
  std::vector<uint8_t> flipped = good;
  flipped[flipped.size() / 2] ^= 0x10;  // one bit, anywhere: the streamed checksum sees it
  EXPECT_EQ(both(flipped), "NCC7016");
  std::vector<uint8_t> cut(good.begin(), good.end() - 3);
  bytecode::sealChecksum(cut);
  EXPECT_EQ(both(cut), "NCC7006");
  EXPECT_EQ(both(std::vector<uint8_t>(good.begin(), good.begin() + 20)), "NCC7001");
  std::vector<uint8_t> magic = good;
  magic[0] = 'X';
  EXPECT_EQ(both(magic), "NCC7002");
}

TEST(Paged, MissingFileIsNCC7015) {
  bytecode::Program p;
  std::optional<bytecode::Error> e = bytecode::loadFilePaged("/nonexistent/x.ncb", p);
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->code, "NCC7015");
}

}  // namespace
}  // namespace ncc
