// The fast path is allowed only while it is invisible: every program of the corpus and of the
// conformance cases, and a set of tricky lines, must give the same blocks (printed text and
// every location) and the same diagnostics through ParserChoice::Auto (fast path + ANTLR
// fallback) as through ParserChoice::AntlrOnly.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "absl/strings/str_cat.h"
#include "ncc/frontend/block_reader.h"

namespace ncc::frontend {
namespace {

void dumpLocations(const ast::Expr& e, std::string& out) {
  absl::StrAppend(&out, " e", e.loc.line, ":", e.loc.column, "k", static_cast<int>(e.kind), "d",
                  static_cast<int>(e.digits));
  for (const ast::Expr& a : e.args) dumpLocations(a, out);
}

void dumpLocations(const ast::Statement& s, std::string& out) {
  absl::StrAppend(&out, " s", s.loc.line, ":", s.loc.column);
  dumpLocations(s.target, out);
  dumpLocations(s.value, out);
  if (s.then_assign) dumpLocations(*s.then_assign, out);
}

// The printed block followed by the file/line/column of every node.
std::string describe(const ast::Block& b) {
  std::string out = printBlock(b);
  absl::StrAppend(&out, " | b", b.loc.file, ":", b.loc.line, ":", b.loc.column);
  for (const ast::Word& w : b.words) {
    absl::StrAppend(&out, " w", w.address.c_str(), w.loc.line, ":", w.loc.column);
    dumpLocations(w.value, out);
  }
  for (const ast::Statement& s : b.statements) dumpLocations(s, out);
  return out;
}

struct Run {
  std::vector<std::string> blocks;
  std::vector<std::string> diagnostics;
  uint64_t fast_blocks = 0;
};

Run read(const SourceManager& sm, uint32_t file, ReaderOptions options) {
  Run run;
  DiagnosticEngine diags(&sm);
  diags.setErrorLimit(1'000'000);
  BlockReader reader(sm, file, diags, options);
  while (auto b = reader.next()) run.blocks.push_back(describe(*b));
  for (const Diagnostic& d : diags.diagnostics()) run.diagnostics.push_back(diags.format(d));
  run.fast_blocks = reader.stats().fast_path_blocks;
  return run;
}

// Compares the two paths on one source; returns how many blocks the fast path read.
uint64_t expectSamePaths(const SourceManager& sm, uint32_t file, bool semicolon_ends_block,
                         Language language = Language::Iso) {
  ReaderOptions fast, antlr;
  fast.semicolon_ends_block = antlr.semicolon_ends_block = semicolon_ends_block;
  fast.initial_language = antlr.initial_language = language;
  fast.language_switch = antlr.language_switch = language == Language::Din;
  antlr.parser = ParserChoice::AntlrOnly;
  Run a = read(sm, file, fast);
  Run b = read(sm, file, antlr);
  EXPECT_EQ(b.fast_blocks, 0u);
  EXPECT_EQ(a.blocks.size(), b.blocks.size()) << sm.displayName(file);
  for (size_t i = 0; i < std::min(a.blocks.size(), b.blocks.size()); ++i) {
    if (a.blocks[i] != b.blocks[i]) {
      ADD_FAILURE() << sm.displayName(file) << " block " << i << "\n fast:  " << a.blocks[i]
                    << "\n antlr: " << b.blocks[i];
      break;
    }
  }
  EXPECT_EQ(a.diagnostics, b.diagnostics) << sm.displayName(file);
  return a.fast_blocks;
}

TEST(Differential, EveryCorpusAndConformanceFile) {
  const std::filesystem::path shared = NCC_SHARED_DIR;
  if (!std::filesystem::exists(shared / "corpus")) GTEST_SKIP() << "no " << shared;
  std::vector<std::filesystem::path> files;
  for (const char* dir : {"corpus", "conformance"})
    for (const auto& entry : std::filesystem::recursive_directory_iterator(shared / dir))
      if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  ASSERT_GT(files.size(), 300u);

  SourceManager sm;
  uint64_t fast_blocks = 0;
  for (const auto& path : files) {
    const uint32_t f = sm.addFile(path);
    fast_blocks += expectSamePaths(sm, f, true);
    fast_blocks += expectSamePaths(sm, f, false);
    // Every file read as DIN too (as the fuzzer reads its seeds): the ISO fast path reads
    // plain word blocks for DIN only where the DIN parser reads them alike.
    expectSamePaths(sm, f, false, Language::Din);
  }
  // The comparison means something only if the fast path did the bulk of the work.
  EXPECT_GT(fast_blocks, 100'000u);
}

TEST(Differential, TrickyLines) {
  const char* lines[] = {
      "G1X10.Y5.", "G 90", "X- 20.", "X+ 3", "X-.5", "X.5.", "X1..", "X1.2.3", "X 1 2",
      "N10N20", "N1.", "N-1", "N 5 G1", "O1 :2", ":", ": 12", "O", "N", "%", "% G1", "%%",
      "/", "/1", "/ 1 X1", "/12 X1", "/1.5 X1", "/.5", "//", "X1/", "/ %", "G1 /2 X1",
      ",C1.", ", C1.", ",C", ",Q1", ",", "X1,", "X1,C-1.", "X1 ,R#1", "(", "()", "(a(b)",
      "(a)b", ")", "X(c)1", "X1(c)Y2", "GOTO1", "G O T O 1", "GOTO", "G0T0", "GT1", "IF",
      "WH", "DO1", "D01", "END", "E1", "EN1", "ENDX", "SIN", "S1N", "A1 B2 C3 D4 E5 F6 G7 H8",
      "I9 J10 K11 L12 M13 P14 Q15 R16 S17 T18 U19 V20 W21 X22 Y23 Z24", "x1 y2 z3", "xyz",
      "X1\t\tY2", "\tG0", "X1 \x01", "X1\x7f", "X\xC3\xA9", "(\xC3\xA9)", "X1 @", "#", "#1",
      "#1=", "X#", "X-#1", "X[1]", "X[", "X]", "[1]", "X1 = 2", "X99999999999999999999999",
      "N9223372036854775807", "N9223372036854775808", "X1e5", "X1E5", "X0x10", "G1 X-0",
      "X00000.00000", "T0101 M06", "T01 T00 M06", "M3S1000", "F1. 25H100", "G02 Y-50, J50.",
      "Z50..", "G1 100. F500", "10 G17", "N10 G80.", "M5.", "X$3", "X1 \"a\"", "\\", "X1;Y2",
  };
  SourceManager sm;
  std::string all;
  for (const char* l : lines) absl::StrAppend(&all, l, "\n");
  const uint32_t f = sm.addBuffer("tricky.nc", all);
  EXPECT_GT(expectSamePaths(sm, f, true), 10u);
  expectSamePaths(sm, f, false);
  expectSamePaths(sm, f, false, Language::Din);
}

// Lines a DIN reader meets: the fast path may take only those the DIN parser reads alike.
TEST(Differential, TrickyDinLines) {
  const char* lines[] = {
      "N10 G1 X10 Y-5.5 F200", "G1X10Y20", "X-10", "X - 10", "X.5", "X10.", "N10", "N10 N20",
      "R1=5", "R1 X1", "R10", "X1 N20", "N10 N20", "G00X-100.Y-100.", "X1Y-2", "X-1Y-2", "X=R1", "MA1: X1", "N20 MA1: G0 X1", ":10 X1", "/1 X1", "/ X1",
      "/12 X1", "x1 y2", "T1 D1 M6", "S1000 M3", "G4 F2", "CR=25", "X1=10", "X1.5=3", "A=ACP(5)",
      "DEF INT A=1, B", "IF R1>2 GOTOB MA1", "GOTOF END", "GOTO N10", "GOTOC 20", "F(1,,3)",
      "POSITION1 (10, 20)", "MYSUB", "T=\"DRILL\"", "X=(1+2)*3", "X=-(1)", "X=--1", "NOT 1",
      "X=1 DIV 2 MOD 3", "X=1<2", "X=1<<2", "WHILE 1", "IF 1", "ENDIF", "X=SIN(30)", "X=SIN()",
      "X=FOO(1)", "X=\"", "%_N_MAIN_MPF", "X1 @", "X\xC3\xA9", "G0 X1 Y2 Z3 A4 B5 C6",
      "M17", "M30", "G291", "G290", "N99999999999999999999 X1", "X99999999999999999999",
  };
  SourceManager sm;
  std::string all;
  for (const char* l : lines) absl::StrAppend(&all, l, "\n");
  const uint32_t f = sm.addBuffer("tricky.mpf", all);
  expectSamePaths(sm, f, false, Language::Din);
}

}  // namespace
}  // namespace ncc::frontend
