#pragma once
// Controller parameters (`[machine.params]`). Every key a machine file may use is declared
// once in a registry (params.cpp) with its type, default and meaning; a key not in the
// registry is an error naming the key. The vocabulary is shared/conformance/FORMAT.md's,
// plus ncc's own keys (rapid_type, same_group_in_block, reference_point_4,
// block_skip_levels); docs/machine-file.md lists them all.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "ncc/machine/axes.h"
#include "ncc/machine/dialect.h"

namespace ncc {

// A parameter value: bool, number, string, per-axis table ({ X = .., Y = .. }), list,
// string table ({ M6 = "M6_MAKRO" }, { X = "U" }) or per-axis range ({ C = [-10, 10] }).
struct ParamAxisTable {
  std::map<std::string, double> by_axis;  // axis name -> value
  friend bool operator==(const ParamAxisTable&, const ParamAxisTable&) = default;
};
struct ParamStringTable {
  std::map<std::string, std::string> by_key;
  friend bool operator==(const ParamStringTable&, const ParamStringTable&) = default;
};
struct ParamAxisRanges {
  std::map<std::string, std::pair<double, double>> by_axis;  // axis name -> [min, max]
  friend bool operator==(const ParamAxisRanges&, const ParamAxisRanges&) = default;
};
using ParamValue = std::variant<bool, double, std::string, ParamAxisTable, std::vector<double>,
                                std::vector<std::string>, ParamStringTable, ParamAxisRanges>;

// How a value is written in TOML and checked. Integer / IntegerList are stored as double(s);
// Axis* types hold axis names that must be in `[machine] axes`.
enum class ParamType : uint8_t {
  Bool,            // true / false                         -> bool
  Number,          // 1.5 or 2                              -> double
  String,          // "text" (one of `choices` when given)  -> std::string
  AxisTable,       // { X = 1.0, Y = 2.0 }                  -> ParamAxisTable
  NumberList,      // [1.0, 2.0]                            -> std::vector<double>
  StringList,      // ["a", "b"]                            -> std::vector<std::string>
  Any,             // reserved: no registry key uses it
  Integer,         // 128 (a float with a fraction is an error) -> double
  IntegerList,     // [1, 2]                                -> std::vector<double>
  AxisList,        // ["B", "C"]                            -> std::vector<std::string>
  AxisNameTable,   // { X = "U" }: axis -> axis             -> ParamStringTable
  StringTable,     // { M6 = "M6_MAKRO" }                   -> ParamStringTable
  AxisRangeTable,  // { C = [-10000.0, 10000.0] }           -> ParamAxisRanges
};

// "a boolean", "a list of axis names", ...: how the type is named in diagnostics and docs.
std::string_view paramTypeDescription(ParamType type);

struct ParamSpec {
  std::string_view key;
  ParamType type;
  std::string_view default_text;  // human-readable default, for docs and --help
  std::string_view meaning;
  // Additions (all optional):
  std::string_view dialects = {};  // "fanuc-t, mazak-m": who reads it (documentation)
  // The dialects in which ncc applies the key: "all", a list like `dialects`, or "" (stored
  // and checked, applied nowhere yet). A machine file setting a key that does not apply in
  // the selected dialect gets warning NCC0307 naming it (paramApplies).
  std::string_view applied_in = "all";
  std::vector<std::string_view> choices = {};  // String: the accepted values
  // StringTable: each key is a code of this letter (`M6`, `m06`: the letter, then a whole
  // number) and each value is not empty; 0 = any key.
  char key_code_letter = 0;
  double min_value = -1e300;       // Number/Integer (and list elements, table values)
  double max_value = 1e300;
  size_t max_items = 0;            // lists: at most this many entries (0 = unbounded)
  bool integral = false;           // numbers must be integers (always so for Integer types)
  // Typed default; nullopt when the default depends on the dialect or on other settings
  // (default_text says how), and the consumer passes its own fallback.
  std::optional<ParamValue> default_value = std::nullopt;
};

// The registry of every known key, in documentation (alphabetical) order.
const std::vector<ParamSpec>& parameterRegistry();
const ParamSpec* findParameter(std::string_view key);
// True when ncc applies `spec` in `dialect` (ParamSpec::applied_in).
bool paramApplies(const ParamSpec& spec, Dialect dialect);

class ParameterSet {
 public:
  // Stores a value; the caller (machine file reader) has checked key and type.
  void set(std::string key, ParamValue value) { values_[std::move(key)] = std::move(value); }
  bool has(std::string_view key) const { return values_.find(key) != values_.end(); }

  // The stored value if it has the asked type, else `fallback`.
  bool getBool(std::string_view key, bool fallback) const;
  double getNumber(std::string_view key, double fallback) const;
  std::string getString(std::string_view key, std::string fallback) const;
  const ParamAxisTable* getAxisTable(std::string_view key) const;
  const ParamValue* get(std::string_view key) const;

  // Stored value, else the registry's typed default. Returns false / 0 / "" when the key has
  // neither (unknown key, or a dialect-dependent default: use the two-argument forms then).
  bool getBool(std::string_view key) const;
  double getNumber(std::string_view key) const;
  std::string getString(std::string_view key) const;
  // Stored value or typed default; nullptr when there is neither.
  const ParamValue* getOrDefault(std::string_view key) const;

  // Typed accessors for the list and table kinds; nullptr when absent or of another type.
  const std::vector<double>* getNumberList(std::string_view key) const;
  const std::vector<std::string>* getStringList(std::string_view key) const;
  const ParamStringTable* getStringTable(std::string_view key) const;
  const ParamAxisRanges* getAxisRanges(std::string_view key) const;

  const std::map<std::string, ParamValue, std::less<>>& all() const { return values_; }

  friend bool operator==(const ParameterSet&, const ParameterSet&) = default;

 private:
  std::map<std::string, ParamValue, std::less<>> values_;
};

}  // namespace ncc
