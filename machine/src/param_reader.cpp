// One `[machine.params]` value: TOML node -> ParamValue of the registry's type.
#include "param_reader.h"

#include <algorithm>

#include "text.h"

namespace ncc::machine_file {

int requireAxis(const std::vector<AxisConfig>& axes, std::string_view name, SourceLocation where,
                std::string_view what, TomlContext& ctx) {
  for (size_t i = 0; i < axes.size(); ++i)
    if (axes[i].name == name) return static_cast<int>(i);
  std::vector<std::string_view> names;
  for (const AxisConfig& a : axes) names.push_back(a.name);
  ctx.error(kUnknownAxis, where,
            cat("unknown axis '", name, "' in '", what, "' (the machine's axes are ",
                join(names, ", "), ")"));
  return -1;
}

namespace {

// Reads values of one registry entry; every method returns false after reporting.
class ParamReader {
 public:
  ParamReader(const ParamSpec& spec, const std::vector<AxisConfig>& axes, TomlContext& ctx)
      : spec_(spec), axes_(axes), ctx_(ctx), what_(spec.key) {}

  std::optional<ParamValue> read(const toml::node& node) {
    switch (spec_.type) {
      case ParamType::Bool:
        if (auto b = ctx_.boolean(node, what_)) return ParamValue(*b);
        return std::nullopt;
      case ParamType::Number:
      case ParamType::Integer:
        if (auto v = scalar(node)) return ParamValue(*v);
        return std::nullopt;
      case ParamType::String:
        return string(node);
      case ParamType::NumberList:
      case ParamType::IntegerList:
        return numberList(node);
      case ParamType::StringList:
      case ParamType::AxisList:
        return stringList(node);
      case ParamType::AxisTable:
        return axisTable(node);
      case ParamType::AxisNameTable:
      case ParamType::StringTable:
        return stringTable(node);
      case ParamType::AxisRangeTable:
        return axisRanges(node);
      case ParamType::Any:
        break;
    }
    ctx_.wrongType(node, what_, paramTypeDescription(spec_.type));
    return std::nullopt;
  }

 private:
  // A number of the entry (or an element of its list / table), range-checked.
  std::optional<double> scalar(const toml::node& node) {
    std::optional<double> v;
    if (spec_.integral) {
      if (auto i = ctx_.integer(node, what_)) v = static_cast<double>(*i);
    } else {
      v = ctx_.number(node, what_);
    }
    if (!v) return std::nullopt;
    if (*v < spec_.min_value || *v > spec_.max_value) {
      ctx_.error(kBadValue, ctx_.at(node),
                 cat("value ", *v, " of '", what_, "' is out of range (", rangeText(), ")"));
      return std::nullopt;
    }
    return v;
  }

  std::string rangeText() const {
    if (spec_.max_value >= 1e300) return cat("at least ", spec_.min_value);
    return cat(spec_.min_value, " to ", spec_.max_value);
  }

  std::optional<ParamValue> string(const toml::node& node) {
    auto s = ctx_.string(node, what_);
    if (!s) return std::nullopt;
    if (!spec_.choices.empty() &&
        std::find(spec_.choices.begin(), spec_.choices.end(), *s) == spec_.choices.end()) {
      std::vector<std::string> quoted;
      for (std::string_view c : spec_.choices) quoted.push_back(cat("\"", c, "\""));
      ctx_.error(
          kBadValue, ctx_.at(node),
          cat("invalid value \"", *s, "\" for '", what_, "': expected ", join(quoted, ", ")));
      return std::nullopt;
    }
    return ParamValue(std::move(*s));
  }

  const toml::array* list(const toml::node& node) {
    const toml::array* arr = node.as_array();
    if (!arr) {
      ctx_.wrongType(node, what_, paramTypeDescription(spec_.type));
      return nullptr;
    }
    if (spec_.max_items && arr->size() > spec_.max_items) {
      ctx_.error(kBadValue, ctx_.at(node),
                 cat("'", what_, "' has ", arr->size(), " entries; at most ", spec_.max_items,
                     " are allowed"));
      return nullptr;
    }
    return arr;
  }

  std::optional<ParamValue> numberList(const toml::node& node) {
    const toml::array* arr = list(node);
    if (!arr) return std::nullopt;
    std::vector<double> out;
    bool ok = true;
    for (const toml::node& el : *arr) {
      if (auto v = scalar(el))
        out.push_back(*v);
      else
        ok = false;
    }
    if (!ok) return std::nullopt;
    return ParamValue(std::move(out));
  }

