// Every word, expression and statement knows its line and 1-based column in the original line.
#include <gtest/gtest.h>

#include "test_util.h"

namespace ncc::frontend {
namespace {

using testing::parse;

class Locations : public ::testing::TestWithParam<ParserChoice> {};

TEST_P(Locations, WordsAndValues) {
  DiagnosticEngine diags;
  auto b = parseIsoBlock("N10 G1  X- 20. y5", 7, 12, diags, 1, GetParam());
  ASSERT_TRUE(b);
  EXPECT_EQ(b->loc, (SourceLocation{7, 12, 1}));
  ASSERT_EQ(b->words.size(), 3u);
  EXPECT_EQ(b->words[0].loc, (SourceLocation{7, 12, 5}));        // G
  EXPECT_EQ(b->words[1].loc, (SourceLocation{7, 12, 9}));        // X
  EXPECT_EQ(b->words[1].value.loc, (SourceLocation{7, 12, 10}));  // the sign
  EXPECT_EQ(b->words[2].value.loc, (SourceLocation{7, 12, 17}));  // 5
}

TEST_P(Locations, CommaAddressAtTheComma) {
  DiagnosticEngine diags;
  auto b = parseIsoBlock("X5.,C10.", 1, 1, diags, 1, GetParam());
  ASSERT_TRUE(b);
  EXPECT_EQ(b->words[1].loc.column, 4u);
  EXPECT_EQ(b->words[1].value.loc.column, 6u);
}

TEST_P(Locations, FirstColumnOffset) {
  DiagnosticEngine diags;
  auto b = parseIsoBlock("G1 X1", 1, 3, diags, 20, GetParam());
  ASSERT_TRUE(b);
  EXPECT_EQ(b->loc.column, 20u);
  EXPECT_EQ(b->words[1].loc.column, 23u);
}

INSTANTIATE_TEST_SUITE_P(BothPaths, Locations,
                         ::testing::Values(ParserChoice::Auto, ParserChoice::AntlrOnly));

TEST(LocationsAntlr, Expressions) {
  //                      1234567890123456789012345
  auto p = parse("#101 = [#1 + 2] * SIN[30]");
  ASSERT_TRUE(p.block);
  const ast::Statement& s = p.block->statements[0];
  EXPECT_EQ(s.loc.column, 1u);
  EXPECT_EQ(s.target.loc.column, 1u);
  const ast::Expr& mul = s.value;
  EXPECT_EQ(mul.op, ast::Op::Times);
  EXPECT_EQ(mul.loc.column, 17u);                   // the operator
  EXPECT_EQ(mul.args[0].loc.column, 8u);            // '['
  EXPECT_EQ(mul.args[0].args[0].args[0].loc.column, 9u);  // #1
  EXPECT_EQ(mul.args[0].args[0].args[1].loc.column, 14u); // 2
  EXPECT_EQ(mul.args[1].loc.column, 19u);           // SIN
  EXPECT_EQ(mul.args[1].args[0].loc.column, 23u);   // 30
}

TEST(LocationsAntlr, Statements) {
  auto p = parse("N5 IF [#1 EQ 0] THEN #2 = 1");
  ASSERT_TRUE(p.block);
  const ast::Statement& s = p.block->statements[0];
  EXPECT_EQ(s.loc.column, 4u);
  EXPECT_EQ(s.value.loc.column, 11u);  // EQ
  EXPECT_EQ(s.then_assign->loc.column, 22u);
  EXPECT_EQ(s.then_assign->value.loc.column, 27u);
}

TEST(LocationsReader, LinesAndSemicolonBlocks) {
  SourceManager sm;
  DiagnosticEngine diags(&sm);
  uint32_t f = sm.addBuffer("t.nc", "%\r\nG0 X1.;G1 Y2.;\r\n\r\n  M30\n");
  BlockReader reader(sm, f, diags);
  auto b1 = reader.next();
  auto b2 = reader.next();
  auto b3 = reader.next();
  auto b4 = reader.next();
  ASSERT_TRUE(b1 && b2 && b3 && b4);
  EXPECT_FALSE(reader.next());
  EXPECT_TRUE(b1->percent);
  EXPECT_EQ(b2->loc, (SourceLocation{f, 2, 1}));
  EXPECT_EQ(b3->loc, (SourceLocation{f, 2, 8}));
  EXPECT_EQ(b3->words[1].loc, (SourceLocation{f, 2, 11}));
  EXPECT_EQ(b4->words[0].loc, (SourceLocation{f, 4, 3}));
  EXPECT_FALSE(diags.hasErrors());
}

}  // namespace
}  // namespace ncc::frontend
