#include "eval_harness.h"

#include <gtest/gtest.h>

#include <sstream>
#include <utility>
#include <vector>

#include "ncc/frontend/block_reader.h"
#include "ncc/support/diagnostics.h"

namespace ncc::eval::test {

std::optional<Value> MapVariables::read(int64_t number, SourceLocation loc, Failure& failure) {
  if (number == 0) return Value::none();
  if ((number >= 1 && number <= 33) || (number >= 100 && number <= 999)) return get(number);
  failure.error = EvalError::VariableNumber;
  failure.loc = loc;
  failure.message = "no variable #" + std::to_string(number);
  return std::nullopt;
}

Value MapVariables::get(int64_t n) const {
  auto it = values.find(n);
  return it == values.end() ? Value::none() : it->second;
}

ast::Block parseBlock(std::string_view text, uint32_t line) {
  DiagnosticEngine diags;
  auto block = frontend::parseIsoBlock(text, 1, line, diags);
  EXPECT_TRUE(block.has_value()) << "does not parse: " << text;
  EXPECT_EQ(diags.errorCount(), 0u) << text;
  return block ? std::move(*block) : ast::Block{};
}

Outcome evalText(std::string_view expression, const MacroRules& rules, MapVariables& vars) {
  const ast::Block block = parseBlock("#1=" + std::string(expression));
  Outcome out;
  if (block.statements.size() != 1) {
    ADD_FAILURE() << "not one assignment: " << expression;
    return out;
  }
  out.value = evaluate(block.statements[0].value, ExpressionContext{rules, vars}, out.failure);
  return out;
}

Outcome evalText(std::string_view expression, const MacroRules& rules) {
  MapVariables vars;
  return evalText(expression, rules, vars);
}

std::optional<Failure> runAssignments(std::string_view program, const MacroRules& rules,
                                      MapVariables& vars) {
  std::istringstream in{std::string(program)};
  std::string text;
  uint32_t line = 0;
  while (std::getline(in, text)) {
    ++line;
    const ast::Block block = parseBlock(text, line);
    std::vector<std::pair<int64_t, Value>> writes;
    for (const ast::Statement& s : block.statements) {
      if (s.kind != ast::Statement::Kind::Assign) continue;
      Failure failure;
      auto n = assignmentTarget(s.target, ExpressionContext{rules, vars}, failure);
      if (!n) return failure;
      auto value = evaluate(s.value, ExpressionContext{rules, vars}, failure);
      if (!value) return failure;
      writes.emplace_back(*n, *value);
    }
    for (auto& [n, v] : writes) vars.set(n, v);
  }
  return std::nullopt;
}

}  // namespace ncc::eval::test
