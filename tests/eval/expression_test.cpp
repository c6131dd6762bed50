// The Macro B evaluator against the manuals' tables and worked examples (Mazak §13-9-3 and
// §13-9-5 in mazak-fusion640m-eia-iso.fr.txt), and every error it reports.
#include "ncc/eval/expression.h"

#include <gtest/gtest.h>

#include "eval_harness.h"

namespace ncc::eval {
namespace {

using test::evalText;
using test::MapVariables;
using test::Outcome;

const MacroRules& mazak() { return macroRules(Dialect::MazakM); }
const MacroRules& fanuc() { return macroRules(Dialect::FanucM); }

double number(std::string_view text, const MacroRules& rules = mazak()) {
  Outcome out = evalText(text, rules);
  EXPECT_TRUE(out.value.has_value()) << text << ": " << out.failure.message;
  if (!out.value) return -1e300;
  EXPECT_FALSE(out.value->vacant) << text;
  return out.value->number;
}

Failure failure(std::string_view text, const MacroRules& rules = mazak()) {
  Outcome out = evalText(text, rules);
  EXPECT_FALSE(out.value.has_value()) << text << " gave " << (out.value ? out.value->number : 0);
  return out.failure;
}

// ---- Values and vacant (§13-9-3 2.) ---------------------------------------------------------

TEST(Vacant, ArithmeticTableOfTheManual) {
  // A. "#1=#0 -> vacant, #2=#0+1 -> 1, #3=1+#0 -> 1, #4=#0*10 -> 0, #5=#0+#0 -> 0".
  Outcome bare = evalText("#0", mazak());
  ASSERT_TRUE(bare.value);
  EXPECT_TRUE(bare.value->vacant);
  EXPECT_EQ(number("#0+1"), 1.0);
  EXPECT_EQ(number("1+#0"), 1.0);
  EXPECT_EQ(number("#0*10"), 0.0);
  EXPECT_EQ(number("#0+#0"), 0.0);  // a number 0, not vacant (number() checks)
}

TEST(Vacant, UnsetVariableIsVacantAndBracketsOrSignKeepIt) {
  MapVariables vars;
  for (const char* text : {"#101", "[#101]", "-#101", "[[#101]]", "#[100+1]"}) {
    Outcome out = evalText(text, mazak(), vars);
    ASSERT_TRUE(out.value) << text;
    EXPECT_TRUE(out.value->vacant) << text;
  }
  Outcome sum = evalText("#101+0", mazak(), vars);
  ASSERT_TRUE(sum.value);
  EXPECT_FALSE(sum.value->vacant);
}

// C. "Only for EQ and NE are vacant and 0 different":
//   #101 vacant: EQ#0 true, NE 0 true, GE#0 true, GT 0 false;
//   #101 = 0:    EQ#0 false, NE 0 false, GE#0 true, GT 0 false.
TEST(Vacant, ConditionTableOfTheManual) {
  struct Row {
    const char* condition;
    double if_vacant, if_zero;
  };
  const Row rows[] = {{"#101EQ#0", 1, 0}, {"#101NE0", 1, 0}, {"#101GE#0", 1, 1},
                      {"#101GT0", 0, 0}};
  for (const Row& r : rows) {
    MapVariables vacant;
    Outcome a = evalText(r.condition, mazak(), vacant);
    ASSERT_TRUE(a.value) << r.condition;
    EXPECT_EQ(a.value->number, r.if_vacant) << r.condition << " with #101 vacant";
    MapVariables zero;
    zero.set(101, Value::of(0.0));
    Outcome b = evalText(r.condition, mazak(), zero);
    ASSERT_TRUE(b.value) << r.condition;
    EXPECT_EQ(b.value->number, r.if_zero) << r.condition << " with #101 = 0";
  }
}

TEST(Vacant, OrderingComparisonsReadVacantAsZero) {
  EXPECT_EQ(number("#0 LE #0"), 1.0);
  EXPECT_EQ(number("#0 LT #0"), 0.0);
  EXPECT_EQ(number("#0 GT #0"), 0.0);
  EXPECT_EQ(number("-5 LT #0"), 1.0);
  EXPECT_EQ(number("5 GT #0"), 1.0);
  EXPECT_EQ(number("0 EQ #0"), 0.0);
  EXPECT_EQ(number("0 NE #0"), 1.0);
  EXPECT_EQ(number("#0 EQ #0"), 1.0);
  EXPECT_EQ(number("#0 NE #0"), 0.0);
}

TEST(Vacant, IsTrue) {
  EXPECT_FALSE(isTrue(Value::none()));
  EXPECT_FALSE(isTrue(Value::of(0.0)));
  EXPECT_TRUE(isTrue(Value::of(0.5)));
  EXPECT_TRUE(isTrue(Value::of(-1.0)));
}

// ---- Operators (§13-9-5 table and examples) ------------------------------------------------

TEST(Operators, LogicAndModuloExamples) {
  EXPECT_EQ(number("100 OR 14"), 110.0);   // 01100100 | 00001110 = 01101110
  EXPECT_EQ(number("100 XOR 14"), 106.0);  // 01101010
  EXPECT_EQ(number("100 AND 15"), 4.0);
  EXPECT_EQ(number("48 MOD 9"), 3.0);
  EXPECT_EQ(number("-1 AND 255"), 255.0);  // 32-bit two's complement
  EXPECT_EQ(number("-48 MOD 9"), -3.0);    // the sign of the dividend
}

TEST(Operators, ArithmeticExamples) {
  MapVariables vars;
  vars.set(101, Value::of(100.0));
  vars.set(102, Value::of(200.0));
  vars.set(1, Value::of(1000.0));
  EXPECT_EQ(evalText("#101+#1", mazak(), vars).value->number, 1100.0);
  EXPECT_EQ(number("1000.-50."), 950.0);
  EXPECT_EQ(number("100*100"), 10000.0);
  EXPECT_EQ(number("100./100"), 1.0);
  EXPECT_EQ(number("-10/200"), -0.05);  // #5081/#102 with #5081 = -10
}

TEST(Operators, PrecedenceFunctionThenMultiplicativeThenAdditive) {
  // §13-9-5 1.: x#101 = #111 + #112 * SIN[#113]
  EXPECT_NEAR(number("1 + 2 * SIN[90]"), 3.0, 1e-12);
  EXPECT_EQ(number("2 + 3 * 4"), 14.0);
  EXPECT_EQ(number("[2 + 3] * 4"), 20.0);
  EXPECT_EQ(number("10 - 4 - 3"), 3.0);   // left to right
  EXPECT_EQ(number("1 OR 2 AND 3"), 3.0);  // AND binds tighter: 1 OR [2 AND 3]
  EXPECT_EQ(number("1 + 2 EQ 3"), 1.0);   // comparison is loosest
  EXPECT_EQ(number("-2 * 3"), -6.0);
}

// ---- Functions (§13-9-5 rows 9-20; values as printed, to 3 decimals) ------------------------

TEST(Functions, TrigonometryInDegrees) {
  EXPECT_NEAR(number("SIN[60]"), 0.866, 0.0005);
  EXPECT_NEAR(number("1000*SIN[60]"), 866.025, 0.0005);
  EXPECT_NEAR(number("1000.*COS[45.]"), 707.107, 0.0005);
  EXPECT_NEAR(number("1000*TAN[60]"), 1732.051, 0.0005);
  EXPECT_NEAR(number("ATAN[173205/100000]"), 60.0, 0.0005);
  EXPECT_NEAR(number("ATAN[1.732]"), 59.999, 0.0005);
  EXPECT_NEAR(number("ACOS[100000/141421]"), 45.0, 0.0005);
  EXPECT_NEAR(number("ACOS[10./14.142]"), 44.999, 0.0006);
  EXPECT_NEAR(number("ACOS[0.707]"), 45.009, 0.0005);
  EXPECT_NEAR(number("100.*COS[210.]"), -86.6025, 0.0001);  // §13-9-8 example
  EXPECT_NEAR(number("100.*SIN[210.]"), -50.0, 1e-9);
}

TEST(Functions, ExactAtQuadrants) {
  EXPECT_EQ(number("COS[90]"), 0.0);
  EXPECT_EQ(number("SIN[180]"), 0.0);
  EXPECT_EQ(number("SIN[-90]"), -1.0);
  EXPECT_EQ(number("COS[360]"), 1.0);
  EXPECT_EQ(number("TAN[45]") > 0.999999, true);
  EXPECT_EQ(number("ASIN[1]"), 90.0);
  EXPECT_EQ(number("ACOS[-1]"), 180.0);
}

TEST(Functions, TwoArgumentArcTangentFrom0To360) {
  EXPECT_NEAR(number("ATAN[1]/[1]"), 45.0, 1e-12);
  EXPECT_NEAR(number("ATAN[1,1]"), 45.0, 1e-12);
  EXPECT_NEAR(number("ATAN[-1]/[-1]"), 225.0, 1e-12);
  EXPECT_NEAR(number("ATAN[-1]/[1]"), 315.0, 1e-12);
  EXPECT_NEAR(number("ATAN[0]/[-5]"), 180.0, 1e-12);
  EXPECT_NEAR(number("ATAN[-1]"), -45.0, 1e-12);
}

TEST(Functions, SqrtAbsBinBcd) {
  EXPECT_NEAR(number("SQRT[1000]"), 31.623, 0.0005);
  EXPECT_NEAR(number("SQRT[10.*10.+20.*20.]"), 22.361, 0.0005);
  EXPECT_NEAR(number("SQR[1000.]"), 31.623, 0.0005);
  EXPECT_EQ(number("ABS[-50.-70.]"), 120.0);
  EXPECT_EQ(number("ABS[-1000]"), 1000.0);
  EXPECT_EQ(number("BIN[100]"), 64.0);   // 100 = 0x64
  EXPECT_EQ(number("BCD[100]"), 256.0);  // 0x100
  EXPECT_EQ(number("BIN[BCD[12345678]]"), 12345678.0);
}

TEST(Functions, RoundFixFupOfTheManual) {
  for (const char* arg : {"14/3", "14./3", "14/3.", "14./3."}) {
    const std::string a(arg);
    EXPECT_EQ(number("ROUND[" + a + "]"), 5.0) << a;
    EXPECT_EQ(number("FIX[" + a + "]"), 4.0) << a;
    EXPECT_EQ(number("FUP[" + a + "]"), 5.0) << a;
    EXPECT_EQ(number("ROUND[-" + a + "]"), -5.0) << a;
    EXPECT_EQ(number("FIX[-" + a + "]"), -4.0) << a;
    EXPECT_EQ(number("FUP[-" + a + "]"), -5.0) << a;
  }
  EXPECT_EQ(number("RND[2.5]"), 3.0);
  EXPECT_EQ(number("ROUND[-2.5]"), -3.0);
  EXPECT_EQ(number("FUP[3]"), 3.0);
  EXPECT_EQ(number("FIX[-3]"), -3.0);
}

TEST(Functions, FixAndFupSeeDecimalValuesNotBinaryNoise) {
  // 0.1*3*10 is 3.0000000000000004 in binary: FUP must give 3, not 4.
  EXPECT_EQ(number("FUP[0.1*3*10]"), 3.0);
  // 0.57*100 is 56.99999999999999: FIX must give 57, not 56.
  EXPECT_EQ(number("FIX[0.57*100]"), 57.0);
  EXPECT_EQ(number("FIX[56.9]"), 56.0);
  EXPECT_EQ(number("FUP[56.01]"), 57.0);
}

TEST(Functions, LnExpPowAdp) {
  EXPECT_NEAR(number("LN[5]"), 1.609, 0.0005);
  EXPECT_NEAR(number("LN[0.5]"), -0.693, 0.0005);
  EXPECT_NEAR(number("EXP[2]"), 7.389, 0.0005);
  EXPECT_NEAR(number("EXP[1]"), 2.718, 0.0005);
  EXPECT_NEAR(number("EXP[-2]"), 0.135, 0.0005);
  EXPECT_EQ(number("POW[2,10]"), 1024.0);
  EXPECT_EQ(number("POW[-2,3]"), -8.0);
  EXPECT_NEAR(number("ADP[0.01]"), 10.0, 1e-12);  // 10 increments of 0.001 -> 10.
}

TEST(Functions, VacantArgumentCountsAsZero) {
  EXPECT_EQ(number("COS[#0]"), 1.0);
  EXPECT_EQ(number("ABS[#0]"), 0.0);
}

// ---- Errors ---------------------------------------------------------------------------------

TEST(Errors, DomainErrorsAreAlarm860OnMazak) {
  for (const char* text : {"LN[-5]", "LN[0]", "SQRT[-1]", "ASIN[1.5]", "ACOS[-1.01]", "TAN[90]",
                           "TAN[-270]", "ATAN[0]/[0]", "POW[-8,0.5]", "POW[0,-1]", "BIN[10]",
                           "BCD[-1]", "BCD[2.5]", "BCD[123456789]"}) {
    const Failure f = failure(text);
    EXPECT_EQ(f.error, EvalError::Domain) << text << ": " << f.message;
    EXPECT_EQ(mazak().alarm(f.error), "860") << text;
  }
}

TEST(Errors, MessageAndLocationOfADomainError) {
  // "#1=LN[-5]": LN starts at column 4.
  const Failure f = failure("LN[-5]");
  EXPECT_EQ(f.loc.line, 1u);
  EXPECT_EQ(f.loc.column, 4u);
  EXPECT_NE(f.message.find("LN[-5]"), std::string::npos) << f.message;
}

TEST(Errors, DivisionByZero) {
  const Failure f = failure("1+10/[2-2]");
  EXPECT_EQ(f.error, EvalError::DivisionByZero);
  EXPECT_EQ(f.loc.column, 8u);  // the '/'
  EXPECT_EQ(failure("5 MOD 0").error, EvalError::DivisionByZero);
  EXPECT_EQ(failure("5/#0").error, EvalError::DivisionByZero);  // vacant is 0
  EXPECT_EQ(mazak().alarm(EvalError::DivisionByZero), "860");
}

TEST(Errors, ValueRange) {
  // FANUC: magnitudes up to 1e47.
  EXPECT_EQ(failure("POW[10,48]", fanuc()).error, EvalError::ValueRange);
  EXPECT_EQ(failure("1000000*POW[10,42]", fanuc()).error, EvalError::ValueRange);
  EXPECT_EQ(number("POW[10,46]", fanuc()), 1e46);
  EXPECT_EQ(failure("EXP[1000]", fanuc()).error, EvalError::ValueRange);
  const Failure overflow = failure("EXP[1000]");  // Mazak: overflow only
  EXPECT_EQ(overflow.error, EvalError::ValueRange);
  EXPECT_NE(overflow.message.find("EXP"), std::string::npos) << overflow.message;
  EXPECT_EQ(overflow.loc.column, 4u);
  // Mazak states no limit on results (§13-9-5 4. computes with 2345678988888.888).
  EXPECT_NEAR(number("2345678988888.888-2345678901234.567"), 87654.321, 0.001);
  EXPECT_EQ(failure("10000000000 OR 1").error, EvalError::ValueRange);  // beyond 32 bits
}

TEST(Errors, VariableNumbers) {
  const Failure negative = failure("#[-1]");
  EXPECT_EQ(negative.error, EvalError::VariableNumber);
  EXPECT_NE(negative.message.find("negative"), std::string::npos) << negative.message;
  EXPECT_EQ(failure("#[#0]").error, EvalError::VariableNumber);    // vacant number
  EXPECT_EQ(failure("#[5000+1]").error, EvalError::VariableNumber);  // the reader refuses it
  EXPECT_EQ(failure("#[#[-3]]").error, EvalError::VariableNumber);
}

TEST(Errors, BracketNestingFiveLevelsIncludingFunctions) {
  MapVariables vars;
  for (int n : {100, 120, 125, 128, 130, 132, 520}) vars.set(n, Value::of(2.0));
  // §13-6: the manual's five-level example is allowed.
  Outcome ok = evalText("-[[[[[#120]/2+15.]*3-#100]/#520+#125+#128]*#130+#132]", mazak(), vars);
  ASSERT_TRUE(ok.value) << ok.failure.message;
  // §13-9-5 2.: SQRT[[[#111-#112]*SIN[#113]+#114]*#15] is 3 deep.
  EXPECT_TRUE(evalText("SQRT[[[#111-#112]*SIN[#113]+#114]*#15]", mazak()).value);
  // Five brackets inside a function: six levels.
  const Failure f = failure("SQRT[[[[[[1]]]]]]");
  EXPECT_EQ(f.error, EvalError::BracketNesting);
  EXPECT_EQ(f.loc.column, 13u);  // the sixth '['
  EXPECT_EQ(failure("[[[[[[1]]]]]]").error, EvalError::BracketNesting);
  EXPECT_EQ(failure("SIN[COS[TAN[ABS[FIX[FUP[1]]]]]]").error, EvalError::BracketNesting);
  EXPECT_TRUE(evalText("SIN[COS[TAN[ABS[FIX[1]]]]]", mazak()).value);
  // #[..] brackets count too.
  EXPECT_EQ(failure("[[[[[#[1+1]]]]]]").error, EvalError::BracketNesting);
  EXPECT_TRUE(evalText("[[[[#[1+1]]]]]", mazak()).value);
  // Brackets already open around the expression (IF [..]).
  const ast::Block block = test::parseBlock("#1=[[[[1]]]]");
  Failure fail4;
  EXPECT_TRUE(checkBracketDepth(block.statements[0].value, mazak(), 1, fail4));
  EXPECT_FALSE(checkBracketDepth(block.statements[0].value, mazak(), 2, fail4));
  EXPECT_EQ(fail4.error, EvalError::BracketNesting);
}

TEST(Errors, MalformedTreeIsRefusedNotRead) {
  ast::Expr e;
  e.kind = ast::Expr::Kind::Binary;
  e.op = ast::Op::Plus;
  e.args.push_back(ast::Expr::literal(1.0, false, {}));
  MapVariables vars;
  Failure f;
  EXPECT_FALSE(evaluate(e, ExpressionContext{mazak(), vars}, f));
  EXPECT_NE(f.message.find("malformed"), std::string::npos) << f.message;
  ast::Expr v;
  v.kind = ast::Expr::Kind::Variable;
  EXPECT_FALSE(evaluate(v, ExpressionContext{mazak(), vars}, f));
}

// A left-deep chain 1+1+...+1 of `terms` terms, built by hand (the parser builds none deeper
// than ast::kMaxExprDepth; a block store or a test might).
ast::Expr chainOfOnes(int terms) {
  ast::Expr e = ast::Expr::literal(1.0, false, SourceLocation{0, 1, 1});
  for (int i = 1; i < terms; ++i) {
    ast::Expr sum;
    sum.kind = ast::Expr::Kind::Binary;
    sum.op = ast::Op::Plus;
    sum.loc = SourceLocation{0, 1, static_cast<uint32_t>(2 * i)};
    sum.args.push_back(std::move(e));
    sum.args.push_back(ast::Expr::literal(1.0, false, {}));
    e = std::move(sum);
  }
  return e;
}

TEST(Errors, TreesDeeperThanTheParserBuildsAreRefusedNotWalked) {
  MapVariables vars;
  Failure f;
  auto at_limit = evaluate(chainOfOnes(ast::kMaxExprDepth), ExpressionContext{mazak(), vars}, f);
  ASSERT_TRUE(at_limit) << f.message;
  EXPECT_EQ(at_limit->number, ast::kMaxExprDepth);
  EXPECT_FALSE(evaluate(chainOfOnes(ast::kMaxExprDepth + 1), ExpressionContext{mazak(), vars}, f));
  EXPECT_EQ(f.error, EvalError::BracketNesting);
  EXPECT_EQ(f.message, "expression nested deeper than 256 levels");
  EXPECT_EQ(f.loc.column, 1u);  // the first term, 257 levels down: the walk stops there
}

TEST(Errors, BracketDepthIsCheckedBeforeEvaluating) {
  // A division by zero inside too deep brackets reports the brackets (a static error).
  EXPECT_EQ(failure("[[[[[[1/0]]]]]]").error, EvalError::BracketNesting);
}

// ---- Variable numbers -----------------------------------------------------------------------

TEST(VariableNumbers, IndirectExamplesOfTheManual) {
  // §13-9-3 1.: #1=10 #10=20 #20=30: #[#[#1]] is #20 = 30.
  MapVariables vars;
  vars.set(1, Value::of(10));
  vars.set(10, Value::of(20));
  vars.set(20, Value::of(30));
  EXPECT_EQ(evalText("#[#[#1]]", mazak(), vars).value->number, 30.0);
  EXPECT_EQ(evalText("#[#1]", mazak(), vars).value->number, 20.0);
  EXPECT_EQ(evalText("#[SIN[90]*10]", mazak(), vars).value->number, 20.0);
}

TEST(VariableNumbers, AssignmentTargets) {
  MapVariables vars;
  vars.set(10, Value::of(5));
  auto target = [&](std::string_view text, Failure& f) {
    const ast::Block block = test::parseBlock(text);
    return assignmentTarget(block.statements[0].target, ExpressionContext{mazak(), vars}, f);
  };
  Failure f;
  // §13-9-3 example 2: #[#10+1] is #6, #[#10*3] is #15, #[#10/2] is #2.
  EXPECT_EQ(target("#[#10+1]=1000", f), 6);
  EXPECT_EQ(target("#[#10*3]=100", f), 15);
  EXPECT_EQ(target("#[#10/2]=-100", f), 2);
  EXPECT_EQ(target("#101=1", f), 101);
  EXPECT_FALSE(target("#0=1", f));
  EXPECT_EQ(f.error, EvalError::VariableReadOnly);
  EXPECT_EQ(f.loc.column, 1u);
  EXPECT_FALSE(target("#[#10-6]=1", f));
  EXPECT_EQ(f.error, EvalError::VariableNumber);
  // The brackets of #[..] count: with four more inside they make five, with five six.
  EXPECT_TRUE(target("#[[[[[#10]]]]]=1", f));
  EXPECT_FALSE(target("#[[[[[[#10]]]]]]=1", f));
  EXPECT_EQ(f.error, EvalError::BracketNesting);
}

TEST(VariableNumbers, FractionsPerDialect) {
  Failure f;
  // Mazak §13-9-3 example 2: #10 = 5, #[#10/2] is #2.
  EXPECT_EQ(variableNumber(Value::of(2.5), mazak(), {}, f), 2);
  EXPECT_EQ(variableNumber(Value::of(2.9), mazak(), {}, f), 2);
  // FANUC rounds to the nearest integer.
  EXPECT_EQ(variableNumber(Value::of(2.5), fanuc(), {}, f), 3);
  EXPECT_EQ(variableNumber(Value::of(2.4), fanuc(), {}, f), 2);
  EXPECT_EQ(variableNumber(Value::of(-0.4), fanuc(), {}, f), 0);
  // Binary noise does not change the number: 0.57*100 is #57 on Mazak too.
  EXPECT_EQ(variableNumber(Value::of(0.57 * 100), mazak(), {}, f), 57);
  EXPECT_FALSE(variableNumber(Value::of(-1), fanuc(), {}, f));
  EXPECT_EQ(f.error, EvalError::VariableNumber);
  EXPECT_FALSE(variableNumber(Value::none(), mazak(), {}, f));
  EXPECT_FALSE(variableNumber(Value::of(1e30), mazak(), {}, f));
}

}  // namespace
}  // namespace ncc::eval
