// Typed, diagnosing access to toml++ nodes for the machine-file reader.
#include "toml_context.h"

#include <algorithm>
#include <cmath>

#include "text.h"

namespace ncc::machine_file {

std::string_view tomlTypeName(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "a list";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a float";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

SourceLocation TomlContext::at(const toml::source_region& region) const {
  return SourceLocation{file_, region.begin.line, region.begin.column};
}

std::vector<std::pair<const toml::key*, const toml::node*>> inFileOrder(const toml::table& t) {
  std::vector<std::pair<const toml::key*, const toml::node*>> out;
  for (const auto& [key, node] : t) out.emplace_back(&key, &node);
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    const auto& pa = a.first->source().begin;
    const auto& pb = b.first->source().begin;
    return pa.line != pb.line ? pa.line < pb.line : pa.column < pb.column;
  });
  return out;
}

void TomlContext::error(std::string_view code, SourceLocation where, std::string message) {
  pending_.push_back(Pending{std::string(code), where, std::move(message)});
  ++errors_;
}

void TomlContext::warning(std::string_view code, SourceLocation where, std::string message) {
  pending_.push_back(Pending{std::string(code), where, std::move(message), true});
}

void TomlContext::flush() {
  std::stable_sort(pending_.begin(), pending_.end(), [](const Pending& a, const Pending& b) {
    return a.where.line != b.where.line ? a.where.line < b.where.line
                                        : a.where.column < b.where.column;
  });
  for (Pending& p : pending_) {
    if (p.is_warning)
      diags_.warning(std::move(p.code), p.where, std::move(p.message));
    else
      diags_.error(std::move(p.code), p.where, std::move(p.message));
  }
  pending_.clear();
  errors_ = 0;
}

void TomlContext::unknownKey(const toml::key& key, std::string_view table_name) {
  error(kUnknownKey, at(key), cat("unknown key '", key.str(), "' in ", table_name));
}

void TomlContext::wrongType(const toml::node& node, std::string_view what,
                            std::string_view expected) {
  error(kWrongType, at(node),
        cat("wrong type for '", what, "': expected ", expected, ", found ", tomlTypeName(node)));
}

std::optional<double> TomlContext::number(const toml::node& node, std::string_view what) {
  double v;
  if (const auto* i = node.as_integer()) {
    v = static_cast<double>(i->get());
  } else if (const auto* f = node.as_floating_point()) {
    v = f->get();
  } else {
    wrongType(node, what, "a number");
    return std::nullopt;
  }
  if (!std::isfinite(v)) {
    error(kBadValue, at(node), cat("'", what, "' must be a finite number"));
    return std::nullopt;
  }
  return v;
}

std::optional<int64_t> TomlContext::integer(const toml::node& node, std::string_view what) {
  if (const auto* i = node.as_integer()) return i->get();
  // 128.0 is accepted where an integer is meant; 128.5 is not.
  if (const auto* f = node.as_floating_point()) {
    double v = f->get();
    if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 9.0e15)
      return static_cast<int64_t>(v);
  }
  wrongType(node, what, "an integer");
  return std::nullopt;
}

std::optional<std::string> TomlContext::string(const toml::node& node, std::string_view what) {
  if (const auto* s = node.as_string()) return s->get();
  wrongType(node, what, "a string");
  return std::nullopt;
}

std::optional<bool> TomlContext::boolean(const toml::node& node, std::string_view what) {
  if (const auto* b = node.as_boolean()) return b->get();
  wrongType(node, what, "a boolean (true or false)");
  return std::nullopt;
}

const toml::table* TomlContext::table(const toml::node& node, std::string_view what) {
  if (const auto* t = node.as_table()) return t;
  wrongType(node, what, "a table");
  return nullptr;
}

const toml::array* TomlContext::array(const toml::node& node, std::string_view what) {
  if (const auto* a = node.as_array()) return a;
  wrongType(node, what, "a list");
  return nullptr;
}

}  // namespace ncc::machine_file
