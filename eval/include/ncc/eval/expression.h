#pragma once
// Expressions of Macro B: literals, variables (#n, #[expr]), brackets, + - * / MOD, OR XOR
// AND, EQ NE GT GE LT LE, and the functions (SIN COS TAN ASIN ACOS ATAN SQRT ABS ROUND FIX
// FUP LN EXP POW ADP BIN BCD), angles in degrees. DIN adds R parameters and named variables,
// DIV, NOT, the bit operators B_AND B_OR B_XOR B_NOT, and ATAN2 POT TRUNC MINVAL MAXVAL. Vacant follows the manual: 0 in arithmetic,
// distinct from 0 only in EQ and NE. Nothing here reads the controller: variables come
// through VariableReader.
#include <optional>
#include <vector>
#include <span>
#include <string>
#include <string_view>

#include "ncc/eval/failure.h"
#include "ncc/eval/macro_rules.h"
#include "ncc/eval/value.h"
#include "ncc/frontend/ast.h"

namespace ncc::eval {

// DIN: one index of a `$` system variable: an axis name (`$AA_IW[X]`), else a number.
struct SystemIndex {
  std::string axis;
  int64_t number = 0;
};

// The failure for a `$` system variable ncc does not read (NotSupported, naming it).
std::optional<Value> unsupportedSystemVariable(std::string_view name, SourceLocation loc,
                                               Failure& failure);

class VariableReader {
 public:
  virtual ~VariableReader() = default;
  // The value of #number; nullopt after filling `failure` (a number outside every range).
  virtual std::optional<Value> read(int64_t number, SourceLocation loc, Failure& failure) = 0;
  // DIN: R n, and a variable by name with its indices (named_variables.h). A reader without
  // them (ISO only) fails with UndefinedName.
  virtual std::optional<Value> readR(int64_t n, SourceLocation loc, Failure& failure);
  virtual std::optional<Value> readNamed(std::string_view name, std::span<const int64_t> indices,
                                         SourceLocation loc, Failure& failure);
  // DIN: the type of the variable `name` (DataType::None when there is none), and the text of
  // a STRING or CHAR variable (named_variables.h, readText).
  virtual ast::DataType namedType(std::string_view name) const;
  virtual std::optional<std::string> readText(std::string_view name,
                                              std::span<const int64_t> indices,
                                              SourceLocation loc, Failure& failure);
  // DIN: a `$` system variable by name; a reader without a controller fails with NotSupported.
  virtual std::optional<Value> readSystem(std::string_view name, std::span<const SystemIndex> indices,
                                          SourceLocation loc, Failure& failure);
};

struct ExpressionContext {
  const MacroRules& rules;
  VariableReader& variables;
  // Brackets already open around the expression and counted against max_bracket_depth: 1
  // for the condition of IF [..] / WHILE [..] and for #[..] on the left of an assignment
  // (the parser keeps their contents only).
  int enclosing_brackets = 0;
  // ADP[x]: the factor from least input increments to input units (1000 with 0.001 mm).
  double adp_scale = 1000.0;
  // The expression is DIN text: AND OR XOR NOT are logic operators on truth values (ISO's AND
  // OR XOR work on the bits of integers; DIN has B_AND B_OR B_XOR for that).
  bool din = false;
};

// The value of `expr`; nullopt after filling `failure` (with the location of the offending
// sub-expression). A string where a number is needed is TypeMismatch.
std::optional<Value> evaluate(const ast::Expr& expr, const ExpressionContext& context,
                              Failure& failure);

// DIN strings (docs/din.md, Strings). What an expression gives: a number, a string (a literal,
// a STRING variable or one character of it, `<<`, SUBSTR TOUPPER TOLOWER SPRINT), or a
// character (a CHAR variable: a number in arithmetic, a one-character string beside strings).
enum class ValueKind : uint8_t { Number, Char, String };
ValueKind kindOf(const ast::Expr& expr, const VariableReader& variables);
// The text of `expr`: a string as it is, a number as `<<` writes it (10 significant digits,
// no trailing zeros: 2.5, 3); nullopt after filling `failure`.
std::optional<std::string> evaluateText(const ast::Expr& expr, const ExpressionContext& context,
                                        Failure& failure);

// The first place where `expr` nests brackets deeper than rules.max_bracket_depth (counting
// [ ], function brackets and #[ ], plus `enclosing` already open); false after filling
// `failure` (BracketNesting). evaluate() checks this first; it is public so that a
// compiler can report it without evaluating.
bool checkBracketDepth(const ast::Expr& expr, const MacroRules& rules, int enclosing,
                       Failure& failure);

// The variable number a value designates (`#[#1+1]`): rounded as the manual states; nullopt
// after filling `failure` (vacant or out of range).
std::optional<int64_t> variableNumber(const Value& value, const MacroRules& rules,
                                      SourceLocation loc, Failure& failure);

// The variable an assignment writes (`#5 = ..`, `#[#1+1] = ..`; `target` is the statement's
// Variable expression): the brackets of #[..] count as one level. nullopt after filling
// `failure`: VariableNumber as above, VariableReadOnly for #0 ("#0 cannot be on the left",
// Mazak §13-9-3 2.). Whether a system variable may be written is the caller's to say.
std::optional<int64_t> assignmentTarget(const ast::Expr& target, const ExpressionContext& context,
                                        Failure& failure);

// DIN: the values of an array's indices `A[i,j]` (rounded to integers); nullopt after filling
// `failure`.
std::optional<std::vector<int64_t>> indicesOf(const std::vector<ast::Expr>& args,
                                              const ExpressionContext& context, Failure& failure);

// A condition (IF, WHILE): true when the value is not 0 (vacant is false).
bool isTrue(const Value& value);

}  // namespace ncc::eval
