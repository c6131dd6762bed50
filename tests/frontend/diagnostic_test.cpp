// Each syntax diagnostic: code, line, column and message; and the reader goes on after it.
#include <gtest/gtest.h>

#include "test_util.h"

namespace ncc::frontend {
namespace {

struct Expected {
  const char* text;
  const char* code;
  uint32_t column;
  const char* message;
};

class SyntaxError : public ::testing::TestWithParam<Expected> {};

TEST_P(SyntaxError, ReportedOnceAtItsColumn) {
  const Expected& e = GetParam();
  for (ParserChoice choice : {ParserChoice::Auto, ParserChoice::AntlrOnly}) {
    DiagnosticEngine diags;
    auto block = parseIsoBlock(e.text, 3, 42, diags, 1, choice);
    EXPECT_FALSE(block) << e.text;
    ASSERT_EQ(diags.diagnostics().size(), 1u) << e.text;
    const Diagnostic& d = diags.diagnostics()[0];
    EXPECT_EQ(d.severity, Severity::Error);
    EXPECT_EQ(d.code, e.code) << e.text;
    EXPECT_EQ(d.location, (SourceLocation{3, 42, e.column})) << e.text;
    EXPECT_EQ(d.message, e.message) << e.text;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Iso, SyntaxError,
    ::testing::Values(
        Expected{"G1 X@10", "NCC1001", 5, "unexpected character '@'"},
        Expected{"G1 X1 \"", "NCC1001", 7, "unexpected character '\"'"},
        Expected{"G1 X1 \xC3\xA9", "NCC1001", 7, "unexpected character '\\xC3'"},
        Expected{"G1 X Y1", "NCC1002", 4, "address 'X' has no value"},
        Expected{"G28 XYZ", "NCC1002", 5, "address 'X' has no value"},
        Expected{"G1 X1 F", "NCC1002", 7, "address 'F' has no value"},
        Expected{"X1. ,C", "NCC1002", 5, "address ',C' has no value"},
        Expected{"X[1+[2]", "NCC1003", 2, "unbalanced '['"},
        Expected{"#1=2]", "NCC1004", 5, "unbalanced ']'"},
        Expected{"G1 (open X1", "NCC1005", 4, "comment '(' is not closed by ')'"},
        Expected{"10 G17", "NCC1006", 1, "number '10' has no address"},
        Expected{"X1=2", "NCC1006", 3, "unexpected '='"},
        Expected{"G1 X1 / Y2", "NCC1007", 7, "block skip '/' must be at the start of the block"},
        Expected{"/12 X1", "NCC1008", 2, "block skip level '12' is not a digit 0 to 9"},
        Expected{"N1.5 G1", "NCC1009", 1,
                 "sequence number 'N' needs an unsigned integer without a decimal point"},
        Expected{"N#1", "NCC1009", 1,
                 "sequence number 'N' needs an unsigned integer without a decimal point"},
        Expected{"O-5", "NCC1009", 1,
                 "program number 'O' needs an unsigned integer without a decimal point"},
        Expected{"#1=", "NCC1010", 4, "block ends before the statement is complete"},
        Expected{"IF [#1 EQ 1]", "NCC1010", 13, "block ends before the statement is complete"},
        Expected{"#1=SIN[1,2]", "NCC1011", 4, "function 'SIN' takes 1 argument"},
        Expected{"#1=POW[2]", "NCC1011", 4, "function 'POW' takes 2 arguments"},
        Expected{"#1=ATAN[1,2]/[3]", "NCC1011", 4, "ATAN takes [a], [a]/[b] or [a,b]"},
        Expected{"WHILE [1] DO 1.5", "NCC1012", 14, "loop identifier '1.5' is not an integer"},
        Expected{"X1. ,Q5.", "NCC1013", 5, "unknown comma address ',Q' (expected ,A ,C or ,R)"},
        Expected{"N1 G1 N2", "NCC1014", 7, "second sequence number in one block"},
        Expected{"N99999999999999999999", "NCC1015", 1,
                 "sequence number '99999999999999999999' is too large"}));

TEST(Nesting, DeepBracketsAreRefusedBeforeParsing) {
  // The parser is recursive: a hostile nesting depth must not reach it.
  std::string text = "#1=" + std::string(65, '[') + "1" + std::string(65, ']');
  DiagnosticEngine diags;
  EXPECT_FALSE(parseIsoBlock(text, 1, 1, diags));
  ASSERT_EQ(diags.diagnostics().size(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].code, "NCC1016");
  EXPECT_EQ(diags.diagnostics()[0].location.column, 4u + 64u);
  EXPECT_EQ(diags.diagnostics()[0].message, "brackets nested deeper than 64 levels");

  DiagnosticEngine ok;
  std::string fine = "#1=" + std::string(64, '[') + "1" + std::string(64, ']');
  EXPECT_TRUE(parseIsoBlock(fine, 1, 1, ok));
}

TEST(ReaderDiagnostics, SeveralErrorsOneRunAndNoWordsFromABadBlock) {
  SourceManager sm;
  DiagnosticEngine diags(&sm);
  uint32_t f = sm.addBuffer("bad.nc", "G0 X1.\nG1 X@\nG1 Y2.\n#1=[2\nM30\n");
  BlockReader reader(sm, f, diags);
  std::vector<std::string> blocks;
  while (auto b = reader.next()) blocks.push_back(printBlock(*b));
  EXPECT_EQ(blocks, (std::vector<std::string>{"G0 X1.", "G1 Y2.", "M30"}));
  ASSERT_EQ(diags.diagnostics().size(), 2u);
  EXPECT_EQ(diags.format(diags.diagnostics()[0]),
            "bad.nc:2:5: error[NCC1001]: unexpected character '@'");
  EXPECT_EQ(diags.format(diags.diagnostics()[1]), "bad.nc:4:4: error[NCC1003]: unbalanced '['");
  EXPECT_EQ(reader.stats().rejected_blocks, 2u);
}

TEST(ReaderDiagnostics, UnreadableFile) {
  SourceManager sm;
  DiagnosticEngine diags(&sm);
  uint32_t f = sm.addFile("/nonexistent/dir/part.nc");
  BlockReader reader(sm, f, diags);
  EXPECT_FALSE(reader.next());
  ASSERT_EQ(diags.diagnostics().size(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].code, "NCC1000");
  EXPECT_EQ(diags.diagnostics()[0].message, "cannot read '/nonexistent/dir/part.nc'");
}

}  // namespace
}  // namespace ncc::frontend
