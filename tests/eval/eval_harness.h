#pragma once
// Test helpers: parse real block text with the ISO parser and evaluate its expressions
// against a map of variables.
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "ncc/eval/expression.h"
#include "ncc/frontend/ast.h"

namespace ncc::eval::test {

// #0 is vacant; #1-#33 and #100-#999 hold values (vacant until written); other numbers are
// VariableNumber failures, like a controller without those variables.
class MapVariables : public VariableReader {
 public:
  std::optional<Value> read(int64_t number, SourceLocation loc, Failure& failure) override;
  Value get(int64_t n) const;
  void set(int64_t n, Value v) { values[n] = v; }
  std::map<int64_t, Value> values;
};

// The block of one line of text (the parse must succeed).
ast::Block parseBlock(std::string_view text, uint32_t line = 1);

struct Outcome {
  std::optional<Value> value;
  Failure failure;
};

// Evaluates `expression` written as the value of `#1=<expression>`.
Outcome evalText(std::string_view expression, const MacroRules& rules, MapVariables& vars);
Outcome evalText(std::string_view expression, const MacroRules& rules);

// Runs a program made of assignment blocks (other words are ignored): each block's values are
// computed from the variables before the block, then assigned. Stops at the first failure and
// returns it (with its line).
std::optional<Failure> runAssignments(std::string_view program, const MacroRules& rules,
                                      MapVariables& vars);

}  // namespace ncc::eval::test
