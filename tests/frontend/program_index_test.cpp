// ProgramIndex: N labels and O numbers found by scanning the text, in the control's search
// order, within a range, cached; positions that BlockReader::seek() accepts.
#include <sys/resource.h>

#include <fstream>

#include <gtest/gtest.h>

#include "ncc/frontend/program_index.h"
#include "temp_dir.h"

namespace ncc::frontend {
namespace {

using testing::TempDir;

// Reads the block at `p` and prints it.
std::string blockAt(const SourceManager& sm, uint32_t file, BlockPosition p,
                    ReaderOptions options = {}) {
  DiagnosticEngine diags(&sm);
  BlockReader reader(sm, file, diags, options);
  reader.seek(p);
  auto b = reader.next();
  return b ? printBlock(*b) : "<none>";
}

// Positions of every block, as a reader reports them.
std::vector<BlockPosition> positions(const SourceManager& sm, uint32_t file,
                                     ReaderOptions options = {}) {
  DiagnosticEngine diags(&sm);
  BlockReader reader(sm, file, diags, options);
  std::vector<BlockPosition> out;
  while (reader.next()) out.push_back(reader.lastPosition());
  return out;
}

const char kLoop[] =
    "O0100 (LOOP)\n"          // 0
    "N10 #1=0\n"              // 1
    "N20 #1=#1+1\n"           // 2
    "N30 IF [#1 LT 3] GOTO 20\n"  // 3
    "N20 X1 (second N20)\n"   // 4
    "n40 goto 10\n"           // 5  lower case
    "/2 N50 M30\n"            // 6  block skip
    "( c ) N60 G0;N70 G1\n"   // 7,8  comment first, ';' split
    "N 80 (blank in the word)\n"  // 9
    "G1 N90\n"                // 10 not the first word: not a label
    "N100.\n";                // 11 not an integer

TEST(ProgramIndex, FindsLabelsAsTheReaderReadsThem) {
  SourceManager sm;
  const uint32_t f = sm.addBuffer("loop.nc", kLoop);
  const std::vector<BlockPosition> at = positions(sm, f);
  ProgramIndex index(sm, f, {});
  const BlockPosition start{};
  EXPECT_EQ(index.findSequence(10, start, SequenceSearch::FromStart), at[1]);
  EXPECT_EQ(index.findSequence(40, start, SequenceSearch::FromStart), at[5]);
  EXPECT_EQ(index.findSequence(50, start, SequenceSearch::FromStart), at[6]);
  EXPECT_EQ(index.findSequence(60, start, SequenceSearch::FromStart), at[7]);
  EXPECT_EQ(index.findSequence(70, start, SequenceSearch::FromStart), at[8]);
  EXPECT_EQ(blockAt(sm, f, *index.findSequence(70, start, SequenceSearch::FromStart)), "N70 G1");
  EXPECT_EQ(index.findSequence(80, start, SequenceSearch::FromStart), at[9]);
  EXPECT_FALSE(index.findSequence(90, start, SequenceSearch::FromStart));
  EXPECT_FALSE(index.findSequence(100, start, SequenceSearch::FromStart));
  EXPECT_FALSE(index.findSequence(11, start, SequenceSearch::FromStart));
}

TEST(ProgramIndex, PositionsSayTheLanguageAsTheReaderReadsIt) {
  // Siemens ISO mode: N2 switches to DIN, N4 (only G291) back; the index finds the DIN blocks
  // in DIN, as the reader reads them.
  SourceManager sm;
  const uint32_t f = sm.addBuffer(
      "p.mpf", "N1 G1 X1\nN2 G90 G290 ; to DIN\nN3 R1=2\nN4 G291\nN5 X2\nN6 (G290 in a comment)\n");
  ReaderOptions options;
  options.semicolon_ends_block = false;
  options.language_switch = true;
  DiagnosticEngine diags(&sm);
  BlockReader reader(sm, f, diags, options);
  std::vector<BlockPosition> at;  // N1 .. N6
  while (reader.next()) at.push_back(reader.lastPosition());
  ASSERT_EQ(at.size(), 6u);
  ProgramIndex index(sm, f, options);
  const BlockPosition start{};
  EXPECT_EQ(index.findSequence(1, start, SequenceSearch::FromStart), at[0]);
  EXPECT_EQ(index.findSequence(2, start, SequenceSearch::FromStart), at[1]);
  const std::optional<BlockPosition> n3 = index.findSequence(3, start, SequenceSearch::FromStart);
  ASSERT_TRUE(n3);
  EXPECT_EQ(n3->language, Language::Din);
  EXPECT_EQ(*n3, at[2]);
  EXPECT_EQ(index.findSequence(4, start, SequenceSearch::FromStart), at[3]);
  EXPECT_EQ(at[3].language, Language::Din);
  EXPECT_EQ(index.findSequence(5, start, SequenceSearch::FromStart), at[4]);
  EXPECT_EQ(at[4].language, Language::Iso);
  EXPECT_EQ(index.findSequence(6, start, SequenceSearch::FromStart), at[5]);
  // Searching on from a DIN position keeps counting from its language.
  EXPECT_EQ(index.findSequence(5, *n3, SequenceSearch::ForwardThenFromStart), at[4]);
  EXPECT_EQ(index.recordEnd().language, Language::Iso);
  // Without G290/G291 in the dialect the same text is all ISO.
  ProgramIndex fanuc(sm, f, {});
  EXPECT_EQ(fanuc.findSequence(3, start, SequenceSearch::FromStart)->language, Language::Iso);
}

TEST(ProgramIndex, DinLabelsAreFoundForwardBackwardAndInAnyCase) {
  // GOTOF searches toward the end, GOTOB toward the start (the nearest label, the jump's own
  // block included), GOTO forward then from the start; labels follow the block number.
  SourceManager sm;
  const uint32_t f = sm.addBuffer(
      "p.mpf", "N10 MA1: R1=1\nN20 lbl: X1\nN30 X2 ; MA1: in a comment\nN40 MA1: X3\nN50 X4\n");
  ReaderOptions options;
  options.semicolon_ends_block = false;
  options.initial_language = Language::Din;
  const std::vector<BlockPosition> at = positions(sm, f, options);
  ASSERT_EQ(at.size(), 5u);
  ProgramIndex index(sm, f, options);
  EXPECT_EQ(index.findLabel("MA1", at[2], SequenceSearch::Backward), at[0]);
  EXPECT_EQ(index.findLabel("MA1", at[2], SequenceSearch::Forward), at[3]);
  EXPECT_EQ(index.findLabel("MA1", at[4], SequenceSearch::Backward), at[3]);
  EXPECT_EQ(index.findLabel("MA1", at[0], SequenceSearch::Backward), at[0]);
  EXPECT_EQ(index.findLabel("MA1", at[3], SequenceSearch::Forward), std::nullopt);
  EXPECT_EQ(index.findLabel("MA1", at[3], SequenceSearch::ForwardThenFromStart), at[0]);
  EXPECT_EQ(index.findLabel("LBL", at[4], SequenceSearch::Backward), at[1]);
  EXPECT_EQ(index.findLabel("LB", at[4], SequenceSearch::Backward), std::nullopt);
  EXPECT_EQ(index.findSequence(20, at[4], SequenceSearch::Backward), at[1]);
  EXPECT_EQ(index.findSequence(20, at[0], SequenceSearch::Backward), std::nullopt);
  EXPECT_EQ(index.findSequence(50, at[0], SequenceSearch::Forward), at[4]);
  // An ISO file has no labels.
  ProgramIndex iso(sm, f, {});
  EXPECT_EQ(iso.findLabel("MA1", at[2], SequenceSearch::Backward), std::nullopt);
}

TEST(ProgramIndex, ForwardThenFromStartAndFromStart) {
  SourceManager sm;
  const uint32_t f = sm.addBuffer("loop.nc", kLoop);
  const std::vector<BlockPosition> at = positions(sm, f);
  ProgramIndex index(sm, f, {});
  // From the GOTO block (N30): the N20 after it comes first, then the one before.
  EXPECT_EQ(index.findSequence(20, at[3], SequenceSearch::ForwardThenFromStart), at[4]);
  EXPECT_EQ(index.findSequence(20, at[4], SequenceSearch::ForwardThenFromStart), at[2]);
  EXPECT_EQ(index.findSequence(20, at[1], SequenceSearch::ForwardThenFromStart), at[2]);
  EXPECT_EQ(index.findSequence(20, at[3], SequenceSearch::FromStart), at[2]);
  // Backwards: GOTO 10 from n40 wraps to the start.
  EXPECT_EQ(index.findSequence(10, at[5], SequenceSearch::ForwardThenFromStart), at[1]);
  // The block itself is the last searched (N30 GOTO 30 loops on itself).
  EXPECT_EQ(index.findSequence(30, at[3], SequenceSearch::ForwardThenFromStart), at[3]);
  // From a block in the middle of a line.
  EXPECT_EQ(index.findSequence(60, at[8], SequenceSearch::ForwardThenFromStart), at[7]);
  EXPECT_EQ(index.findSequence(70, at[7], SequenceSearch::ForwardThenFromStart), at[8]);
}

const char kTwoPrograms[] =
    "%\n"
    "O1000 (MAIN)\n"    // 1
    "N10 M98 P2000\n"   // 2
    "N20 M30\n"         // 3
    ":2000 (SUB)\n"     // 4
    "N10 G1 X1\n"       // 5
    "N20 M99\n"         // 6
    "o3000\n"           // 7
    "N20 M99\n"         // 8
    "%\n"               // 9 closes the record
    "O4000\n"           // not part of the program
    "N99\n";

TEST(ProgramIndex, SearchWithinAProgram) {
  SourceManager sm;
  const uint32_t f = sm.addBuffer("two.nc", kTwoPrograms);
  const std::vector<BlockPosition> at = positions(sm, f);
  ProgramIndex index(sm, f, {});
  const std::optional<BlockPosition> sub = index.findProgram(2000);
  ASSERT_TRUE(sub);
  EXPECT_EQ(*sub, at[4]);
  const BlockRange sub_range{*sub, index.programEnd(*sub)};
  EXPECT_EQ(sub_range.second, at[7]);
  // N10 of the subprogram, not of the main program, even searching from the start.
  EXPECT_EQ(index.findSequence(10, *sub, SequenceSearch::FromStart, sub_range), at[5]);
  EXPECT_EQ(index.findSequence(10, at[6], SequenceSearch::ForwardThenFromStart, sub_range), at[5]);
  // N20 of program 3000 is outside program 2000: from N20 (M99) the search wraps to its own.
  EXPECT_EQ(index.findSequence(20, at[6], SequenceSearch::ForwardThenFromStart, sub_range), at[6]);
  EXPECT_FALSE(index.findSequence(30, *sub, SequenceSearch::FromStart, sub_range));
  // Without a range, N20 after program 2000's N20 is program 3000's.
  EXPECT_EQ(index.findSequence(20, at[6], SequenceSearch::ForwardThenFromStart), at[8]);
  // The main program: from the file start to the first O block after it.
  const BlockPosition main_end = index.programEnd(BlockPosition{});
  EXPECT_EQ(main_end, at[1]);  // the file starts with '%': O1000 is the next O block
  const BlockRange main_range{at[1], index.programEnd(at[1])};
  EXPECT_EQ(main_range.second, at[4]);
  EXPECT_EQ(index.findSequence(20, at[2], SequenceSearch::ForwardThenFromStart, main_range), at[3]);
  // From a block before the range: every block of the range comes after it.
  EXPECT_EQ(index.findSequence(10, at[0], SequenceSearch::ForwardThenFromStart, sub_range), at[5]);
}

TEST(ProgramIndex, ProgramsAndTheEndOfTheRecord) {
  SourceManager sm;
  const uint32_t f = sm.addBuffer("two.nc", kTwoPrograms);
  const std::vector<BlockPosition> at = positions(sm, f);
  ProgramIndex index(sm, f, {});
  EXPECT_EQ(index.findProgram(1000), at[1]);
  EXPECT_EQ(index.findProgram(2000), at[4]);  // ':2000'
  EXPECT_EQ(index.findProgram(3000), at[7]);  // 'o3000'
  EXPECT_FALSE(index.findProgram(4000));      // after the closing '%'
  EXPECT_FALSE(index.findSequence(99, BlockPosition{}, SequenceSearch::FromStart));
  EXPECT_EQ(index.programEnd(at[7]), at[9]);  // the last program ends at the closing '%'
  EXPECT_EQ(blockAt(sm, f, at[9]), "%");
  EXPECT_EQ(index.firstProgramNumber(), 1000);
}

TEST(ProgramIndex, ProgramEndIsTheEndOfTheFileWithoutAClosingPercent) {
  SourceManager sm;
  const uint32_t f = sm.addBuffer("open.nc", "O1\nN1 M99\n");
  ProgramIndex index(sm, f, {});
  const BlockPosition end = index.programEnd(*index.findProgram(1));
  DiagnosticEngine diags(&sm);
  BlockReader reader(sm, f, diags);
  while (reader.next()) {
  }
  EXPECT_EQ(end, reader.position());
  EXPECT_EQ(end, (BlockPosition{10, 3, 1}));
}

TEST(ProgramIndex, FirstProgramNumber) {
  SourceManager sm;
  const auto first = [&](const char* text) {
    const uint32_t f = sm.addBuffer("f.nc", text);
    return ProgramIndex(sm, f, {}).firstProgramNumber();
  };
  EXPECT_EQ(first("O0012\nG0 X1\n"), 12);
  EXPECT_EQ(first("\xEF\xBB\xBF%\r\n(header)\r\n\r\n  :34 (SUB)\r\nM99\r\n"), 34);
  EXPECT_EQ(first("( only comments ) ; o56 ; N1\n"), 56);
  EXPECT_EQ(first("N1 O78\n"), std::nullopt);  // O is not the first word
  EXPECT_EQ(first("G0 X1\nO90\n"), std::nullopt);  // the first block is not a program block
  EXPECT_EQ(first("%\n%\nO91\n"), std::nullopt);   // an empty record: O91 is after its end
  EXPECT_EQ(first(""), std::nullopt);
}

TEST(ProgramIndex, SiemensAnnotationIsNotABlockEnd) {
  SourceManager sm;
  const uint32_t f = sm.addBuffer("s.nc", "N10 G1 X1 ; N20 X2\nN30 M30\n");
  ReaderOptions siemens;
  siemens.semicolon_ends_block = false;
  ProgramIndex iso(sm, f, siemens);
  EXPECT_FALSE(iso.findSequence(20, BlockPosition{}, SequenceSearch::FromStart));
  EXPECT_EQ(iso.findSequence(30, BlockPosition{}, SequenceSearch::FromStart),
            (BlockPosition{19, 2, 1}));
  ProgramIndex fanuc(sm, f, {});  // ';' ends the block: N20 starts one
  EXPECT_EQ(fanuc.findSequence(20, BlockPosition{}, SequenceSearch::FromStart),
            (BlockPosition{0, 1, 12}));
  EXPECT_EQ(blockAt(sm, f, BlockPosition{0, 1, 12}), "N20 X2");
}

TEST(ProgramIndex, RepeatedLookupsScanOnce) {
  // A loop jumping back 10000 times to N1 from the same block, in a file of 20000 blocks:
  // the search reads the file once, then answers from its cache.
  std::string text = "O1\nN1 #1=#1+1\n";
  for (int i = 0; i < 20000; ++i) text += "N" + std::to_string(i + 2) + " G1 X1\n";
  text += "N99999 IF [#1 LT 10000] GOTO 1\nM30\n";
  TempDir dir;
  SourceManager sm;
  const uint32_t f = sm.addFile(dir.write("big.nc", text));
  const std::vector<BlockPosition> at = positions(sm, f);
  const BlockPosition goto_block = at[at.size() - 2];
  ProgramIndex index(sm, f, {});
  const std::optional<BlockPosition> first = index.findSequence(1, goto_block,
                                                               SequenceSearch::ForwardThenFromStart);
  ASSERT_EQ(first, at[1]);
  const ProgramIndex::Stats after_first = index.stats();
  for (int i = 0; i < 10000; ++i)
    ASSERT_EQ(index.findSequence(1, goto_block, SequenceSearch::ForwardThenFromStart), first);
  EXPECT_EQ(index.stats().scans, after_first.scans);
  EXPECT_EQ(index.stats().lines, after_first.lines);
  // A label searched forward from just before it reads a few lines, not the file.
  const uint64_t lines_before = index.stats().lines;
  EXPECT_EQ(index.findSequence(502, at[500], SequenceSearch::ForwardThenFromStart), at[502]);
  EXPECT_LE(index.stats().lines - lines_before, 3u);
  // A plain reader pays nothing: the index is not involved in reading.
}

TEST(ProgramIndex, UnreadableFileFindsNothing) {
  SourceManager sm;
  const uint32_t f = sm.addFile("/nonexistent/ncc/missing.nc");
  ProgramIndex index(sm, f, {});
  EXPECT_FALSE(index.findSequence(1, BlockPosition{}, SequenceSearch::FromStart));
  EXPECT_FALSE(index.findProgram(1));
  EXPECT_FALSE(index.firstProgramNumber());
  EXPECT_EQ(index.programEnd(BlockPosition{}), BlockPosition{});
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

long maxRssKb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

TEST(ProgramIndex, LookupsInAMillionLineFileKeepMemoryFlat) {
  // A CAM program with an N on every line and a subprogram at the end: nothing of the file
  // (30+ MB) nor its labels may be held.
  TempDir dir;
  const std::filesystem::path path = dir.path() / "large.nc";
  {
    std::ofstream out(path, std::ios::binary);
    out << "%\nO1000 (LARGE)\nG90 G21 G17\n";
    for (int i = 0; i < 1'000'000; ++i)
      out << "N" << i << " G1 X" << (i % 1000) << ".5 Y-" << (i % 777) << ". F1500.\n";
    out << "M30\nO2000\nN5 G0 X0\nM99\n%\n";
  }
  ASSERT_GT(std::filesystem::file_size(path), 30u * 1024 * 1024);
  SourceManager sm;
  const uint32_t f = sm.addFile(path);
  const long rss_before = maxRssKb();
  {
    ProgramIndex index(sm, f, {});
    EXPECT_EQ(index.firstProgramNumber(), 1000);
    const std::optional<BlockPosition> sub = index.findProgram(2000);
    ASSERT_TRUE(sub);
    EXPECT_EQ(sub->line, 1'000'005u);
    EXPECT_FALSE(index.findProgram(3000));
    const BlockPosition end = index.programEnd(*sub);
    EXPECT_EQ(end.line, 1'000'008u);  // the closing '%'
    // N5 of the subprogram, searched within it; and N5 of the main program from its end.
    EXPECT_EQ(index.findSequence(5, *sub, SequenceSearch::FromStart, BlockRange{*sub, end})->line,
              1'000'006u);
    EXPECT_EQ(index.findSequence(5, *sub, SequenceSearch::ForwardThenFromStart, BlockRange{{}, *sub})
                  ->line,
              9u);
    const std::optional<BlockPosition> last = index.findSequence(999'999, BlockPosition{},
                                                                 SequenceSearch::FromStart);
    ASSERT_TRUE(last);
    EXPECT_EQ(blockAt(sm, f, *last), "N999999 G1 X999.5 Y-0. F1500.");
    EXPECT_FALSE(index.findSequence(2'000'000, BlockPosition{}, SequenceSearch::FromStart));
  }
  const long grown_kb = maxRssKb() - rss_before;
  // AddressSanitizer's quarantine keeps freed memory resident, so RSS says nothing there.
  if (kAddressSanitizer) GTEST_SKIP() << "RSS bound not checked under AddressSanitizer";
  EXPECT_LT(grown_kb, 8 * 1024) << "max RSS grew by " << grown_kb << " kB";
}

}  // namespace
}  // namespace ncc::frontend
