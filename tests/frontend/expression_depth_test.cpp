// Expression depth (docs/macro.md, Expression depth; issue 31): a chain of n terms is a tree n
// deep, and every walker of the tree recurses once per level, so the parser refuses an
// expression deeper than ast::kMaxExprDepth with NCC1017 where it becomes too deep, and takes
// one exactly that deep. Hostile lengths (20,000 terms) must be refused, not crash.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "test_util.h"

namespace ncc::frontend {
namespace {

constexpr int kLimit = ast::kMaxExprDepth;
constexpr const char* kMessage =
    "expression nested deeper than 256 levels (each operator, sign, bracket and function is one)";

// "1<op>1<op>...1" with `terms` terms.
std::string chain(int terms, const std::string& op) {
  std::string s = "1";
  for (int i = 1; i < terms; ++i) s += op + "1";
  return s;
}

// Nodes on the longest path of the tree (ast::kMaxExprDepth's measure).
int depth(const ast::Expr& e) {
  int deepest = 0;
  for (const ast::Expr& a : e.args) deepest = std::max(deepest, depth(a));
  return deepest + 1;
}

void expectRefusedAt(const std::string& text, uint32_t column, const char* code = "NCC1017",
                     const char* message = kMessage) {
  for (ParserChoice choice : {ParserChoice::Auto, ParserChoice::AntlrOnly}) {
    DiagnosticEngine diags;
    EXPECT_FALSE(parseIsoBlock(text, 3, 7, diags, 1, choice)) << text.substr(0, 60);
    ASSERT_EQ(diags.diagnostics().size(), 1u) << text.substr(0, 60);
    const Diagnostic& d = diags.diagnostics()[0];
    EXPECT_EQ(d.code, code) << text.substr(0, 60);
    EXPECT_EQ(d.location, (SourceLocation{3, 7, column})) << text.substr(0, 60);
    EXPECT_EQ(d.message, message) << text.substr(0, 60);
  }
}

ast::Block parsed(const std::string& text) {
  testing::Parsed p = testing::parse(text, ParserChoice::AntlrOnly);
  EXPECT_TRUE(p.block) << (p.diags.diagnostics().empty() ? std::string()
                                                         : p.diags.diagnostics()[0].message);
  return p.block ? *p.block : ast::Block{};  // a copy: copies are deep
}

TEST(ExpressionDepth, ChainsAtTheLimitAreRead) {
  for (std::string op : {"+", "-", "*", "/", "EQ", "OR", "AND", "MOD"}) {
    const std::string text = "#1=" + chain(kLimit, op);
    ast::Block b = parsed(text);
    ASSERT_EQ(b.statements.size(), 1u) << op;
    EXPECT_EQ(depth(b.statements[0].value), kLimit) << op;
    // Left-deep: the root is the last operator, its right operand the last term.
    EXPECT_EQ(b.statements[0].value.args[1].loc.column, text.size());
    // The printer walks it too.
    const size_t spaces = op.size() > 1 ? 2 * (kLimit - 1) : 0;  // keyword operators
    EXPECT_EQ(printBlock(b).size(), text.size() + 2 * (kLimit - 1) + spaces) << op;
  }
}

TEST(ExpressionDepth, OneTermMoreIsRefusedAtTheOperatorWhereItCrosses) {
  // '#1=' is columns 1-3; the k-th '+' is at 3 + 2k, the k-th 'EQ' at 2 + 3k.
  expectRefusedAt("#1=" + chain(kLimit + 1, "+"), 3 + 2 * kLimit);
  expectRefusedAt("#1=" + chain(kLimit + 1, "*"), 3 + 2 * kLimit);
  expectRefusedAt("#1=" + chain(kLimit + 1, "EQ"), 2 + 3 * kLimit);
}

TEST(ExpressionDepth, HostileChainsAreRefusedNotCrashed) {
  expectRefusedAt("#1=" + chain(20000, "+"), 3 + 2 * kLimit);
  expectRefusedAt("#1=" + chain(20000, "*"), 3 + 2 * kLimit);
  expectRefusedAt("#1=" + chain(20000, "EQ"), 2 + 3 * kLimit);
  expectRefusedAt("#1=" + chain(20000, " XOR "), 6 * kLimit);
  // In a condition, a word value, a variable number, a function argument.
  expectRefusedAt("IF[" + chain(20000, "EQ") + "]GOTO5", 2 + 3 * kLimit);
  expectRefusedAt("WHILE[" + chain(20000, "LT") + "]DO1", 5 + 3 * kLimit);
  expectRefusedAt("IF[1]THEN#1=" + chain(20000, "-"), 12 + 2 * kLimit);
  expectRefusedAt("G1X[" + chain(20000, "+") + "]", 4 + 2 * kLimit);
  expectRefusedAt("#[" + chain(20000, "+") + "]=1", 2 + 2 * kLimit);
  expectRefusedAt("#1=SIN[" + chain(20000, "*") + "]", 7 + 2 * kLimit);
}

TEST(ExpressionDepth, BracketsAroundAChainCount) {
  // Each bracket is a level: 10 brackets and 246 terms are 256 deep...
  const std::string ten(10, '['), close(10, ']');
  ast::Block b = parsed("#1=" + ten + chain(kLimit - 10, "+") + close);
  EXPECT_EQ(depth(b.statements[0].value), kLimit);
  // ...and one more term is not: the outermost bracket is the 257th level.
  expectRefusedAt("#1=" + ten + chain(kLimit - 9, "+") + close, 4);
}

TEST(ExpressionDepth, HostileBracketsAreRefusedBeforeParsing) {
  // Brackets keep their own lexical limit (NCC1016, 64 levels), far below kMaxExprDepth.
  const std::string open(20000, '['), close(20000, ']');
  expectRefusedAt("G1X" + open + "1" + close, 4 + 64, "NCC1016",
                  "brackets nested deeper than 64 levels");
  expectRefusedAt("#1=" + open + "1" + close, 4 + 64, "NCC1016",
                  "brackets nested deeper than 64 levels");
}

TEST(ExpressionDepth, SignsBeforeBracketsNestAndAreRefusedBeforeParsing) {
  // 63 signs before each bracket: the parser recurses once per sign, so the signs of all the
  // open brackets add up; the 257th level (a sign after the fourth bracket) is refused before
  // the parser sees the block.
  const std::string signs(63, '-');
  std::string deep = "#1=";
  for (int i = 0; i < 5; ++i) deep += signs + "[";
  deep += "1" + std::string(5, ']');
  expectRefusedAt(deep, 4 + 4 * 64);
  // Three such brackets, 62 signs and a fourth bracket: 255 levels and the 1 inside is 256.
  std::string fits = "#1=";
  for (int i = 0; i < 3; ++i) fits += signs + "[";
  fits += std::string(62, '-') + "[1" + std::string(4, ']');
  EXPECT_EQ(depth(parsed(fits).statements[0].value), kLimit);
  // One sign more: the tree is 257 deep, found by the builder at the outermost sign.
  std::string over = "#1=";
  for (int i = 0; i < 4; ++i) over += signs + "[";
  over += "1" + std::string(4, ']');
  expectRefusedAt(over, 4);
}

TEST(ExpressionDepth, ConditionBracketIsNotALevel) {
  // IF [..] keeps no node for its bracket: a 256-term condition is 256 deep and read.
  ast::Block b = parsed("IF[" + chain(kLimit, "EQ") + "]GOTO5");
  EXPECT_EQ(depth(b.statements[0].value), kLimit);
  ast::Block w = parsed("WHILE[" + chain(kLimit, "GE") + "]DO1");
  EXPECT_EQ(depth(w.statements[0].value), kLimit);
}

TEST(ExpressionDepth, TheReaderGoesOnAfterARefusedBlock) {
  SourceManager sm;
  DiagnosticEngine diags(&sm);
  const uint32_t f = sm.addBuffer(
      "deep.nc", "G0 X1.\n#1=" + chain(20000, "+") + "\n#2=" + chain(kLimit, "+") + "\nM30\n");
  BlockReader reader(sm, f, diags);
  std::vector<std::string> firsts;
  while (auto b = reader.next()) firsts.push_back(printBlock(*b).substr(0, 6));
  EXPECT_EQ(firsts, (std::vector<std::string>{"G0 X1.", "#2=[[[", "M30"}));
  ASSERT_EQ(diags.diagnostics().size(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].code, "NCC1017");
  EXPECT_EQ(diags.diagnostics()[0].location.line, 2u);
  EXPECT_EQ(diags.diagnostics()[0].location.column, 3u + 2 * kLimit);
}

}  // namespace
}  // namespace ncc::frontend