  std::optional<ParamValue> stringList(const toml::node& node) {
    const toml::array* arr = list(node);
    if (!arr) return std::nullopt;
    std::vector<std::string> out;
    bool ok = true;
    for (const toml::node& el : *arr) {
      auto s = ctx_.string(el, what_);
      if (!s) {
        ok = false;
        continue;
      }
      if (spec_.type == ParamType::AxisList) {
        if (requireAxis(axes_, *s, ctx_.at(el), what_, ctx_) < 0) ok = false;
        if (std::find(out.begin(), out.end(), *s) != out.end()) {
          ctx_.error(kBadValue, ctx_.at(el),
                     cat("axis '", *s, "' is listed twice in '", what_, "'"));
          ok = false;
        }
      }
      out.push_back(std::move(*s));
    }
    if (!ok) return std::nullopt;
    return ParamValue(std::move(out));
  }

  const toml::table* table(const toml::node& node) {
    const toml::table* t = node.as_table();
    if (!t) ctx_.wrongType(node, what_, paramTypeDescription(spec_.type));
    return t;
  }

  std::optional<ParamValue> axisTable(const toml::node& node) {
    const toml::table* t = table(node);
    if (!t) return std::nullopt;
    ParamAxisTable out;
    bool ok = true;
    for (const auto& [key, value] : *t) {
      if (requireAxis(axes_, key.str(), ctx_.at(key), what_, ctx_) < 0) ok = false;
      if (auto v = scalar(value))
        out.by_axis[std::string(key.str())] = *v;
      else
        ok = false;
    }
    if (!ok) return std::nullopt;
    return ParamValue(std::move(out));
  }

  // A key of a code table (`M6 = "M6_MAKRO"`): the spec's letter and a whole number, to a
  // program that is named.
  bool codeKey(const toml::key& key, const std::string& program, const toml::node& value) {
    const std::string_view k = key.str();
    const char letter = spec_.key_code_letter;
    const bool digits = k.size() > 1 && k.size() <= 9 &&
                        k.find_first_not_of("0123456789", 1) == std::string_view::npos;
    if (k.empty() || (k[0] != letter && k[0] != letter + ('a' - 'A')) || !digits) {
      ctx_.error(kBadValue, ctx_.at(key),
                 cat("'", k, "' in '", what_, "' is not a ", std::string(1, letter),
                     " code (", std::string(1, letter), " and a whole number, e.g. ",
                     std::string(1, letter), letter == 'M' ? "6" : "100", ")"));
      return false;
    }
    if (program.empty()) {
      ctx_.error(kBadValue, ctx_.at(value),
                 cat("'", what_, "' ", k, ": the program to call is empty"));
      return false;
    }
    return true;
  }

  std::optional<ParamValue> stringTable(const toml::node& node) {
    const toml::table* t = table(node);
    if (!t) return std::nullopt;
    const bool axes_both_sides = spec_.type == ParamType::AxisNameTable;
    ParamStringTable out;
    bool ok = true;
    for (const auto& [key, value] : *t) {
      if (axes_both_sides && requireAxis(axes_, key.str(), ctx_.at(key), what_, ctx_) < 0)
        ok = false;
      auto s = ctx_.string(value, what_);
      if (!s) {
        ok = false;
        continue;
      }
      if (axes_both_sides && requireAxis(axes_, *s, ctx_.at(value), what_, ctx_) < 0) ok = false;
      if (spec_.key_code_letter && !codeKey(key, *s, value)) ok = false;
      out.by_key[std::string(key.str())] = std::move(*s);
    }
    if (!ok) return std::nullopt;
    return ParamValue(std::move(out));
  }

  std::optional<ParamValue> axisRanges(const toml::node& node) {
    const toml::table* t = table(node);
    if (!t) return std::nullopt;
    ParamAxisRanges out;
    bool ok = true;
    for (const auto& [key, value] : *t) {
      if (requireAxis(axes_, key.str(), ctx_.at(key), what_, ctx_) < 0) ok = false;
      const toml::array* pair = value.as_array();
      if (!pair || pair->size() != 2) {
        ctx_.wrongType(value, what_, "a [min, max] pair of numbers");
        ok = false;
        continue;
      }
      auto lo = ctx_.number(*pair->get(0), what_);
      auto hi = ctx_.number(*pair->get(1), what_);
      if (!lo || !hi) {
        ok = false;
        continue;
      }
      if (!(*lo < *hi)) {
        ctx_.error(kBadValue, ctx_.at(value),
                   cat("'", what_, "' of ", key.str(), ": min ", *lo, " must be below max ", *hi));
        ok = false;
        continue;
      }
      out.by_axis[std::string(key.str())] = {*lo, *hi};
    }
    if (!ok) return std::nullopt;
    return ParamValue(std::move(out));
  }

  const ParamSpec& spec_;
  const std::vector<AxisConfig>& axes_;
  TomlContext& ctx_;
  std::string_view what_;
};

}  // namespace

std::optional<ParamValue> readParam(const ParamSpec& spec, const toml::node& node,
                                    const std::vector<AxisConfig>& axes, TomlContext& ctx) {
  return ParamReader(spec, axes, ctx).read(node);
}

}  // namespace ncc::machine_file
