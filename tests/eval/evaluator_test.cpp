// The evaluator over a program store that is not a source file: blocks parsed up front and held
// in memory, as a run-time user of the library (the VM) would hand them over. Checks the
// blocks it gives lowering, its control flow and calls, and its failures' alarm numbers.
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "eval_harness.h"
#include "memory_store.h"
#include "gtest/gtest.h"
#include "ncc/eval/evaluator.h"
#include "ncc/eval/macro_rules.h"
#include "ncc/eval/variables.h"
#include "ncc/frontend/block_reader.h"

namespace ncc::eval {
namespace {

using test::MemoryStore;

// The blocks of a program text, one a line (each must parse), for `store`'s next file.
std::vector<ast::Block> parse(MemoryStore& store, std::string_view text) {
  std::vector<ast::Block> blocks;
  std::istringstream in{std::string(text)};
  std::string line;
  for (uint32_t n = 1; std::getline(in, line); ++n) {
    DiagnosticEngine diags;
    std::optional<ast::Block> b = frontend::parseIsoBlock(line, store.nextFile(), n, diags);
    EXPECT_TRUE(b) << line;
    if (b) blocks.push_back(std::move(*b));
  }
  return blocks;
}

struct EvalRun {
  std::vector<std::string> blocks;  // printed as lowering gets them
  std::map<int64_t, double> writes; // last value written per kept variable
  std::vector<Diagnostic> diagnostics;
  ProgramEnd end = ProgramEnd::Running;
};

EvalRun run(std::string_view program, Dialect dialect = Dialect::FanucM, uint64_t max_back_jumps = 0) {
  const MacroRules& rules = macroRules(dialect);
  MemoryStore store;
  const uint32_t main = store.add(parse(store, program));
  Variables variables(rules, {rules.commons.begin(), rules.commons.end()}, nullptr);
  EvalRun out;
  variables.on_write = [&](int64_t n, const Value& v, SourceLocation) {
    out.writes[n] = v.arithmetic();
  };
  DiagnosticEngine diags;
  EvaluatorOptions options;
  options.rules = &rules;
  options.repeat = rules.repeat;
  options.limits.max_back_jumps = max_back_jumps;
  // As the block loop sets it: siemens-iso-m reads DIN after G290 (passes::languageTables).
  options.language_switch = dialect == Dialect::SiemensIsoM;
  options.is_axis = [](std::string_view a) { return a == "X" || a == "Y" || a == "Z"; };
  Evaluator evaluator(options, store, store.open(main), variables, diags);
  while (const ast::Block* b = evaluator.next()) {
    out.blocks.push_back(frontend::printBlock(*b));
    for (const ast::Word& w : b->words)
      if (w.address == "M" && (w.value.number == 30 || w.value.number == 2)) evaluator.programEndCode();
  }
  out.diagnostics = diags.diagnostics();
  out.end = evaluator.end();
  return out;
}

TEST(Evaluator, PlainBlocksPassThroughAndExpressionsBecomeNumbers) {
  EvalRun r = run("G90 G00 X1. Y2.\n#1=2.5\n#2=#0\nG01 X[#1*2] Y#2 Z-#1 F100.\nM30\n");
  EXPECT_EQ(r.blocks, (std::vector<std::string>{"G90 G0 X1. Y2.", "G1 X5. Z-2.5 F100.", "M30"}));
  EXPECT_EQ(r.end, ProgramEnd::ProgramEndCode);
  EXPECT_TRUE(r.diagnostics.empty());
}

TEST(Evaluator, AComputedLanguageSwitchIsRefused) {
  // The reader switches language on G290/G291 as written; a computed one it cannot see.
  EvalRun r = run("#1=290\nG#1\nM30\n", Dialect::SiemensIsoM);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].location.line, 2u);
  EXPECT_EQ(r.diagnostics[0].code, std::string(macroRules(Dialect::SiemensIsoM).alarm(EvalError::AddressValue)));
  EXPECT_NE(r.diagnostics[0].message.find("G290 must be written as a number"), std::string::npos)
      << r.diagnostics[0].message;
  // Elsewhere G290 is not a language code: the value goes on to lowering, which judges it.
  EvalRun fanuc = run("#1=290\nG#1\nM30\n", Dialect::FanucM);
  EXPECT_TRUE(fanuc.diagnostics.empty());
  EXPECT_EQ(fanuc.blocks.front(), "G290");
}

TEST(Evaluator, LoopsAndJumps) {
  EvalRun r = run("#100=0\n#1=0\nN5 IF [#1 GE 3] GOTO 9\n#1=#1+1\n#100=#100+#1\nGOTO 5\n"
              "N9 WHILE [#1 GT 0] DO1\nX#1\n#1=#1-1\nEND1\nM30\n");
  EXPECT_EQ(r.writes[100], 6.0);
  // A statement block keeps its sequence number for lowering (which has nothing to do there).
  EXPECT_EQ(r.blocks, (std::vector<std::string>{"N5", "N5", "N5", "N5", "N9", "X3.", "N9", "X2.",
                                                "N9", "X1.", "N9", "M30"}));
}

TEST(Evaluator, EndlessLoopStopsAtItsJump) {
  EvalRun r = run("N1 #100=1\nGOTO 1\nM30\n", Dialect::FanucM, 50);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "NCC2419");
  EXPECT_EQ(r.diagnostics[0].location.line, 2u);
  EXPECT_EQ(r.end, ProgramEnd::Alarm);
}

TEST(Evaluator, CallsReturnsAndRepeats) {
  EvalRun r = run("#100=0\nM98 P10 L3\nG65 P20 A4. B5.\n#101=#1\nM30\nO10\n#100=#100+1\nM99\n"
              "O20\n#102=#1*#2\n#1=7\nM99\n", Dialect::MazakM);
  EXPECT_EQ(r.writes[100], 3.0);
  EXPECT_EQ(r.writes[102], 20.0);
  EXPECT_EQ(r.writes[101], 0.0);  // the main program's #1 is still vacant: G65 had its own
  EXPECT_TRUE(r.diagnostics.empty());
}

TEST(Evaluator, ModalCallAfterEachMotionBlock) {
  EvalRun r = run("#100=0\nG66 P30 A1.\nX1.\nM05\nY2.\nG67\nX3.\nM30\nO30\n#100=#100+#1\nM99\n",
              Dialect::MazakM);
  EXPECT_EQ(r.writes[100], 2.0);  // after X1. and Y2., not after M05 nor after G67
  EXPECT_EQ(r.blocks, (std::vector<std::string>{"X1.", "M5", "Y2.", "X3.", "M30"}));
}

TEST(Evaluator, FailuresCarryTheDialectsAlarmNumbers) {
  struct Case {
    const char* program;
    const char* code;
    uint32_t line;
  } cases[] = {
      {"#1=1\nGOTO 7\nM30\n", "843", 2},
      {"M98 P1234\nM30\n", "844", 1},
      {"G67\nM30\n", "857", 1},
      {"#1=LN[0]\nM30\n", "860", 1},
      {"#3000=30 (STOP)\nM30\n", "3030", 1},
      {"END 1\nM30\n", "NCC2407", 1},
  };
  for (const Case& c : cases) {
    EvalRun r = run(c.program, Dialect::MazakM);
    ASSERT_FALSE(r.diagnostics.empty()) << c.program;
    EXPECT_EQ(r.diagnostics[0].code, c.code) << c.program;
    EXPECT_EQ(r.diagnostics[0].location.line, c.line) << c.program;
    EXPECT_EQ(r.end, ProgramEnd::Alarm) << c.program;
  }
}

}  // namespace
}  // namespace ncc::eval
