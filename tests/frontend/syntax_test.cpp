// Every syntax item of the ISO family, checked through the printed AST. Each case runs through
// both parser choices: the printed text must be the same.
#include <gtest/gtest.h>

#include "test_util.h"

namespace ncc::frontend {
namespace {

using testing::parse;
using testing::printed;

void expectPrints(std::string_view text, std::string_view expected) {
  EXPECT_EQ(printed(text, ParserChoice::Auto), expected) << "input: " << text;
  EXPECT_EQ(printed(text, ParserChoice::AntlrOnly), expected) << "input (ANTLR): " << text;
}

TEST(Syntax, PlainWords) {
  expectPrints("N10 G01 X10. Y-5 F100.", "N10 G1 X10. Y-5 F100.");
  expectPrints("G1X10.Y5.", "G1 X10. Y5.");
  expectPrints("G 90 X- 20. Z + 3", "G90 X-20. Z3");
  expectPrints("X.5 Y-.25 Z10.125", "X0.5 Y-0.25 Z10.125");
}

TEST(Syntax, NumbersKeepPointAndDigits) {
  auto p = parse("X0010 Y10. Z-1.50");
  ASSERT_TRUE(p.block);
  const auto& w = p.block->words;
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w[0].value.number, 10.0);
  EXPECT_FALSE(w[0].value.has_point);
  EXPECT_EQ(w[0].value.digits, 4);
  EXPECT_TRUE(w[1].value.has_point);
  EXPECT_EQ(w[1].value.digits, 2);
  EXPECT_EQ(w[2].value.number, -1.5);
  EXPECT_EQ(w[2].value.digits, 3);
}

TEST(Syntax, DecimalGCodes) {
  expectPrints("G54.1 P1", "G54.1 P1");
  expectPrints("G92.1 X0", "G92.1 X0");
  expectPrints("G50.1 X0 Y0", "G50.1 X0 Y0");
  auto p = parse("G54.1");
  ASSERT_TRUE(p.block);
  EXPECT_DOUBLE_EQ(p.block->words[0].value.number, 54.1);
}

TEST(Syntax, LowerCaseIsUpperCase) {
  expectPrints("n5 g1 x1. (keep Case)", "N5 G1 X1. (keep Case)");
  expectPrints("#1=sin[30]", "#1=SIN[30]");
}

TEST(Syntax, SequenceAndProgramNumbers) {
  auto p = parse("O2000 N0100 G90 G01 X40.");
  ASSERT_TRUE(p.block);
  EXPECT_EQ(p.block->program_number, 2000);
  EXPECT_EQ(p.block->sequence, 100);
  EXPECT_EQ(p.block->words.size(), 3u);  // N and O are not words
  expectPrints(":1234", "O1234");
  expectPrints("O2000 G90 G01 X40.", "O2000 G90 G1 X40.");
}

TEST(Syntax, PercentAndSkip) {
  expectPrints("%", "%");
  auto p = parse("%");
  ASSERT_TRUE(p.block);
  EXPECT_TRUE(p.block->percent);
  EXPECT_FALSE(p.block->empty());

  auto s = parse("/ N10 X1.");
  ASSERT_TRUE(s.block);
  EXPECT_EQ(s.block->skip_level, 1);
  EXPECT_EQ(parse("/3 X1.").block->skip_level, 3);
  EXPECT_EQ(parse("/0 X1.").block->skip_level, 0);
  EXPECT_EQ(parse("X1.").block->skip_level, -1);
  expectPrints("/9 G0 X0", "/9 G0 X0");
}

TEST(Syntax, CommentsAreKept) {
  expectPrints("(DEMO. PROG)", "(DEMO. PROG)");
  expectPrints("N35 X100. (axisl)", "N35 X100. (axisl)");
  expectPrints("G0 (a) X1 (b (nested open)", "G0 X1 (a) (b (nested open)");
  auto p = parse("(\xE5\x8A\xA0\xE5\xB7\xA5) G0");  // UTF-8 in a comment
  ASSERT_TRUE(p.block);
  EXPECT_EQ(p.block->comments[0], "\xE5\x8A\xA0\xE5\xB7\xA5");
}

TEST(Syntax, CommaAddresses) {
  expectPrints("G01 X5.,C10. F100", "G1 X5. ,C10. F100");
  expectPrints("N30 X80. Y70. A95.824, R10.", "N30 X80. Y70. A95.824 ,R10.");
  expectPrints("G17 G91 G01 Y20.,R10.Z-0.01", "G17 G91 G1 Y20. ,R10. Z-0.01");
  expectPrints("X10. ,A30.", "X10. ,A30.");
  auto p = parse("X1.,C2.");
  ASSERT_TRUE(p.block);
  EXPECT_EQ(p.block->words[1].address, ",C");
}

TEST(Syntax, ExpressionValues) {
  expectPrints("X#1", "X#1");
  expectPrints("X-#2", "X-#2");
  expectPrints("X#[#2+1]", "X#[#2+1]");
  expectPrints("X[1+2*#3]", "X[1+[2*#3]]");
  expectPrints("R-[#5024]", "R-[#5024]");
  expectPrints("G#8 Z#[#1]", "G#8 Z#[#1]");
  expectPrints("G90G10L20P#100X#101Y#101", "G90 G10 L20 P#100 X#101 Y#101");
  auto p = parse("X-#5");
  ASSERT_TRUE(p.block);
  const ast::Expr& v = p.block->words[0].value;
  EXPECT_EQ(v.kind, ast::Expr::Kind::Unary);
  EXPECT_EQ(v.op, ast::Op::Minus);
  EXPECT_EQ(v.args[0].kind, ast::Expr::Kind::Variable);
}

TEST(Syntax, Precedence) {
  // multiplicative binds tighter than additive, which binds tighter than comparison
  expectPrints("#1=1+2*3-4", "#1=[[1+[2*3]]-4]");
  expectPrints("#1=#2 OR #3 AND #4", "#1=[#2 OR [#3 AND #4]]");
  expectPrints("#1=#2 XOR #3 MOD 4", "#1=[#2 XOR [#3 MOD 4]]");
  expectPrints("#1=8/4/2", "#1=[[8/4]/2]");
  expectPrints("#1=-#2*3", "#1=[-#2*3]");
  expectPrints("#1=2*-3", "#1=[2*-3]");
  expectPrints("#1=[1+2]*3", "#1=[[1+2]*3]");
  expectPrints("IF[#1+1EQ#2*2]GOTO5", "IF [[#1+1] EQ [#2*2]] GOTO 5");
  auto p = parse("#1=1+2*3");
  ASSERT_TRUE(p.block);
  const ast::Expr& e = p.block->statements[0].value;
  ASSERT_EQ(e.kind, ast::Expr::Kind::Binary);
  EXPECT_EQ(e.op, ast::Op::Plus);
  EXPECT_EQ(e.args[1].op, ast::Op::Times);
}

TEST(Syntax, Functions) {
  for (const char* f : {"SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "ABS", "BIN", "BCD",
                        "ROUND", "FIX", "FUP", "LN", "EXP", "ADP"}) {
    std::string text = std::string("#1=") + f + "[#2]";
    expectPrints(text, text);
  }
  expectPrints("#1=POW[2,10]", "#1=POW[2,10]");
  expectPrints("#1=ATAN[#2]/[#3]", "#1=ATAN[#2,#3]");
  expectPrints("#1=ATAN[1,2]", "#1=ATAN[1,2]");
  expectPrints("#1=ATN[1] + SQR[4] + RND[1.5]", "#1=[[ATAN[1]+SQRT[4]]+ROUND[1.5]]");
  expectPrints("#1=ATAN[1]/[2]/2", "#1=[ATAN[1,2]/2]");
  expectPrints("#1=SIN[30]/[2]", "#1=[SIN[30]/[2]]");
}

TEST(Syntax, Statements) {
  expectPrints("#100 = 5", "#100=5");
  expectPrints("#[#1+1]=#2", "#[#1+1]=#2");
  expectPrints("#1=200 #2=#1+200", "#1=200 #2=[#1+200]");
  expectPrints("GOTO 10", "GOTO 10");
  expectPrints("N41GOTO#22", "N41 GOTO #22");
  expectPrints("IF [#1 EQ 0] GOTO 99", "IF [#1 EQ 0] GOTO 99");
  expectPrints("IF[#50600EQ0]GOTO60", "IF [#50600 EQ 0] GOTO 60");
  expectPrints("IF [#1 GT 2] THEN #3 = 4", "IF [#1 GT 2] THEN #3=4");
  expectPrints("WHILE [#1 LT 10] DO 1", "WHILE [#1 LT 10] DO 1");
  expectPrints("WH[[#1GE#2]AND[#3GE#7]]DO1", "WHILE [[#1 GE #2] AND [#3 GE #7]] DO 1");
  expectPrints("END 1", "END 1");
  expectPrints("END1", "END 1");
  expectPrints("#1=#2NE#3", "#1=[#2 NE #3]");
  expectPrints("#1=#2 LE #3", "#1=[#2 LE #3]");

  auto p = parse("IF [#1 GT 2] THEN #3 = 4");
  ASSERT_TRUE(p.block);
  const ast::Statement& s = p.block->statements[0];
  EXPECT_EQ(s.kind, ast::Statement::Kind::IfThen);
  ASSERT_TRUE(s.then_assign);
  EXPECT_EQ(s.then_assign->kind, ast::Statement::Kind::Assign);
  auto w = parse("WHILE [#1 LT 10] DO 2");
  ASSERT_TRUE(w.block);
  EXPECT_EQ(w.block->statements[0].loop_id, 2);
  EXPECT_EQ(w.block->statements[0].kind, ast::Statement::Kind::While);
}

TEST(Syntax, FastPathTakesPlainBlocksOnly) {
  SourceManager sm;
  DiagnosticEngine diags(&sm);
  uint32_t f = sm.addBuffer("t.nc", "N1 G0 X1.\n#1=2\nG1 X#1 (c)\n/2 G1 Y2. ,R1.\n%\n");
  BlockReader reader(sm, f, diags);
  int n = 0;
  while (reader.next()) ++n;
  EXPECT_EQ(n, 5);
  EXPECT_EQ(reader.stats().fast_path_blocks, 3u);  // not the two with '#'
}

}  // namespace
}  // namespace ncc::frontend
