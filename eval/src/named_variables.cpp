#include "ncc/eval/named_variables.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "number_format.h"

namespace ncc::eval {

namespace {

bool fail(Failure& failure, EvalError error, SourceLocation loc, std::string message) {
  failure = {error, loc, std::move(message), 0};
  return false;
}

const char* typeName(ast::DataType t) { return ast::kDataTypeNames[static_cast<size_t>(t)]; }

// The value a variable of type `t` holds after `v` is written to it: INT rounds to the nearest
// integer (Fundamentals, type conversion REAL -> INT), BOOL is 1 for any value but 0.
double converted(ast::DataType t, double v) {
  switch (t) {
    case ast::DataType::Int: return std::round(v);
    case ast::DataType::Bool: return v != 0.0 ? 1.0 : 0.0;
    case ast::DataType::Char: return std::round(v);
    default: return v;
  }
}

}  // namespace

std::optional<Value> NamedVariables::readR(int64_t n, SourceLocation loc, Failure& failure) const {
  if (n < 0 || n >= kRParameters) {
    fail(failure, EvalError::VariableNumber, loc,
         absl::StrCat("R", n, ": R parameters are R0 to R", kRParameters - 1));
    return std::nullopt;
  }
  return Value::of(r_[static_cast<size_t>(n)]);
}

bool NamedVariables::writeR(int64_t n, const Value& value, SourceLocation loc, Failure& failure) {
  if (n < 0 || n >= kRParameters)
    return fail(failure, EvalError::VariableNumber, loc,
                absl::StrCat("R", n, ": R parameters are R0 to R", kRParameters - 1));
  r_[static_cast<size_t>(n)] = value.arithmetic();
  if (on_write) on_write(kFirstNumber + n, Value::of(value.arithmetic()), loc);
  return true;
}

bool NamedVariables::define(std::string_view name, ast::DataType type, int length,
                            std::span<const int64_t> dims, const std::optional<Datum>& initial,
                            SourceLocation loc, Failure& failure) {
  if (type == ast::DataType::Axis || type == ast::DataType::Frame || type == ast::DataType::None)
    return fail(failure, EvalError::NotSupported, loc,
                absl::StrCat("DEF ", typeName(type), ": variables of type ", typeName(type),
                             " are not supported yet (docs/din.md)"));
  Scope& scope = scopes_.back();
  const std::string key(name);
  if (scope.variables.count(key))
    return fail(failure, EvalError::NameDefinedTwice, loc,
                absl::StrCat("'", key, "' is declared already"));
  Variable v;
  v.type = type;
  v.length = type == ast::DataType::String ? std::clamp(length, 1, ast::kMaxStringLength) : 0;
  v.rank = static_cast<int>(dims.size());
  int64_t elements = 1;
  for (size_t i = 0; i < dims.size(); ++i) {
    if (dims[i] < 1 || dims[i] > kMaxElements)
      return fail(failure, EvalError::ArrayIndex, loc,
                  absl::StrCat("'", key, "': array dimension ", dims[i], " is not 1 to ",
                               kMaxElements));
    v.dims[i] = dims[i];
    elements *= dims[i];
    if (elements > kMaxElements)
      return fail(failure, EvalError::ArrayIndex, loc,
                  absl::StrCat("'", key, "': more than ", kMaxElements, " elements"));
  }
  // The initial value, converted by the type's rules: checked on a scalar of the type first.
  if (type == ast::DataType::String) {
    std::string start;
    if (initial) {
      std::optional<std::string> t = textFor(v, key, *initial, loc, failure);
      if (!t) return false;
      start = std::move(*t);
    }
    v.texts.assign(static_cast<size_t>(elements), start);
  } else {
    double start = 0.0;
    if (initial) {
      std::optional<double> n = numberFor(v, key, *initial, loc, failure);
      if (!n) return false;
      start = *n;
    }
    v.values.assign(static_cast<size_t>(elements), start);
  }
  const bool main_level = scopes_.size() == 1;
  if (main_level && type != ast::DataType::String &&
      next_number_ + static_cast<uint64_t>(elements) - 1 <= kLastNumber) {
    v.first_number = next_number_;
    next_number_ += static_cast<uint32_t>(elements);
  }
  auto [it, added] = scope.variables.emplace(key, std::move(v));
  const Variable& stored = it->second;
  if (stored.first_number != 0) {
    numbered_.emplace_back(key, &stored);
    if (on_write)
      for (size_t i = 0; i < stored.values.size(); ++i)
        on_write(stored.first_number + i, Value::of(stored.values[i]), loc);
  }
  return true;
}

std::optional<std::string> NamedVariables::textFor(const Variable& v, std::string_view name,
                                                   const Datum& d, SourceLocation loc,
                                                   Failure& failure) {
  std::string text = std::holds_alternative<std::string>(d)
                         ? std::get<std::string>(d)
                         : formatNumber(std::get<Value>(d).arithmetic());
  if (static_cast<int>(text.size()) > v.length) {
    fail(failure, EvalError::ValueRange, loc,
         absl::StrCat("'", std::string(name), "' is a STRING[", v.length, "]: \"",
                      text.substr(0, 40), text.size() > 40 ? "..." : "", "\" has ", text.size(),
                      " characters"));
    return std::nullopt;
  }
  return text;
}

std::optional<double> NamedVariables::numberFor(const Variable& v, std::string_view name,
                                                const Datum& d, SourceLocation loc,
                                                Failure& failure) {
  if (const Value* n = std::get_if<Value>(&d)) {
    const double x = converted(v.type, n->arithmetic());
    if (v.type == ast::DataType::Char && !(x >= 0 && x <= 255)) {
      fail(failure, EvalError::ValueRange, loc,
           absl::StrCat("'", std::string(name), "' is a CHAR: a character code is 0 to 255, not ",
                        formatNumber(n->arithmetic())));
      return std::nullopt;
    }
    return x;
  }
  const std::string& text = std::get<std::string>(d);
  if (v.type == ast::DataType::Char && text.size() == 1)
    return static_cast<double>(static_cast<unsigned char>(text[0]));
  fail(failure, EvalError::TypeMismatch, loc,
       v.type == ast::DataType::Char
           ? absl::StrCat("'", std::string(name), "' is a CHAR: it takes one character, not \"",
                          text.substr(0, 40), "\"")
           : absl::StrCat("'", std::string(name), "' is ", typeName(v.type),
                          ": a string is not a number (NUMBER(\"...\") reads one)"));
  return std::nullopt;
}

const NamedVariables::Variable* NamedVariables::declared(std::string_view name, SourceLocation loc,
                                                        Failure& failure) const {
  const Variable* v = find(name);
  if (!v) fail(failure, EvalError::UndefinedName, loc, absl::StrCat("'", std::string(name), "' is not defined"));
  return v;
}

NamedVariables::Variable* NamedVariables::declared(std::string_view name, SourceLocation loc,
                                                  Failure& failure) {
  return const_cast<Variable*>(std::as_const(*this).declared(name, loc, failure));
}

const NamedVariables::Variable* NamedVariables::find(std::string_view name) const {
  auto it = scopes_.back().variables.find(std::string(name));
  return it == scopes_.back().variables.end() ? nullptr : &it->second;
}

std::optional<size_t> NamedVariables::element(std::string_view name, const Variable& v,
                                              std::span<const int64_t> indices,
                                              SourceLocation loc, Failure& failure) const {
  if (static_cast<int>(indices.size()) != v.rank) {
    fail(failure, EvalError::ArrayIndex, loc,
         v.rank == 0 ? absl::StrCat("'", std::string(name), "' is not an array")
                     : absl::StrCat("'", std::string(name), "' has ", v.rank, " dimension",
                                    v.rank == 1 ? "" : "s", ", not ", indices.size()));
    return std::nullopt;
  }
  size_t at = 0;
  for (int i = 0; i < v.rank; ++i) {
    // Indices count from 0 (Fundamentals, arrays: A[0] .. A[n-1]).
    if (indices[i] < 0 || indices[i] >= v.dims[i]) {
      fail(failure, EvalError::ArrayIndex, loc,
           absl::StrCat("'", std::string(name), "': index ", indices[i], " is outside 0 to ", v.dims[i] - 1));
      return std::nullopt;
    }
    at = at * static_cast<size_t>(v.dims[i]) + static_cast<size_t>(indices[i]);
  }
  return at;
}

std::optional<Value> NamedVariables::read(std::string_view name, std::span<const int64_t> indices,
                                          SourceLocation loc, Failure& failure) const {
  const Variable* v = declared(name, loc, failure);
  if (!v) return std::nullopt;
  if (v->type == ast::DataType::String) {
    fail(failure, EvalError::TypeMismatch, loc,
         absl::StrCat("'", std::string(name), "' is a STRING, not a number"));
    return std::nullopt;
  }
  std::optional<size_t> at = element(name, *v, indices, loc, failure);
  if (!at) return std::nullopt;
  return Value::of(v->values[*at]);
}

std::optional<std::string> NamedVariables::readText(std::string_view name,
                                                    std::span<const int64_t> indices,
                                                    SourceLocation loc, Failure& failure) const {
  const Variable* v = declared(name, loc, failure);
  if (!v) return std::nullopt;
  if (v->type == ast::DataType::Char) {
    std::optional<size_t> at = element(name, *v, indices, loc, failure);
    if (!at) return std::nullopt;
    const double code = v->values[*at];
    return code == 0.0 ? std::string() : std::string(1, static_cast<char>(static_cast<int>(code)));
  }
  if (v->type != ast::DataType::String) {
    fail(failure, EvalError::TypeMismatch, loc,
         absl::StrCat("'", std::string(name), "' is ", typeName(v->type), ", not a string"));
    return std::nullopt;
  }
  // S[i] after the array's indices: the character i of the string (from 0).
  const bool character = static_cast<int>(indices.size()) == v->rank + 1;
  std::optional<size_t> at =
      element(name, *v, character ? indices.first(indices.size() - 1) : indices, loc, failure);
  if (!at) return std::nullopt;
  const std::string& text = v->texts[*at];
  if (!character) return text;
  const int64_t i = indices.back();
  if (i < 0 || i >= static_cast<int64_t>(text.size())) {
    fail(failure, EvalError::ArrayIndex, loc,
         absl::StrCat("'", std::string(name), "': character ", i, " is outside 0 to ",
                      static_cast<int64_t>(text.size()) - 1, " (\"", text.substr(0, 40), "\")"));
    return std::nullopt;
  }
  return std::string(1, text[static_cast<size_t>(i)]);
}

std::optional<Datum> NamedVariables::readDatum(std::string_view name,
                                               std::span<const int64_t> indices,
                                               SourceLocation loc, Failure& failure) const {
  const Variable* v = find(name);
  if (v && v->type == ast::DataType::String) {
    std::optional<std::string> t = readText(name, indices, loc, failure);
    if (!t) return std::nullopt;
    return Datum(std::move(*t));
  }
  std::optional<Value> n = read(name, indices, loc, failure);
  if (!n) return std::nullopt;
  return Datum(*n);
}

bool NamedVariables::write(std::string_view name, std::span<const int64_t> indices,
                           const Datum& value, SourceLocation loc, Failure& failure) {
  Variable* v = declared(name, loc, failure);
  if (!v) return false;
  std::optional<size_t> at = element(name, *v, indices, loc, failure);
  if (!at) return false;
  if (v->type == ast::DataType::String) {
    std::optional<std::string> text = textFor(*v, name, value, loc, failure);
    if (!text) return false;
    v->texts[*at] = std::move(*text);
    return true;
  }
  std::optional<double> stored = numberFor(*v, name, value, loc, failure);
  if (!stored) return false;
  v->values[*at] = *stored;
  if (v->first_number != 0 && on_write) on_write(v->first_number + *at, Value::of(*stored), loc);
  return true;
}

std::optional<size_t> NamedVariables::firstElement(std::string_view name, const Variable& v,
                                                   std::span<const int64_t> first,
                                                   SourceLocation loc, Failure& failure) const {
  if (first.empty()) return 0;  // the whole array: from its first element
  return element(name, v, first, loc, failure);
}

std::optional<size_t> NamedVariables::elementsFrom(std::string_view name,
                                                   std::span<const int64_t> first,
                                                   SourceLocation loc, Failure& failure) const {
  const Variable* v = declared(name, loc, failure);
  if (!v) return std::nullopt;
  std::optional<size_t> at = firstElement(name, *v, first, loc, failure);
  if (!at) return std::nullopt;
  const size_t count = v->type == ast::DataType::String ? v->texts.size() : v->values.size();
  return count - *at;
}

bool NamedVariables::fill(std::string_view name, std::span<const int64_t> first,
                          std::span<const std::optional<Datum>> values, SourceLocation loc,
                          Failure& failure) {
  Variable* v = declared(name, loc, failure);
  if (!v) return false;
  std::optional<size_t> at = firstElement(name, *v, first, loc, failure);
  if (!at) return false;
  const bool text = v->type == ast::DataType::String;
  const size_t count = text ? v->texts.size() : v->values.size();
  if (values.size() > count - *at)
    return fail(failure, EvalError::TooManyValues, loc,
                absl::StrCat(values.size(), " values, ", count - *at, " elements are left in '",
                             std::string(name), "'"));
  // Every value converted first: a value the type refuses leaves the array as it was.
  std::vector<std::optional<std::string>> texts(values.size());
  std::vector<std::optional<double>> numbers(values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    if (!values[i]) continue;
    if (text) {
      texts[i] = textFor(*v, name, *values[i], loc, failure);
      if (!texts[i]) return false;
    } else {
      numbers[i] = numberFor(*v, name, *values[i], loc, failure);
      if (!numbers[i]) return false;
    }
  }
  for (size_t i = 0; i < values.size(); ++i) {
    const size_t e = *at + i;
    if (texts[i]) v->texts[e] = std::move(*texts[i]);
    if (!numbers[i]) continue;
    v->values[e] = *numbers[i];
    if (v->first_number != 0 && on_write) on_write(v->first_number + e, Value::of(*numbers[i]), loc);
  }
  return true;
}

void NamedVariables::pushScope() { scopes_.emplace_back(); }

void NamedVariables::popScope() {
  if (scopes_.size() > 1) scopes_.pop_back();
}

std::string NamedVariables::nameOf(uint32_t n) const {
  if (n >= kFirstNumber && n < kFirstNumber + kRParameters)
    return absl::StrCat("R", n - kFirstNumber);
  for (const auto& [name, v] : numbered_) {
    if (n < v->first_number || n >= v->first_number + v->values.size()) continue;
    if (v->rank == 0) return name;
    size_t offset = n - v->first_number;
    std::array<int64_t, 3> index{};
    for (int i = v->rank - 1; i >= 0; --i) {
      index[i] = static_cast<int64_t>(offset % static_cast<size_t>(v->dims[i]));
      offset /= static_cast<size_t>(v->dims[i]);
    }
    return absl::StrCat(name, "[", absl::StrJoin(std::span(index.data(), v->rank), ","), "]");
  }
  return "";
}

}  // namespace ncc::eval
