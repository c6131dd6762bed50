#pragma once
// The variables a program reads and writes: #0 (always vacant), the locals #1..#33 with a
// fresh set per macro call, the common variables, and the system variables, which belong to
// the controller model and are reached through SystemVariables. One store: the evaluator and
// G10 (through the controller model) read and write the same values.
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <vector>

#include "ncc/eval/expression.h"
#include "ncc/eval/macro_rules.h"
#include "ncc/eval/named_variables.h"
#include "ncc/eval/value.h"

namespace ncc::eval {

// The controller's numbered parameters (#1000 and up: signals, offset registers, modal
// information, positions, work offsets), implemented by the controller model.
class SystemVariables {
 public:
  virtual ~SystemVariables() = default;
  // nullopt after filling `failure`: no such variable, or one only known when the program
  // runs on the machine.
  virtual std::optional<Value> read(int64_t number, SourceLocation loc, Failure& failure) = 0;
  // False after filling `failure` (read-only, out of range).
  virtual bool write(int64_t number, const Value& value, SourceLocation loc,
                     Failure& failure) = 0;
  // DIN: a `$` system variable by name (`$AA_IW[X]`); this default has none.
  virtual std::optional<Value> readSystem(std::string_view name, std::span<const SystemIndex> indices,
                                          SourceLocation loc, Failure& failure);
};

class Variables final : public VariableReader {
 public:
  // `commons`: the common-variable ranges in force (the dialect's default or the machine's
  // `common_variables` set); `system` may be null (no system variables).
  Variables(const MacroRules& rules, std::vector<VariableRange> commons, SystemVariables* system);

  std::optional<Value> read(int64_t number, SourceLocation loc, Failure& failure) override;
  bool write(int64_t number, const Value& value, SourceLocation loc, Failure& failure);

  // DIN's R parameters and DEF'd variables; their writes reach on_write too.
  NamedVariables& named() { return named_; }
  const NamedVariables& named() const { return named_; }
  std::optional<Value> readR(int64_t n, SourceLocation loc, Failure& failure) override {
    return named_.readR(n, loc, failure);
  }
  std::optional<Value> readNamed(std::string_view name, std::span<const int64_t> indices,
                                 SourceLocation loc, Failure& failure) override {
    return named_.read(name, indices, loc, failure);
  }
  ast::DataType namedType(std::string_view name) const override {
    const NamedVariables::Variable* v = named_.find(name);
    return v ? v->type : ast::DataType::None;
  }
  std::optional<std::string> readText(std::string_view name, std::span<const int64_t> indices,
                                      SourceLocation loc, Failure& failure) override {
    return named_.readText(name, indices, loc, failure);
  }
  // `$C_X` (the macro argument X) here; other `$` names from the controller (`system`).
  std::optional<Value> readSystem(std::string_view name, std::span<const SystemIndex> indices,
                                  SourceLocation loc, Failure& failure) override;

  // A macro call opens a new set of locals (all vacant but the arguments); its return
  // closes it.
  using Locals = std::vector<Value>;  // index = variable number (0 unused)
  Locals freshLocals() const { return Locals(static_cast<size_t>(rules_.local_count) + 1); }
  void pushLocals(Locals locals);
  void popLocals();
  int level() const { return static_cast<int>(locals_.size()) - 1; }

  // Every write of a variable the program keeps (commons, the main level's locals, system
  // variables the model stores), in program order: the IR records them for the VM.
  std::function<void(int64_t number, const Value& value, SourceLocation loc)> on_write;

  // Commons from rules.persistent_first on (the variables file of --vars).
  std::map<int64_t, double> persistent() const;
  bool isPersistent(int64_t number) const;
  // Loads a saved value of a persistent common (`loc`: where it was saved); false for a
  // number that is not one. Reported to on_write like any write, so the run ends with it.
  bool setPersistent(int64_t number, double value, SourceLocation loc);

  bool isCommon(int64_t number) const;

 private:
  const MacroRules& rules_;
  std::vector<VariableRange> commons_;
  SystemVariables* system_;
  std::vector<Locals> locals_;
  std::map<int64_t, Value> common_values_;
  NamedVariables named_;
};

}  // namespace ncc::eval
