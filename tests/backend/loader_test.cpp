// The loader rejects every malformed container with a precise code.
#include "ncc/bytecode/loader.h"

#include "gtest/gtest.h"
#include "test_programs.h"

namespace ncc {
namespace {

std::string loadError(const std::vector<uint8_t>& bytes) {
  bytecode::Program program;
  std::optional<bytecode::Error> e = bytecode::load(bytes, program);
  return e ? e->code + ": " + e->message : "ok";
}

void putU32(std::vector<uint8_t>& b, size_t at, uint32_t v) {
  for (int i = 0; i < 4; ++i) b[at + i] = static_cast<uint8_t>(v >> (8 * i));
}

TEST(Loader, LoadsWhatTheWriterWrote) {
  bytecode::Program original = test::smallProgram();
  original.header.axes.push_back({"C", AxisKind::Rotary});  // header with a rotary axis
  original.header.config_hash = 0x0123456789ABCDEFull;
  original.header.dialect = Dialect::SiemensIsoM;
  // The code was assembled for three axes; give it a matching four-axis body.
  bytecode::Assembler a(original.header);
  a.at(1, 7, 3).rapid({1.0, 2.0, 3.0, 90.0}).op(bytecode::Opcode::End);
  original = a.finish({"", "prog.nc", "sub.nc"});
  bytecode::Program loaded;
  ASSERT_FALSE(bytecode::load(test::serialise(original), loaded));
  EXPECT_EQ(loaded.header, original.header);
  EXPECT_EQ(loaded.strings, original.strings);
  EXPECT_EQ(loaded.code, original.code);
  EXPECT_EQ(loaded.lines, original.lines);
  EXPECT_EQ(loaded.units, original.units);
}

TEST(Loader, HeaderBytesAreTheDocumentedLayout) {
  std::vector<uint8_t> b = test::serialise(test::smallProgram());
  ASSERT_GE(b.size(), 56u + 3 * 16u);
  EXPECT_EQ(std::string(b.begin(), b.begin() + 4), "NCCB");
  EXPECT_EQ(b[4], 1);  // major, little-endian
  EXPECT_EQ(b[5], 0);
  EXPECT_EQ(b[9], 3);  // axis count
  EXPECT_EQ(b[24], 56 + 3 * 16);  // code section offset = header size
  EXPECT_EQ(b[56], 0);    // axis X: linear
  EXPECT_EQ(b[57], 1);    // name length
  EXPECT_EQ(b[58], 'X');
  EXPECT_EQ(b[104], static_cast<uint8_t>(bytecode::Opcode::Rapid));  // first instruction
}

TEST(Loader, RejectsShortFile) {
  EXPECT_EQ(loadError({'N', 'C', 'C', 'B'}).substr(0, 7), "NCC7001");
  EXPECT_EQ(loadError({}).substr(0, 7), "NCC7001");
}

TEST(Loader, RejectsBadMagic) {
  std::vector<uint8_t> b = test::serialise(test::smallProgram());
  b[0] = 'X';
  EXPECT_EQ(loadError(b).substr(0, 7), "NCC7002");
}

TEST(Loader, RejectsOtherMajorVersion) {
  std::vector<uint8_t> b = test::serialise(test::smallProgram());
  b[4] = 2;
  EXPECT_EQ(loadError(b).substr(0, 7), "NCC7003");
}

TEST(Loader, RejectsBadHeaderFields) {
  std::vector<uint8_t> b = test::serialise(test::smallProgram());
  std::vector<uint8_t> dialect = b;
  dialect[8] = 77;
  EXPECT_EQ(loadError(dialect).substr(0, 7), "NCC7004");
  std::vector<uint8_t> axes = b;
  axes[9] = 0;
  EXPECT_EQ(loadError(axes).substr(0, 7), "NCC7004");
  axes[9] = 10;
  EXPECT_EQ(loadError(axes).substr(0, 7), "NCC7004");
  std::vector<uint8_t> vars = b;
  putU32(vars, 12, 0);
  EXPECT_EQ(loadError(vars).substr(0, 7), "NCC7004");
  putU32(vars, 12, 100001);
  EXPECT_EQ(loadError(vars).substr(0, 7), "NCC7004");
}

TEST(Loader, RejectsBadAxisEntries) {
  std::vector<uint8_t> b = test::serialise(test::smallProgram());
  std::vector<uint8_t> kind = b;
  kind[56] = 2;
  EXPECT_EQ(loadError(kind).substr(0, 7), "NCC7005");
  std::vector<uint8_t> duplicate = b;
  duplicate[56 + 16 + 2] = 'X';  // second axis also named X
  EXPECT_EQ(loadError(duplicate), "NCC7005: axis table entry 1: axis name 'X' repeated");
  std::vector<uint8_t> padding = b;
  padding[56 + 5] = 'Q';  // garbage after the name
  EXPECT_EQ(loadError(padding).substr(0, 7), "NCC7005");
}

TEST(Loader, RejectsSectionsThatDoNotTileTheFile) {
  std::vector<uint8_t> b = test::serialise(test::smallProgram());
  std::vector<uint8_t> trailing = b;
  trailing.push_back(0);
  EXPECT_EQ(loadError(trailing), "NCC7006: 1 bytes after the last section");
  std::vector<uint8_t> truncated(b.begin(), b.end() - 1);
  EXPECT_EQ(loadError(truncated).substr(0, 7), "NCC7006");
  std::vector<uint8_t> huge = b;
  putU32(huge, 28, 0xFFFFFFF0u);  // code size
  EXPECT_EQ(loadError(huge).substr(0, 7), "NCC7006");
  std::vector<uint8_t> gap = b;
  putU32(gap, 24, 200);  // code offset
  EXPECT_EQ(loadError(gap).substr(0, 7), "NCC7006");
}

TEST(Loader, RejectsMalformedStringPool) {
  bytecode::Program p = test::smallProgram();
  std::vector<uint8_t> b = test::serialise(p);
  // String section offset is at header bytes 40..43.
  const uint32_t strings = b[40] | (b[41] << 8) | (b[42] << 16) | (b[43] << 24);
  std::vector<uint8_t> count = b;
  putU32(count, strings, 1000);
  EXPECT_EQ(loadError(count).substr(0, 7), "NCC7007");
  std::vector<uint8_t> length = b;
  putU32(length, strings + 4 + 4, 0x7FFFFFFF);  // string 1 ("" is string 0, 4 bytes)
  EXPECT_EQ(loadError(length).substr(0, 7), "NCC7007");
}

TEST(Loader, RejectsLineTableOfPartialEntries) {
  std::vector<uint8_t> b = test::serialise(test::smallProgram());
  // Move one byte from the line table to the string pool: both sizes still tile the file.
  const uint32_t line_size = b[36] | (b[37] << 8);
  putU32(b, 36, line_size - 1);
  const uint32_t strings = b[40] | (b[41] << 8);
  putU32(b, 40, strings - 1);
  const uint32_t strings_size = b[44] | (b[45] << 8);
  putU32(b, 44, strings_size + 1);
  EXPECT_EQ(loadError(b).substr(0, 7), "NCC7008");
}

TEST(Loader, RejectsMissingUnits) {
  bytecode::Program p = test::smallProgram();
  p.units.clear();
  EXPECT_EQ(loadError(test::serialise(p)), "NCC7009: unit table: no program unit");
}

TEST(Loader, ReportsUnreadableFile) {
  bytecode::Program p;
  std::optional<bytecode::Error> e = bytecode::loadFile("/nonexistent/x.ncb", p);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code, "NCC7015");
}

}  // namespace
}  // namespace ncc
