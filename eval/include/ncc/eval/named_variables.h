#pragma once
// The variables of the DIN language (docs/din.md, Variables): the R parameters and the
// variables DEF declares, by name, typed, arrays up to three dimensions. A DIN variable is
// never vacant: R parameters and DEF'd variables start at 0 (or their initial value).
//
// Each variable of the main program has a number in the run's variable space, after the ISO
// `#` numbers, so that the IR and the VM keep it as they keep `#n` (ir::SetVariable) and the
// bytecode names it for `--emit=vars`: R n is kFirstNumber + n, the DEF'd ones follow in the
// order they are declared, one number per array element. Variables of a called PROC have no
// number (they end with the call), as the locals of an ISO macro call.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <variant>
#include <vector>

#include "ncc/eval/failure.h"
#include "ncc/eval/value.h"
#include "ncc/frontend/ast.h"

namespace ncc::eval {

// What a DIN variable holds or is given: a number, or a text (a STRING; a CHAR given "E").
using Datum = std::variant<Value, std::string>;

class NamedVariables {
 public:
  // R0 .. R999 (an 840D has 100 by default, machine data MM_NUM_R_PARAM raises it to 1000 and
  // more; real programs use up to R999).
  static constexpr int64_t kRParameters = 1000;
  // The first number after the ISO variables (bytecode::kDefaultVariableCount).
  static constexpr uint32_t kFirstNumber = 10000;
  // The numbers DIN variables may take: the VM's variable space ends at 100000.
  static constexpr uint32_t kLastNumber = 99999;
  // Elements of one array (the 840D limit for a local array is far lower; this bounds memory).
  static constexpr int64_t kMaxElements = 1 << 16;

  struct Variable {
    ast::DataType type = ast::DataType::Real;
    std::array<int64_t, 3> dims{1, 1, 1};
    int rank = 0;                // 0: a scalar
    uint32_t first_number = 0;   // 0: none (a PROC's variable, a STRING)
    std::vector<double> values;  // row-major; a STRING's are in `texts`
    std::vector<std::string> texts;
    int length = 0;              // STRING[n]: n
  };

  // R n; `failure` (VariableNumber) for n outside 0 .. kRParameters-1.
  std::optional<Value> readR(int64_t n, SourceLocation loc, Failure& failure) const;
  bool writeR(int64_t n, const Value& value, SourceLocation loc, Failure& failure);

  // DEF: a new variable of the current scope with its type, STRING length, dimensions (empty:
  // a scalar) and initial value (nullopt: the type's zero, "" for a STRING), converted as
  // write() converts. False after filling `failure`: the name is declared already in this
  // scope, a dimension is not positive, the type is not built yet, the value does not fit.
  bool define(std::string_view name, ast::DataType type, int length, std::span<const int64_t> dims,
              const std::optional<Datum>& initial, SourceLocation loc, Failure& failure);
  const Variable* find(std::string_view name) const;
  // Whether any variable is declared in the current scope (most programs declare none: a word
  // then needs no look-up).
  bool any() const { return !scopes_.back().variables.empty(); }
  // A variable's element; `failure` for an undefined name (UndefinedName) or an index outside
  // the array (ArrayIndex).
  std::optional<Value> read(std::string_view name, std::span<const int64_t> indices,
                            SourceLocation loc, Failure& failure) const;
  // A STRING (or one character of it, `S[2]`), or a CHAR as a one-character text; TypeMismatch
  // for a variable of another type.
  std::optional<std::string> readText(std::string_view name, std::span<const int64_t> indices,
                                      SourceLocation loc, Failure& failure) const;
  // An element as the type holds it: a STRING's text, another type's number.
  std::optional<Datum> readDatum(std::string_view name, std::span<const int64_t> indices,
                                 SourceLocation loc, Failure& failure) const;
  // Writes converting to the variable's type (Job Planning, type conversion): INT rounds, BOOL
  // is 0 or 1, a STRING takes a number as its text (2.5 -> "2.5") and at most its length, a
  // CHAR a one-character text as its code. A text written to a number is TypeMismatch.
  bool write(std::string_view name, std::span<const int64_t> indices, const Datum& value,
             SourceLocation loc, Failure& failure);

  // SET and REP (docs/din.md, Arrays): the elements of array `name` from `first` on (empty: the
  // first element), in memory order; fill() gives them `values` in turn (nullopt: left as it
  // is), converted as write() converts, all or none; TooManyValues past the last element.
  std::optional<size_t> elementsFrom(std::string_view name, std::span<const int64_t> first,
                                     SourceLocation loc, Failure& failure) const;
  bool fill(std::string_view name, std::span<const int64_t> first,
            std::span<const std::optional<Datum>> values, SourceLocation loc, Failure& failure);

  // A PROC call opens a scope of its own; its return closes it.
  void pushScope();
  void popScope();

  // The name of variable number `n` (`R10`, `COUNT`, `A[1,2]`); empty when none has it.
  std::string nameOf(uint32_t n) const;

  // Every write of a variable with a number, in program order (Variables::on_write).
  std::function<void(int64_t number, const Value& value, SourceLocation loc)> on_write;

 private:
  struct Scope {
    std::unordered_map<std::string, Variable> variables;
  };
  // The variable `name` of the current scope; nullptr after filling `failure` (UndefinedName).
  const Variable* declared(std::string_view name, SourceLocation loc, Failure& failure) const;
  Variable* declared(std::string_view name, SourceLocation loc, Failure& failure);
  // `d` as variable `v` (named `name`) holds it; nullopt after filling `failure`.
  static std::optional<std::string> textFor(const Variable& v, std::string_view name,
                                            const Datum& d, SourceLocation loc, Failure& failure);
  static std::optional<double> numberFor(const Variable& v, std::string_view name, const Datum& d,
                                         SourceLocation loc, Failure& failure);
  std::optional<size_t> firstElement(std::string_view name, const Variable& v,
                                     std::span<const int64_t> first, SourceLocation loc,
                                     Failure& failure) const;
  std::optional<size_t> element(std::string_view name, const Variable& v,
                                std::span<const int64_t> indices, SourceLocation loc,
                                Failure& failure) const;

  std::array<double, kRParameters> r_{};
  std::vector<Scope> scopes_{Scope{}};
  uint32_t next_number_ = kFirstNumber + kRParameters;
  // Number -> (name, the variable's first number): the main program's DEF'd variables.
  std::vector<std::pair<std::string, const Variable*>> numbered_;
};

}  // namespace ncc::eval
