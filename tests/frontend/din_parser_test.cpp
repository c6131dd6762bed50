// The DIN parser (grammar/Din.g4, frontend/src/din_block_parser.cpp): the tree of each
// construct, printed (block_printer.cpp), and the diagnostic of each kind of bad text.
#include <gtest/gtest.h>

#include "din_block_parser.h"
#include "ncc/frontend/block_reader.h"

namespace ncc::frontend {
namespace {

struct Parsed {
  bool ok = false;
  ast::Block block;
  std::string diagnostics;
};

Parsed parse(std::string_view text) {
  SourceManager sm;
  const uint32_t f = sm.addBuffer("p.mpf", std::string(text));
  DiagnosticEngine diags(&sm);
  DinBlockParser parser;
  Parsed p;
  p.ok = parser.parse(text, SourceLocation{f, 1, 1}, diags, p.block);
  for (const Diagnostic& d : diags.diagnostics()) p.diagnostics += diags.format(d) + "\n";
  return p;
}

std::string printed(std::string_view text) {
  Parsed p = parse(text);
  EXPECT_TRUE(p.ok) << text << "\n" << p.diagnostics;
  EXPECT_EQ(p.block.language, Language::Din);
  return printBlock(p.block);
}

TEST(DinParser, WordsAndAddressesWithValues) {
  EXPECT_EQ(printed("N10 G1 X10 Y-5.5 F200"), "N10 G1 X10 Y-5.5 F200");
  EXPECT_EQ(printed("g1x10y20"), "G1 X10 Y20");  // words without blanks, any case
  EXPECT_EQ(printed("X=R1+5 CR=25 X1=-3"), "X=R1+5 CR=25 X1=-3");
  EXPECT_EQ(printed("X=2+3*4"), "X=2+(3*4)");  // * before +
  EXPECT_EQ(printed("X=(2+3)*4"), "X=(2+3)*4");
  EXPECT_EQ(printed("T=\"Drill 8\""), "T=\"Drill 8\"");  // a string keeps its case
  EXPECT_EQ(printed(":10 X1"), "N10 X1");  // a main block number
  EXPECT_EQ(printed("/1 X1"), "/1 X1");
  EXPECT_EQ(printed("%_N_MYKONTUR_SPF"), "% (_N_MYKONTUR_SPF)");  // the file's header
  EXPECT_EQ(printed("%"), "%");
}

TEST(DinParser, PriorityLoosestFirstComparisonThenLogicThenArithmetic) {
  EXPECT_EQ(printed("R1=1+2 == 3 AND 4"), "R1=(1+2)==(3 AND 4)");
  EXPECT_EQ(printed("R1=1 OR 2 XOR 3 AND 4"), "R1=1 OR (2 XOR (3 AND 4))");
  EXPECT_EQ(printed("R1=1 B_OR 2 B_XOR 3 B_AND 4+5"), "R1=1 B_OR (2 B_XOR (3 B_AND (4+5)))");
  EXPECT_EQ(printed("R1=8 DIV 3 MOD 2"), "R1=(8 DIV 3) MOD 2");
  EXPECT_EQ(printed("R1=NOT R2 <> -R3"), "R1=NOT R2<>-R3");
  EXPECT_EQ(printed("R1=ATAN2(1,2)+POT(3)+MINVAL(1,2)"), "R1=(ATAN2(1,2)+POT(3))+MINVAL(1,2)");
}

TEST(DinParser, StatementsVariablesLabelsAndJumps) {
  EXPECT_EQ(printed("N20 MA1: R3=R1*COUNT"), "N20 MA1: R3=R1*COUNT");
  EXPECT_EQ(printed("R[R1+1]=2"), "R[R1+1]=2");
  EXPECT_EQ(printed("DEF REAL A[3,4], b=2"), "DEF REAL A[3,4] DEF REAL B=2");
  EXPECT_EQ(printed("DEF STRING[8] NAME=\"A\" << R1"), "DEF STRING[8] NAME=\"A\"<<R1");
  EXPECT_EQ(printed("PROC P(VAR STRING[20] S)"), "PROC P(VAR STRING[20] S)");
  EXPECT_EQ(printed("R1=SUBSTR(S,1,2)"), "R1=SUBSTR(S,1,2)");
  EXPECT_EQ(printed("N10 REPEAT MA1 MA2 P=R1+1"), "N10 REPEAT MA1 MA2 P=R1+1");
  EXPECT_EQ(printed("REPEATB MA1"), "REPEATB MA1");
  EXPECT_EQ(printed("A[1,2]=A[0,0]+$P_UIFR[1]"), "A[1,2]=A[0,0]+$P_UIFR[1]");
  EXPECT_EQ(printed("IF COUNT<6 GOTOB MA1"), "IF COUNT<6 GOTOB MA1");
  EXPECT_EQ(printed("GOTOF N100"), "GOTOF 100");
  EXPECT_EQ(printed("GOTO 100"), "GOTO 100");
  EXPECT_EQ(printed("GOTOC END_1"), "GOTOC END_1");
  EXPECT_EQ(printed("POSITION1 (10, , 30)"), "POSITION1(10,,30)");
  EXPECT_EQ(printed("MYKONTUR"), "MYKONTUR");
  EXPECT_EQ(printed("CYCLE81()"), "CYCLE81");
  // The jump's kind and target, the DEF's type and dimensions are in the tree.
  Parsed p = parse("IF R1==TRUE GOTOF LBL");
  ASSERT_TRUE(p.ok);
  ASSERT_EQ(p.block.statements.size(), 1u);
  EXPECT_EQ(p.block.statements[0].kind, ast::Statement::Kind::IfGoto);
  EXPECT_EQ(p.block.statements[0].jump, ast::Jump::Forward);
  EXPECT_EQ(*p.block.statements[0].target.text, "LBL");
  p = parse("DEF INT K[2]");
  ASSERT_TRUE(p.ok);
  EXPECT_EQ(p.block.statements[0].type, ast::DataType::Int);
  EXPECT_EQ(p.block.statements[0].target.args.size(), 1u);
  EXPECT_EQ(p.block.statements[0].value.kind, ast::Expr::Kind::Vacant);
}

TEST(DinParser, ControlStructuresStandAloneWithNumberAndLabel) {
  // Comparisons bind last in DIN: A==(1 AND B).
  EXPECT_EQ(printed("N10 IF (A==1 AND B)"), "N10 IF (A==(1 AND B))");
  EXPECT_EQ(printed("IF (A==1) AND (B<2)"), "IF (A==1) AND (B<2)");
  EXPECT_EQ(printed("ELSE"), "ELSE");
  EXPECT_EQ(printed("N20 LBL: ENDIF"), "N20 LBL: ENDIF");
  EXPECT_EQ(printed("WHILE Y<=Y_END"), "WHILE Y<=Y_END");
  EXPECT_EQ(printed("endwhile"), "ENDWHILE");
  EXPECT_EQ(printed("N110 FOR COUNTER=0 TO NUMBER-1"), "N110 FOR COUNTER=0 TO NUMBER-1");
  EXPECT_EQ(printed("FOR R[R1]=1 TO 3"), "FOR R[R1]=1 TO 3");
  EXPECT_EQ(printed("ENDFOR"), "ENDFOR");
  EXPECT_EQ(printed("REPEAT"), "REPEAT");
  EXPECT_EQ(printed("UNTIL $AA_IW[Z] > (H-0.05)"), "UNTIL $AA_IW[Z]>(H-0.05)");
  EXPECT_EQ(printed("LOOP"), "LOOP");
  EXPECT_EQ(printed("ENDLOOP"), "ENDLOOP");
  EXPECT_EQ(printed("N30 CASE(V1+V2) OF 7 GOTOF L_1 -9 GOTOB N20 DEFAULT GOTOF L_3"),
            "N30 CASE (V1+V2) OF 7 GOTOF L_1 -9 GOTOB 20 DEFAULT GOTOF L_3");
  EXPECT_EQ(printed("CASE(1) OF 1 GOTOF A"), "CASE (1) OF 1 GOTOF A");
  // FOR holds its counter's assignment and the end value; CASE its branches after it.
  Parsed p = parse("FOR I=2 TO 5");
  ASSERT_TRUE(p.ok);
  ASSERT_EQ(p.block.statements.size(), 1u);
  const ast::Statement& f = p.block.statements[0];
  EXPECT_EQ(f.kind, ast::Statement::Kind::For);
  ASSERT_TRUE(f.then_assign);
  EXPECT_EQ(*f.then_assign->target.text, "I");
  EXPECT_EQ(f.then_assign->value.number, 2.0);
  EXPECT_EQ(f.value.number, 5.0);
  p = parse("CASE(X) OF 1 GOTOF A DEFAULT GOTOB B");
  ASSERT_TRUE(p.ok);
  ASSERT_EQ(p.block.statements.size(), 3u);
  EXPECT_EQ(p.block.statements[1].kind, ast::Statement::Kind::CaseBranch);
  EXPECT_EQ(p.block.statements[1].jump, ast::Jump::Forward);
  EXPECT_EQ(p.block.statements[2].value.kind, ast::Expr::Kind::Vacant);
  EXPECT_EQ(p.block.statements[2].jump, ast::Jump::Backward);
}

TEST(DinParser, ProcParametersAndReturn) {
  EXPECT_EQ(printed("PROC POSITION1 (REAL XWERT, VAR INT N) DISPLOF SBLOF"),
            "PROC POSITION1(REAL XWERT,VAR INT N)");
  EXPECT_EQ(printed("PROC MYKONTUR"), "PROC MYKONTUR");
  EXPECT_EQ(printed("N90 RET"), "N90 RET");
  EXPECT_EQ(printed("X=IC(5) Y=AC(R1*2)"), "X=IC(5) Y=AC(R1*2)");
  Parsed p = parse("PROC P(REAL A, VAR BOOL B)");
  ASSERT_TRUE(p.ok);
  ASSERT_EQ(p.block.statements.size(), 3u);
  EXPECT_EQ(p.block.statements[0].kind, ast::Statement::Kind::Proc);
  EXPECT_EQ(*p.block.statements[0].target.text, "P");
  EXPECT_EQ(p.block.statements[1].kind, ast::Statement::Kind::Parameter);
  EXPECT_EQ(p.block.statements[1].type, ast::DataType::Real);
  EXPECT_EQ(p.block.statements[1].loop_id, 0);
  EXPECT_EQ(p.block.statements[2].type, ast::DataType::Bool);
  EXPECT_EQ(p.block.statements[2].loop_id, 1);  // VAR
  EXPECT_EQ(*p.block.statements[2].target.text, "B");
}

TEST(DinParser, LocationsAreColumnsOfTheLine) {
  Parsed p = parse("N5 R1=2 X=R1");
  ASSERT_TRUE(p.ok);
  ASSERT_EQ(p.block.statements.size(), 1u);
  EXPECT_EQ(p.block.statements[0].loc.column, 4u);
  ASSERT_EQ(p.block.words.size(), 1u);
  EXPECT_EQ(p.block.words[0].loc.column, 9u);
  EXPECT_EQ(p.block.words[0].value.loc.column, 11u);
}

TEST(DinParser, BadTextGetsOneDiagnosticAtItsColumn) {
  struct Case {
    const char* text;
    const char* expected;
  };
  const Case cases[] = {
      {"X=(1+2", "p.mpf:1:3: error[NCC1003]: unbalanced '('"},
      {"X=1+2)", "p.mpf:1:6: error[NCC1004]: unbalanced ')'"},
      {"X=A[1)", "p.mpf:1:6: error[NCC1004]: unbalanced ')'"},
      {"X=\"abc", "p.mpf:1:3: error[NCC1018]: string '\"' is not closed by '\"'"},
      {"DEF FOO A", "p.mpf:1:5: error[NCC1019]: unknown type 'FOO'"},
      {"DEF INT[3] A", "p.mpf:1:8: error[NCC1006]: only STRING takes a length [n]"},
      {"DEF REAL R5", "p.mpf:1:10: error[NCC1006]: unexpected 'R5'"},
      {"DEF REAL ABCDEFGHIJABCDEFGHIJABCDEFGHIJAB",
       "p.mpf:1:10: error[NCC1006]: 'ABCDEFGHIJABCDEFGHIJABCDEFGHIJAB': a name has at most 31"},
      {"X=SIN(1,2)", "p.mpf:1:3: error[NCC1011]: function 'SIN' takes 1 argument"},
      {"X=SIN(,)", "p.mpf:1:7: error[NCC1011]: 'SIN': an argument is missing"},
      {"X=FOO(1)", "p.mpf:1:3: error[NCC1090]: DIN function 'FOO' is not supported yet"},
      {"X=STRLEN(1,2)", "p.mpf:1:3: error[NCC1011]: function 'STRLEN' takes 1 argument"},
      {"X=SUBSTR(1)", "p.mpf:1:3: error[NCC1011]: function 'SUBSTR' takes 2 or 3 arguments"},
      {"X=SPRINT()", "p.mpf:1:3: error[NCC1011]: function 'SPRINT' takes 1 to 65535 arguments"},
      {"DEF STRING S", "p.mpf:1:5: error[NCC1006]: STRING takes its length: STRING[n]"},
      {"DEF STRING[0] S", "p.mpf:1:12: error[NCC1015]: STRING[0]: a string holds 1 to 200"},
      {"PROC A SAVE", "p.mpf:1:8: error[NCC1090]: DIN 'PROC ... SAVE'"},
      {"PROC A FOO", "p.mpf:1:8: error[NCC1006]: 'FOO' is not a PROC attribute"},
      {"PROC A X1", "p.mpf:1:8: error[NCC1006]: a control structure keyword (PROC) stands alone"},
      {"PROC A(VAR REAL B[3])", "p.mpf:1:18: error[NCC1090]: DIN array parameters"},
      {"PROC A(VECTOR B)", "p.mpf:1:8: error[NCC1019]: unknown type 'VECTOR'"},
      {"N10 REPEATB", "p.mpf:1:5: error[NCC1006]: REPEATB takes the label of the block to repeat"},
      {"N10 WHILE 1 X10", "p.mpf:1:13: error[NCC1006]: a control structure keyword (WHILE) stands alone"},
      {"X1 ENDIF", "p.mpf:1:1: error[NCC1006]: a control structure keyword (ENDIF) stands alone"},
      {"FOR 1=2 TO 3", "p.mpf:1:5: error[NCC1006]"},
      {"FOR I=1", "p.mpf:1:8: error[NCC1010]"},
      {"CASE(1) OF X GOTOF A", "p.mpf:1:12: error[NCC1006]"},
      {"G0 X1 @", "p.mpf:1:7: error[NCC1001]: unexpected character '@'"},
      {"%_N_A B", "p.mpf:1:1: error[NCC1001]: unexpected character '%'"},
      {"X1.5=3", "p.mpf:1:1: error[NCC1006]: 'X1.5' is not a name"},
      {"XY-5", "p.mpf:1:1: error[NCC1006]: address 'XY' takes its value after '='"},
      {"GOTOF X5", "p.mpf:1:7: error[NCC1006]: 'X5' is neither a label nor a block number"},
      {"N1.5 X1", "p.mpf:1:1: error[NCC1009]"},
      {"N10 N20", "p.mpf:1:5: error[NCC1014]: second block number in one block"},
      {"X1 N20", "p.mpf:1:4: error[NCC1006]: a block number 'N' must start the block"},
      {"X=1 =", "p.mpf:1:5: error[NCC1006]: unexpected '='"},
      {"X=", "p.mpf:1:3: error[NCC1010]: block ends before the statement is complete"},
      {"/12 X1", "p.mpf:1:2: error[NCC1008]"},
      {"X=A[1,2,3,4]", "p.mpf:1:3: error[NCC1011]: 'A': arrays have at most 3 dimensions"},
  };
  for (const Case& c : cases) {
    Parsed p = parse(c.text);
    EXPECT_FALSE(p.ok) << c.text;
    EXPECT_EQ(p.diagnostics.rfind(c.expected, 0), 0u) << c.text << "\n" << p.diagnostics;
    EXPECT_EQ(std::count(p.diagnostics.begin(), p.diagnostics.end(), '\n'), 1) << c.text;
  }
}

TEST(DinParser, DeepTextIsRefusedBeforeTheParserRecurses) {
  std::string deep = "X=" + std::string(100, '(') + "1" + std::string(100, ')');
  Parsed p = parse(deep);
  EXPECT_FALSE(p.ok);
  EXPECT_NE(p.diagnostics.find("NCC1016"), std::string::npos) << p.diagnostics;
  std::string signs = "X=" + std::string(100, '-') + "1";
  p = parse(signs);
  EXPECT_FALSE(p.ok);
  EXPECT_NE(p.diagnostics.find("NCC1016"), std::string::npos) << p.diagnostics;
  std::string chain = "X=1";
  for (int i = 0; i < 300; ++i) chain += "+1";
  p = parse(chain);
  EXPECT_FALSE(p.ok);
  EXPECT_NE(p.diagnostics.find("NCC1017"), std::string::npos) << p.diagnostics;
}

}  // namespace
}  // namespace ncc::frontend
