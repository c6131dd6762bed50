#include "ncc/support/diagnostics.h"

#include <sstream>

#include "gtest/gtest.h"
#include "ncc/support/source_manager.h"

namespace ncc {
namespace {

TEST(Diagnostics, FormatsFileLineColumnCodeAndCaret) {
  SourceManager sources;
  uint32_t file = sources.addBuffer("part.nc", "N10 G01 X10.\nN20 G02 X5. R1.\n");
  DiagnosticEngine diags(&sources);
  diags.error("818", SourceLocation{file, 2, 5}, "arc radius too small");
  ASSERT_TRUE(diags.hasErrors());
  std::ostringstream out;
  diags.print(out);
  EXPECT_EQ(out.str(),
            "part.nc:2:5: error[818]: arc radius too small\n"
            "  N20 G02 X5. R1.\n"
            "      ^\n");
}

TEST(Diagnostics, ColumnsCountCharactersNotBytes) {
  SourceManager sources;
  // "é" and "°" are two bytes each: Q is byte 12 of the line but character 10.
  uint32_t file = sources.addBuffer("part.nc", "(é °) X1 Q5\n");
  DiagnosticEngine diags(&sources);
  diags.error("NCC2011", SourceLocation{file, 1, 12}, "address Q");
  std::ostringstream out;
  diags.print(out);
  EXPECT_EQ(out.str(),
            "part.nc:1:10: error[NCC2011]: address Q\n"
            "  (é °) X1 Q5\n"
            "           ^\n");
}

TEST(Diagnostics, LongLinesAreQuotedInAWindowAroundTheCaret) {
  SourceManager sources;
  std::string line = std::string(5000, 'A') + "@" + std::string(5000, 'B');
  uint32_t file = sources.addBuffer("long.nc", line + "\n");
  DiagnosticEngine diags(&sources);
  diags.error("NCC1001", SourceLocation{file, 1, 5001}, "unexpected character '@'");
  std::ostringstream out;
  diags.print(out);
  std::string text = out.str();
  EXPECT_LT(text.size(), 400u);
  std::string quoted = text.substr(text.find('\n') + 1);
  std::string source = quoted.substr(0, quoted.find('\n'));
  std::string caret = quoted.substr(quoted.find('\n') + 1);
  EXPECT_EQ(source.substr(0, 5), "  ...");
  EXPECT_EQ(source.substr(source.size() - 3), "...");
  EXPECT_EQ(source.size(), 2u + 3u + 120u + 3u);
  // The caret sits under the '@'.
  EXPECT_EQ(caret.find('^'), source.find('@'));
}

TEST(Diagnostics, ShortLinesAreQuotedWhole) {
  std::string q = DiagnosticEngine::quoteLine("G1 X1", 4);
  EXPECT_EQ(q, "  G1 X1\n     ^\n");
  // A long line with the caret near its start: cut at the end only.
  std::string line(300, 'X');
  q = DiagnosticEngine::quoteLine(line, 1);
  EXPECT_EQ(q.substr(0, 2 + 120 + 3), "  " + std::string(120, 'X') + "...");
  EXPECT_EQ(q.substr(q.find('\n') + 1), "  ^\n");
}

TEST(Diagnostics, WarningsDoNotCountAsErrors) {
  DiagnosticEngine diags;
  diags.warning("NCC0001", SourceLocation{0, 3, 1}, "w");
  EXPECT_FALSE(diags.hasErrors());
  EXPECT_EQ(diags.diagnostics().size(), 1u);
}

TEST(Diagnostics, ErrorLimitStopsStoringButKeepsCounting) {
  DiagnosticEngine diags;
  diags.setErrorLimit(3);
  for (int i = 0; i < 10; ++i) diags.error("E", SourceLocation{0, uint32_t(i + 1), 1}, "x");
  EXPECT_EQ(diags.errorCount(), 10u);
  EXPECT_EQ(diags.diagnostics().size(), 3u);
}

TEST(SourceManager, SameFileRegisteredOnce) {
  SourceManager sources;
  EXPECT_EQ(sources.addFile("a.nc"), sources.addFile("a.nc"));
  EXPECT_NE(sources.addFile("a.nc"), sources.addFile("b.nc"));
}

TEST(SourceManager, LineTextStripsCarriageReturn) {
  SourceManager sources;
  uint32_t f = sources.addBuffer("x", "A\r\nB\r\n");
  EXPECT_EQ(sources.lineText(f, 2), "B");
  EXPECT_EQ(sources.lineText(f, 3), "");
}

}  // namespace
}  // namespace ncc
