#include "ncc/eval/variables.h"

#include "absl/strings/str_cat.h"

namespace ncc::eval {

std::optional<Value> Variables::readSystem(std::string_view name, std::span<const SystemIndex> indices,
                                           SourceLocation loc, Failure& failure) {
  // ISO mode's macro arguments in a DIN body (840D ISO §4.11, table 4.10): $C_X is the value of
  // X (the local G65 type I gives it), $C_X_PROG (the manual's example writes _PROC) whether it
  // was programmed.
  constexpr std::string_view kArgument = "$C_";
  if (name.substr(0, kArgument.size()) == kArgument && indices.empty()) {
    std::string_view rest = name.substr(kArgument.size());
    bool programmed = false;
    if (rest.size() == 6 && (rest.substr(1) == "_PROG" || rest.substr(1) == "_PROC")) {
      programmed = true;
      rest = rest.substr(0, 1);
    }
    if (rest.size() == 1 && rest[0] >= 'A' && rest[0] <= 'Z') {
      if (const int local = rules_.argument_spec1[static_cast<size_t>(rest[0] - 'A')]; local != 0) {
        std::optional<Value> v = read(local, loc, failure);
        if (!v || !programmed) return v;
        return Value::of(v->vacant ? 0.0 : 1.0);
      }
    }
  }
  return system_ ? system_->readSystem(name, indices, loc, failure)
                 : unsupportedSystemVariable(name, loc, failure);
}

std::optional<Value> SystemVariables::readSystem(std::string_view name,
                                                 std::span<const SystemIndex>,
                                                 SourceLocation loc, Failure& failure) {
  return unsupportedSystemVariable(name, loc, failure);
}

namespace {
// #1000 and up are the controller's (interface signals, offsets, positions, ...).
constexpr int64_t kFirstSystemVariable = 1000;
}  // namespace

Variables::Variables(const MacroRules& rules, std::vector<VariableRange> commons,
                     SystemVariables* system)
    : rules_(rules), commons_(std::move(commons)), system_(system) {
  locals_.push_back(freshLocals());  // level 0: the main program, no arguments
  named_.on_write = [this](int64_t n, const Value& v, SourceLocation loc) {
    if (on_write) on_write(n, v, loc);
  };
}

bool Variables::isCommon(int64_t number) const {
  for (const VariableRange& r : commons_)
    if (r.contains(number)) return true;
  return false;
}

bool Variables::isPersistent(int64_t number) const {
  return number >= rules_.persistent_first && isCommon(number);
}

std::optional<Value> Variables::read(int64_t number, SourceLocation loc, Failure& failure) {
  if (number == 0) return Value::none();
  if (number > 0 && number <= rules_.local_count) return locals_.back()[number];
  if (isCommon(number)) {
    auto it = common_values_.find(number);
    return it == common_values_.end() ? Value::none() : it->second;
  }
  if (number >= kFirstSystemVariable && system_) return system_->read(number, loc, failure);
  failure = {EvalError::VariableNumber, loc,
             absl::StrCat("#", number, " is not a variable of this controller"), 0};
  return std::nullopt;
}

bool Variables::write(int64_t number, const Value& value, SourceLocation loc, Failure& failure) {
  if (number == 0) {
    failure = {EvalError::VariableReadOnly, loc, "#0 is always vacant and cannot be assigned", 0};
    return false;
  }
  if (number > 0 && number <= rules_.local_count) {
    locals_.back()[number] = value;
    if (level() == 0 && on_write) on_write(number, value, loc);
    return true;
  }
  if (isCommon(number)) {
    common_values_[number] = value;
    if (on_write) on_write(number, value, loc);
    return true;
  }
  if (number >= kFirstSystemVariable && system_) {
    if (!system_->write(number, value, loc, failure)) return false;
    if (on_write) on_write(number, value, loc);
    return true;
  }
  failure = {EvalError::VariableNumber, loc,
             absl::StrCat("#", number, " is not a variable of this controller"), 0};
  return false;
}

void Variables::pushLocals(Locals locals) {
  locals.resize(static_cast<size_t>(rules_.local_count) + 1);
  locals_.push_back(std::move(locals));
}

void Variables::popLocals() {
  if (locals_.size() > 1) locals_.pop_back();
}

std::map<int64_t, double> Variables::persistent() const {
  std::map<int64_t, double> out;
  for (const auto& [n, v] : common_values_)
    if (!v.vacant && isPersistent(n)) out[n] = v.number;
  return out;
}

bool Variables::setPersistent(int64_t number, double value, SourceLocation loc) {
  if (!isPersistent(number)) return false;
  common_values_[number] = Value::of(value);
  if (on_write) on_write(number, Value::of(value), loc);
  return true;
}

}  // namespace ncc::eval
