#pragma once
// Controller parameters (`[machine.params]`). Every key a machine file may use is declared
// once in a registry (params.cpp) with its type, default and meaning; a key not in the
// registry is an error naming the key. The vocabulary is shared/conformance/FORMAT.md's.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "ncc/machine/axes.h"

namespace ncc {

// A parameter value: bool, number, string, per-axis table ({ X = .., Y = .. }) or list.
struct ParamAxisTable {
  std::map<std::string, double> by_axis;  // axis name -> value
};
using ParamValue = std::variant<bool, double, std::string, ParamAxisTable, std::vector<double>,
                                std::vector<std::string>>;

enum class ParamType : uint8_t { Bool, Number, String, AxisTable, NumberList, StringList, Any };

struct ParamSpec {
  std::string_view key;
  ParamType type;
  std::string_view default_text;  // human-readable default, for docs and --help
  std::string_view meaning;
};

// The registry of every known key, in documentation order.
const std::vector<ParamSpec>& parameterRegistry();
const ParamSpec* findParameter(std::string_view key);

class ParameterSet {
 public:
  // Stores a value; the caller (machine file reader) has checked key and type.
  void set(std::string key, ParamValue value) { values_[std::move(key)] = std::move(value); }
  bool has(std::string_view key) const { return values_.find(std::string(key)) != values_.end(); }

  bool getBool(std::string_view key, bool fallback) const;
  double getNumber(std::string_view key, double fallback) const;
  std::string getString(std::string_view key, std::string fallback) const;
  const ParamAxisTable* getAxisTable(std::string_view key) const;
  const ParamValue* get(std::string_view key) const;

  const std::map<std::string, ParamValue, std::less<>>& all() const { return values_; }

 private:
  std::map<std::string, ParamValue, std::less<>> values_;
};

}  // namespace ncc
