// The loader rejects every malformed container with a precise code.
#include "ncc/bytecode/loader.h"

#include "ncc/bytecode/checksum.h"

#include "gtest/gtest.h"
#include "test_programs.h"

namespace ncc {
namespace {

std::string loadError(const std::vector<uint8_t>& bytes) {
  bytecode::Program program;
  std::optional<bytecode::Error> e = bytecode::load(bytes, program);
  return e ? e->code + ": " + e->message : "ok";
}

// A file edited on purpose, with its checksum written anew so that the edit reaches the check
// behind the checksum.
std::string tamperedError(std::vector<uint8_t> bytes) {
  if (bytes.size() >= bytecode::kFixedHeaderSize) bytecode::sealChecksum(bytes);
  return loadError(bytes);
}

void putU32(std::vector<uint8_t>& b, size_t at, uint32_t v) {
  ASSERT_LE(at + 4, b.size());  // a test that edits past the file is itself wrong
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
  ASSERT_GE(b.size(), 64u + 3 * 16u);
  EXPECT_EQ(std::string(b.begin(), b.begin() + 4), "NCCB");
  EXPECT_EQ(b[4], 2);  // major, little-endian
  EXPECT_EQ(b[5], 0);
  EXPECT_EQ(b[6], 3);  // minor (2.1: SKIP, 2.2: PREPARE and the block store, 2.3: names)
  EXPECT_EQ(b[9], 3);  // axis count
  EXPECT_EQ(b[24], 64 + 3 * 16);  // code section offset = header size
  EXPECT_EQ(bytecode::storedChecksum(b), bytecode::fileChecksum(b));
  EXPECT_NE(bytecode::storedChecksum(b), 0u);
  EXPECT_EQ(b[64], 0);    // axis X: linear
  EXPECT_EQ(b[65], 1);    // name length
  EXPECT_EQ(b[66], 'X');
  EXPECT_EQ(b[112], static_cast<uint8_t>(bytecode::Opcode::Rapid));  // first instruction
}

TEST(Loader, ChecksumIsFnv1aOverBodyThenFixedHeader) {
  std::vector<uint8_t> b = test::serialise(test::smallProgram());
  // The documented definition, written out independently of checksum.cpp.
  uint64_t h = 0xCBF29CE484222325ull;
  auto step = [&h](uint8_t byte) { h = (h ^ byte) * 0x100000001B3ull; };
  for (size_t i = 64; i < b.size(); ++i) step(b[i]);
  for (size_t i = 0; i < 64; ++i) step(i >= 56 ? 0 : b[i]);
  uint64_t stored = 0;
  for (int i = 7; i >= 0; --i) stored = (stored << 8) | b[56 + i];
  EXPECT_EQ(stored, h);
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

// 2.1 only added SKIP, 2.2 PREPARE and the block store: 2.0 and 2.1 files (the same bytes,
// minor 0 or 1) still load; a newer minor is refused, since it may hold opcodes this loader
// does not know.
TEST(Loader, ReadsOlderMinorRefusesNewer) {
  std::vector<uint8_t> b = test::serialise(test::smallProgram());
  // Before 2.3 the unit section ends with the units: drop the (empty) name table, the file's
  // last 4 bytes here (no block store), from the section.
  std::vector<uint8_t> older(b.begin(), b.end() - 4);
  const uint32_t units_size = older[52] | older[53] << 8 | older[54] << 16 | older[55] << 24;
  older[52] = static_cast<uint8_t>(units_size - 4);
  for (uint8_t minor : {0, 1, 2}) {
    older[6] = minor;
    bytecode::sealChecksum(older);
    EXPECT_EQ(loadError(older), "ok");
  }
  // An older file with the 2.3 name table is one with bytes after its units.
  b[6] = 2;
  bytecode::sealChecksum(b);
  EXPECT_EQ(loadError(b).substr(0, 7), "NCC7009");
  b[6] = 4;
  bytecode::sealChecksum(b);
  EXPECT_EQ(loadError(b).substr(0, 7), "NCC7003");
}

// Since 2.2 the bytes after the unit table are the block store; before, they are refused.
TEST(Loader, BytesAfterTheUnitsAreTheBlockStoreSince22) {
  std::vector<uint8_t> b = test::serialise(test::smallProgram());
  b.insert(b.end(), {'N', 'C', 'B', 'S'});
  bytecode::sealChecksum(b);
  bytecode::Program loaded;
  ASSERT_FALSE(bytecode::load(b, loaded).has_value());
  EXPECT_EQ(loaded.blocks, (std::vector<uint8_t>{'N', 'C', 'B', 'S'}));
  b[6] = 1;
  bytecode::sealChecksum(b);
  EXPECT_EQ(loadError(b), "NCC7006: 4 bytes after the last section");
  // The writer puts them there.
  bytecode::Program with_store = test::smallProgram();
  with_store.blocks = {1, 2, 3};
  bytecode::Program back;
  ASSERT_FALSE(bytecode::load(test::serialise(with_store), back).has_value());
  EXPECT_EQ(back.blocks, with_store.blocks);
}

TEST(Loader, RejectsOtherMajorVersion) {
  std::vector<uint8_t> b = test::serialise(test::smallProgram());
  b[4] = 1;  // a 1.x file: no checksum, refused by version
  EXPECT_EQ(loadError(b).substr(0, 7), "NCC7003");
  b[4] = 3;
  EXPECT_EQ(loadError(b).substr(0, 7), "NCC7003");
}

TEST(Loader, RejectsEveryChangedByte) {
  // FNV-1a detects any single changed byte, so every flip of every bit is refused: by the
  // magic or version check in the first 8 bytes, by the checksum everywhere else.
  const std::vector<uint8_t> b = test::serialise(test::smallProgram());
  for (size_t i = 0; i < b.size(); ++i) {
    for (int bit = 0; bit < 8; ++bit) {
      std::vector<uint8_t> flipped = b;
      flipped[i] ^= static_cast<uint8_t>(1u << bit);
      const std::string code = loadError(flipped).substr(0, 7);
      // Clearing bit 0 or 1 of the minor (3) makes a 2.2 or 2.1 header, a version this loader
      // reads: the checksum refuses it.
      const bool older_minor = i == 6 && bit <= 1;
      const char* expected = i < 4 ? "NCC7002" : i < 8 && !older_minor ? "NCC7003" : "NCC7016";
      ASSERT_EQ(code, expected) << "byte " << i << " bit " << bit;
    }
  }
  std::vector<uint8_t> zeroed = b;
  zeroed[100] = 0;
  zeroed[101] = 0xFF;
  EXPECT_EQ(loadError(zeroed).substr(0, 7), "NCC7016");
}

TEST(Loader, RejectsBadHeaderFields) {
  std::vector<uint8_t> b = test::serialise(test::smallProgram());
  std::vector<uint8_t> dialect = b;
  dialect[8] = 77;
  EXPECT_EQ(tamperedError(dialect).substr(0, 7), "NCC7004");
  std::vector<uint8_t> axes = b;
  axes[9] = 0;
  EXPECT_EQ(tamperedError(axes).substr(0, 7), "NCC7004");
  axes[9] = 10;
  EXPECT_EQ(tamperedError(axes).substr(0, 7), "NCC7004");
  std::vector<uint8_t> vars = b;
  putU32(vars, 12, 0);
  EXPECT_EQ(tamperedError(vars).substr(0, 7), "NCC7004");
  putU32(vars, 12, 100001);
  EXPECT_EQ(tamperedError(vars).substr(0, 7), "NCC7004");
}

TEST(Loader, RejectsBadAxisEntries) {
  std::vector<uint8_t> b = test::serialise(test::smallProgram());
  std::vector<uint8_t> kind = b;
  kind[64] = 2;
  EXPECT_EQ(tamperedError(kind).substr(0, 7), "NCC7005");
  std::vector<uint8_t> duplicate = b;
  duplicate[64 + 16 + 2] = 'X';  // second axis also named X
  EXPECT_EQ(tamperedError(duplicate), "NCC7005: axis table entry 1: axis name 'X' repeated");
  std::vector<uint8_t> padding = b;
  padding[64 + 5] = 'Q';  // garbage after the name
  EXPECT_EQ(tamperedError(padding).substr(0, 7), "NCC7005");
}

TEST(Loader, RejectsSectionsThatDoNotTileTheFile) {
  std::vector<uint8_t> b = test::serialise(test::smallProgram());
  std::vector<uint8_t> trailing = b;
  trailing[6] = 1;  // 2.1: nothing after the units (since 2.2 the block store is there)
  trailing.push_back(0);
  EXPECT_EQ(tamperedError(trailing), "NCC7006: 1 bytes after the last section");
  std::vector<uint8_t> truncated(b.begin(), b.end() - 1);
  EXPECT_EQ(tamperedError(truncated).substr(0, 7), "NCC7006");
  std::vector<uint8_t> huge = b;
  putU32(huge, 28, 0xFFFFFFF0u);  // code size
  EXPECT_EQ(tamperedError(huge).substr(0, 7), "NCC7006");
  std::vector<uint8_t> gap = b;
  putU32(gap, 24, 200);  // code offset
  EXPECT_EQ(tamperedError(gap).substr(0, 7), "NCC7006");
}

TEST(Loader, RejectsMalformedStringPool) {
  bytecode::Program p = test::smallProgram();
  std::vector<uint8_t> b = test::serialise(p);
  // String section offset is at header bytes 40..43.
  const uint32_t strings = b[40] | (b[41] << 8) | (b[42] << 16) | (b[43] << 24);
  std::vector<uint8_t> count = b;
  putU32(count, strings, 1000);
  EXPECT_EQ(tamperedError(count).substr(0, 7), "NCC7007");
  std::vector<uint8_t> length = b;
  putU32(length, strings + 4 + 4, 0x7FFFFFFF);  // string 1 ("" is string 0, 4 bytes)
  EXPECT_EQ(tamperedError(length).substr(0, 7), "NCC7007");
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
  EXPECT_EQ(tamperedError(b).substr(0, 7), "NCC7008");
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
