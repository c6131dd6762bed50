// Evaluation and lowering run on blocks built without the parser, in a binary that does not
// link it (ncc_eval and ncc_passes depend on ncc_ast only): what a run-time user such as the VM
// needs to prepare blocks. The build itself is half the test: a dependency of either library on
// the parser fails to link here.
#include <variant>
#include <vector>

#include "gtest/gtest.h"
#include "memory_store.h"
#include "ncc/eval/evaluator.h"
#include "ncc/eval/variables.h"
#include "ncc/passes/lowering.h"

namespace ncc {
namespace {

ast::Expr number(double v, bool point = true) { return ast::Expr::literal(v, point, {1, 1, 1}); }

ast::Expr variable(double n) {
  ast::Expr e;
  e.kind = ast::Expr::Kind::Variable;
  e.args.push_back(number(n, false));
  return e;
}

ast::Word word(const char* address, ast::Expr value) { return ast::Word{address, std::move(value), {}}; }

struct Collect : ir::BlockSink {
  void accept(ir::Block&& b) override { blocks.push_back(std::move(b)); }
  void finish() override {}
  std::vector<ir::Block> blocks;
};

TEST(WithoutParser, EvaluationFeedsLowering) {
  // #1 = 2.5 / G01 X#1 F100. / M30
  std::vector<ast::Block> program(3);
  ast::Statement assign;
  assign.kind = ast::Statement::Kind::Assign;
  assign.target = variable(1);
  assign.value = number(2.5);
  program[0].statements.push_back(std::move(assign));
  program[1].words = {word("G", number(1, false)), word("X", variable(1)), word("F", number(100))};
  program[2].words = {word("M", number(30, false))};
  for (size_t i = 0; i < program.size(); ++i) program[i].loc = {1, static_cast<uint32_t>(i + 1), 1};

  const MachineConfig machine = defaultMachine();
  DiagnosticEngine diags;
  Collect ir;
  passes::LoweringOptions options;
  options.dialect = Dialect::FanucM;
  options.machine = &machine;
  passes::Lowering lowering(options, diags, ir);
  const eval::MacroRules& rules = eval::macroRules(Dialect::FanucM);
  eval::Variables variables(rules, {rules.commons.begin(), rules.commons.end()},
                            &lowering.systemVariables());
  std::vector<ir::SetVariable> writes;
  variables.on_write = [&](int64_t n, const eval::Value& v, SourceLocation) {
    writes.push_back({static_cast<uint32_t>(n), v.number, v.vacant, {}});
  };
  eval::test::MemoryStore store;
  const uint32_t file = store.add(std::move(program));
  eval::EvaluatorOptions eo;
  eo.rules = &rules;
  eval::Evaluator evaluator(eo, store, store.open(file), variables, diags);
  while (const ast::Block* b = evaluator.next()) {
    if (!writes.empty()) lowering.variablesWritten(b->loc, std::exchange(writes, {}));
    if (lowering.lower(*b).program_end) evaluator.programEndCode();
  }
  lowering.finish();
  ASSERT_TRUE(diags.diagnostics().empty()) << diags.diagnostics()[0].message;
  ASSERT_EQ(ir.blocks.size(), 3u);
  const auto* set = std::get_if<ir::SetVariable>(&ir.blocks[0].ops.at(0));
  ASSERT_NE(set, nullptr);
  EXPECT_EQ(set->number, 1u);
  EXPECT_EQ(set->value, 2.5);
  const auto* line = std::get_if<ir::Linear>(&ir.blocks[1].ops.at(0));
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(line->to[0], 2.5);
  EXPECT_EQ(line->feed, 100.0);
  EXPECT_EQ(evaluator.end(), eval::ProgramEnd::ProgramEndCode);
}

}  // namespace
}  // namespace ncc
