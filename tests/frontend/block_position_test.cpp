// BlockReader positions: lastPosition(), position() and seek() on files and in-memory buffers.
// After a seek, next() must return the very block (printed text and every location) that
// reading straight through returned.
#include <gtest/gtest.h>

#include "absl/strings/str_cat.h"
#include "ncc/frontend/block_reader.h"
#include "temp_dir.h"

namespace ncc::frontend {
namespace {

using testing::TempDir;

// The printed block and the line:column of the block and each word.
std::string describe(const ast::Block& b) {
  std::string out = printBlock(b);
  absl::StrAppend(&out, " @", b.loc.file, ":", b.loc.line, ":", b.loc.column);
  for (const ast::Word& w : b.words) absl::StrAppend(&out, " ", w.address.c_str(), w.loc.line, ":", w.loc.column);
  for (const ast::Statement& s : b.statements) absl::StrAppend(&out, " s", s.loc.line, ":", s.loc.column);
  return out;
}

struct Read {
  std::vector<std::string> blocks;
  std::vector<BlockPosition> positions;  // lastPosition() after each block
};

Read readAll(const SourceManager& sm, uint32_t file, ReaderOptions options = {}) {
  DiagnosticEngine diags(&sm);
  BlockReader reader(sm, file, diags, options);
  Read r;
  while (auto b = reader.next()) {
    r.blocks.push_back(describe(*b));
    r.positions.push_back(reader.lastPosition());
  }
  return r;
}

// Seeks to every position, in reverse order (each seek goes back), and compares.
void expectSeeksReproduce(const SourceManager& sm, uint32_t file, ReaderOptions options = {}) {
  const Read straight = readAll(sm, file, options);
  ASSERT_FALSE(straight.blocks.empty());
  DiagnosticEngine diags(&sm);
  BlockReader reader(sm, file, diags, options);
  for (size_t i = straight.positions.size(); i-- > 0;) {
    reader.seek(straight.positions[i]);
    auto b = reader.next();
    ASSERT_TRUE(b) << i;
    EXPECT_EQ(describe(*b), straight.blocks[i]) << "block " << i;
    EXPECT_EQ(reader.lastPosition(), straight.positions[i]);
    // and reading on from there continues as straight reading did
    if (i + 1 < straight.blocks.size()) {
      auto after = reader.next();
      ASSERT_TRUE(after);
      EXPECT_EQ(describe(*after), straight.blocks[i + 1]);
    }
  }
}

const char kProgram[] =
    "%\n"
    "O1000 (MAIN)\n"
    "N10 G0 X1. Y2.;N20 G1 X3.;  N30 Y4. (A;B) Z1;\n"
    "\n"
    "  N40 #1=#1+1\n"
    "/N50 IF [#1 LT 3] GOTO 40\n"
    "N60 M30\n"
    "%\n";

TEST(BlockPosition, PositionsOfBlocksSplitBySemicolon) {
  SourceManager sm;
  const uint32_t f = sm.addBuffer("p.nc", kProgram);
  const Read r = readAll(sm, f);
  ASSERT_EQ(r.blocks.size(), 9u);
  EXPECT_EQ(r.positions[0], (BlockPosition{0, 1, 1}));    // %
  EXPECT_EQ(r.positions[1], (BlockPosition{2, 2, 1}));    // O1000
  EXPECT_EQ(r.positions[2], (BlockPosition{15, 3, 1}));   // N10
  EXPECT_EQ(r.positions[3], (BlockPosition{15, 3, 16}));  // N20 after the first ';'
  EXPECT_EQ(r.positions[4], (BlockPosition{15, 3, 27}));  // "  N30": the blanks are the block's
  EXPECT_EQ(r.positions[5], (BlockPosition{62, 5, 1}));   // N40 after a blank line
  EXPECT_EQ(r.positions[8], (BlockPosition{110, 8, 1}));  // closing %
}

TEST(BlockPosition, SeekReproducesBlocksOfABuffer) {
  SourceManager sm;
  expectSeeksReproduce(sm, sm.addBuffer("p.nc", kProgram));
  ReaderOptions siemens;
  siemens.semicolon_ends_block = false;  // one block per line, ';' starts an annotation
  expectSeeksReproduce(sm, sm.addBuffer("s.nc", "N10 G1 X1 ; note\n; only a note\nN20 M30\n"),
                       siemens);
}

TEST(BlockPosition, SeekReproducesBlocksOfAFileWithCrLfAndByteOrderMark) {
  TempDir dir;
  std::string text = "\xEF\xBB\xBFN1 G0 X1;N2 Y2\r\n\r\nN3 (c) Z3\r\n  N4 M30";  // no final LF
  SourceManager sm;
  const uint32_t file = sm.addFile(dir.write("bom.nc", text));
  const uint32_t buffer = sm.addBuffer("bom-buffer.nc", text);
  const Read from_file = readAll(sm, file);
  const Read from_buffer = readAll(sm, buffer);
  ASSERT_EQ(from_file.blocks.size(), 4u);
  EXPECT_EQ(from_file.positions, from_buffer.positions);  // same offsets for both sources
  EXPECT_EQ(from_file.positions[0], (BlockPosition{0, 1, 1}));
  EXPECT_EQ(from_file.positions[1], (BlockPosition{0, 1, 10}));  // columns after the BOM
  EXPECT_EQ(from_file.positions[2], (BlockPosition{21, 3, 1}));   // offsets count BOM and CR
  EXPECT_EQ(from_file.positions[3], (BlockPosition{32, 4, 1}));
  expectSeeksReproduce(sm, file);
  expectSeeksReproduce(sm, buffer);
}

TEST(BlockPosition, PositionIsWhereReadingContinues) {
  SourceManager sm;
  const uint32_t f = sm.addBuffer("p.nc", "N1 X1;N2 X2\nN3 X3\n");
  DiagnosticEngine diags(&sm);
  BlockReader reader(sm, f, diags);
  EXPECT_EQ(reader.file(), f);
  EXPECT_EQ(reader.position(), (BlockPosition{0, 1, 1}));  // before the first next()
  ASSERT_TRUE(reader.next());
  EXPECT_EQ(reader.position(), (BlockPosition{0, 1, 7}));
  ASSERT_TRUE(reader.next());
  EXPECT_EQ(reader.position(), (BlockPosition{12, 2, 1}));
  const BlockPosition third = reader.position();
  ASSERT_TRUE(reader.next());
  EXPECT_EQ(reader.lastPosition(), third);
  EXPECT_FALSE(reader.next());
  const BlockPosition end = reader.position();
  EXPECT_EQ(end, (BlockPosition{18, 3, 1}));  // the size of the source, the line after the last
  // Going back after the end, then to the end again.
  reader.seek(BlockPosition{0, 1, 7});
  auto b = reader.next();
  ASSERT_TRUE(b);
  EXPECT_EQ(printBlock(*b), "N2 X2");
  EXPECT_EQ(b->loc, (SourceLocation{f, 1, 7}));
  reader.seek(end);
  EXPECT_FALSE(reader.next());
}

TEST(BlockPosition, SeekToTheEndOfALineWithoutATerminator) {
  TempDir dir;
  SourceManager sm;
  const uint32_t f = sm.addFile(dir.write("t.nc", "N1 X1\nN2 X2"));
  DiagnosticEngine diags(&sm);
  BlockReader reader(sm, f, diags);
  while (reader.next()) {
  }
  EXPECT_EQ(reader.position(), (BlockPosition{11, 3, 1}));
  reader.seek(BlockPosition{6, 2, 1});
  auto b = reader.next();
  ASSERT_TRUE(b);
  EXPECT_EQ(printBlock(*b), "N2 X2");
  EXPECT_FALSE(reader.next());
}

TEST(BlockPosition, APositionSaysItsLanguage) {
  // After G290 the reader is in DIN mode; seeking back to a block before it reads ISO again,
  // and seeking to a DIN position reads DIN (a GOTO back across a G290, then forward).
  SourceManager sm;
  const uint32_t f = sm.addBuffer("p.nc", "N1 G1 X1\nN2 G290\nN3 G291\nN4 X2\n");
  DiagnosticEngine diags(&sm);
  ReaderOptions options;
  options.language_switch = true;
  BlockReader reader(sm, f, diags, options);
  ASSERT_TRUE(reader.next());
  const BlockPosition first = reader.lastPosition();
  ASSERT_TRUE(reader.next());  // N2 G290
  const BlockPosition in_din = reader.position();
  EXPECT_EQ(in_din.language, Language::Din);
  ASSERT_TRUE(reader.next());  // N3 G291, read in DIN
  EXPECT_EQ(reader.lastPosition(), in_din);
  EXPECT_EQ(reader.language(), Language::Iso);
  reader.seek(first);
  EXPECT_EQ(reader.language(), Language::Iso);
  auto b = reader.next();
  ASSERT_TRUE(b);
  EXPECT_EQ(printBlock(*b), "N1 G1 X1");
  reader.seek(in_din);
  EXPECT_EQ(reader.language(), Language::Din);
  ASSERT_TRUE((b = reader.next()));
  EXPECT_EQ(printBlock(*b), "N3 G291");
  // The same text read in another language is another position.
  BlockPosition as_iso = in_din;
  as_iso.language = Language::Iso;
  EXPECT_FALSE(as_iso == in_din);
  EXPECT_FALSE(as_iso < in_din || in_din < as_iso);  // text order is by offset and column
  EXPECT_FALSE(diags.hasErrors());
}

}  // namespace
}  // namespace ncc::frontend
