// Reading a machine file: the structure of [machine] and [start] (docs/machine-file.md).
// Every problem is reported with its line and column and reading goes on, so one run shows
// all errors of a file; the result is nullopt when any was found.
#include "ncc/machine/machine_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "absl/strings/ascii.h"
#include "ncc/machine/bounds.h"
#include "ncc/machine/travel.h"
#include "param_reader.h"
#include "servo_keys.h"
#include "text.h"
#include "toml_context.h"

namespace ncc {

namespace machine_file {
namespace {

constexpr int kMaxRegister = 9999;       // H/D/T/geometry/... register numbers: 1..9999
constexpr int kMaxAdditionalWork = 300;  // G54.1 P1..P300 (FANUC/Mazak, with the option)
constexpr int kMaxSiemensWork = 99;      // G54 P1..P99 (Siemens ISO)

bool isAxisName(std::string_view name) {
  if (name.empty() || name.size() > 8 || !absl::ascii_isupper(name[0])) return false;
  return std::all_of(name.begin(), name.end(),
                     [](char c) { return absl::ascii_isupper(c) || absl::ascii_isdigit(c); });
}

bool consumePrefix(std::string_view* s, std::string_view prefix) {
  if (!s->starts_with(prefix)) return false;
  s->remove_prefix(prefix.size());
  return true;
}

// "12" -> 12; nullopt for anything but 1-9 decimal digits.
std::optional<int> parseNumber(std::string_view digits) {
  if (digits.empty() || digits.size() > 9) return std::nullopt;
  int n = 0;
  auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
  if (ec != std::errc() || ptr != digits.data() + digits.size()) return std::nullopt;
  return n;
}

// Work offset key -> canonical name: G54..G59; G54.1P<n> (also spelt "G54.1 P<n>" and, as a
// bare TOML key, G54_1P<n>); G54P<n>. nullopt if the key names no work offset.
std::optional<std::string> workOffsetName(std::string_view key, int* number, int* max_number) {
  *number = 0;
  if (key.size() == 3 && key.starts_with("G5") && key[2] >= '4' && key[2] <= '9')
    return std::string(key);
  std::string_view rest = key;
  std::string canonical;
  if (consumePrefix(&rest, "G54.1") || consumePrefix(&rest, "G54_1")) {
    consumePrefix(&rest, " ");
    canonical = "G54.1P";
    *max_number = kMaxAdditionalWork;
  } else if (consumePrefix(&rest, "G54")) {
    canonical = "G54P";
    *max_number = kMaxSiemensWork;
  } else {
    return std::nullopt;
  }
  if (!consumePrefix(&rest, "P")) return std::nullopt;
  auto n = parseNumber(rest);
  if (!n) return std::nullopt;
  *number = *n;
  return cat(canonical, *n);
}

// { "1P1" = [...] }: what `G54.1P1 = [...]` parses to without quotes.
bool isDottedAdditionalOffset(const toml::table& t) {
  for (const auto& [key, node] : t)
    if (key.str().starts_with("1P") || key.str().starts_with("1 P")) return true;
  return false;
}

std::string axisList(const std::vector<AxisConfig>& axes) {
  std::vector<std::string_view> names;
  for (const AxisConfig& a : axes) names.push_back(a.name);
  return join(names, ", ");
}

class MachineFileReader {
 public:
  MachineFileReader(TomlContext& ctx, const MachineFileOptions& options)
      : ctx_(ctx), options_(options) {}

  std::optional<MachineConfig> read(const toml::table& root) {
    const size_t errors_before = ctx_.errorCount();
    m_ = MachineConfig{};
    const toml::node* machine = nullptr;
    const toml::node* start = nullptr;
    for (const auto& [key, node] : root) {
      if (key == "machine")
        machine = &node;
      else if (key == "start")
        start = &node;
      else if (!options_.ignore_other_top_level_keys)
        ctx_.unknownKey(key, "the machine file");
    }
    bool axes_ok = true;
    if (machine) {
      if (const toml::table* t = ctx_.table(*machine, "machine"))
        axes_ok = readMachine(*t);
      else
        axes_ok = false;
    } else {
      m_.axes = defaultMachine().axes;
    }
    for (const char* name : {"G54", "G55", "G56", "G57", "G58", "G59"})
      m_.work_offsets.try_emplace(name, zeroAxes());
    if (start && axes_ok) {
      if (const toml::table* t = ctx_.table(*start, "start")) readStart(*t);
    }
    if (axes_ok) checkStartWithinTravel();
    if (ctx_.errorCount() != errors_before) return std::nullopt;
    warnParamsWithoutEffect();
    return std::move(m_);
  }

 private:
  // Returns false when the axes are unusable (then nothing that names an axis is read).
  bool readMachine(const toml::table& t) {
    static constexpr std::string_view kKeys[] = {"axes",   "diameter_axes", "offsets",  "work",
                                                 "params", "axis",          "ipo_cycle",
                                                 "chord_tolerance", "corner_tolerance",
                                                 "lookahead_segments", "dialect", "probe",
                                                 "signals"};
    for (const auto& [key, node] : t)
      if (std::find(std::begin(kKeys), std::end(kKeys), key.str()) == std::end(kKeys))
        ctx_.unknownKey(key, "[machine]");

    if (const toml::node* axes = t.get("axes")) {
      if (!readAxes(*axes)) return false;
    } else {
      m_.axes = defaultMachine().axes;
    }
    // Params first: rotary_axes and software_limits shape the axes the other tables see.
    if (const toml::node* n = t.get("params"))
      if (const toml::table* p = ctx_.table(*n, "machine.params")) readParams(*p);
    applyAxisKinds();
    if (const toml::node* n = t.get("diameter_axes")) readDiameterAxes(*n);
    if (const toml::node* n = t.get("offsets"))
      if (const toml::table* o = ctx_.table(*n, "machine.offsets")) readOffsets(*o);
    if (const toml::node* n = t.get("work"))
      if (const toml::table* w = ctx_.table(*n, "machine.work")) readWork(*w);
    if (const toml::node* n = t.get("axis"))
      if (const toml::table* a = ctx_.table(*n, "machine.axis")) readAxisLimits(*a);
    if (const toml::node* n = t.get("dialect")) readDialect(*n);
    if (const toml::node* n = t.get("probe"))
      if (const toml::table* p = ctx_.table(*n, "machine.probe")) readProbe(*p);
    if (const toml::node* n = t.get("signals"))
      if (const toml::table* s = ctx_.table(*n, "machine.signals")) readSignals(*s);
    readBounded(t, "ipo_cycle", bounds::kMinIpoCycle, bounds::kMaxIpoCycle, "s",
                m_.ipo_cycle_seconds);
    readBounded(t, "chord_tolerance", bounds::kMinChordTolerance, bounds::kMaxChordTolerance,
                "mm", m_.chord_tolerance);
    readBounded(t, "corner_tolerance", bounds::kMinCornerTolerance, bounds::kMaxCornerTolerance,
                "mm", m_.corner_tolerance, /*zero_allowed=*/true);  // 0: corners stop
    readCount(t, "lookahead_segments", MachineConfig::kMinLookaheadSegments,
              MachineConfig::kMaxLookaheadSegments, m_.lookahead_segments);
    return true;
  }

  // [machine] `key`, if given: an integer from `low` to `high` into `field`, else an error
  // naming the range.
  void readCount(const toml::table& t, std::string_view key, int low, int high, int& field) {
    const toml::node* n = t.get(key);
    if (!n) return;
    const std::optional<int64_t> v = ctx_.integer(*n, key);
    if (!v) return;
    if (*v >= low && *v <= high) {
      field = static_cast<int>(*v);
      return;
    }
    ctx_.error(kBadValue, ctx_.at(*n),
               cat("'", key, "' must be at least ", low, " and at most ", high, ", not ", *v));
  }

  // [machine] `key`, if given: a number from `low` to `high` (bounds.h), or 0 when
  // `zero_allowed`, into `field`; else an error naming the range.
  void readBounded(const toml::table& t, std::string_view key, double low, double high,
                   std::string_view unit, double& field, bool zero_allowed = false) {
    const toml::node* n = t.get(key);
    if (!n) return;
    const std::optional<double> v = ctx_.number(*n, key);
    if (!v) return;
    if ((*v >= low && *v <= high) || (zero_allowed && *v == 0.0)) {
      field = *v;
      return;
    }
    ctx_.error(kBadValue, ctx_.at(*n),
               cat("'", key, "' must be ", zero_allowed ? "0 or " : "", "at least ", low,
                   " and at most ", high, " ", unit, ", not ", *v));
  }

  // [machine] dialect = "mazak-m": the dialect the machine's programs are written in
  // (--dialect overrides it).
  void readDialect(const toml::node& n) {
    const std::optional<std::string> name = ctx_.string(n, "dialect");
    if (!name) return;
    if (const std::optional<Dialect> d = parseDialect(*name)) {
      m_.dialect = *d;
      return;
    }
    ctx_.error(kBadValue, ctx_.at(n),
               cat("unknown dialect '", *name,
                   "' (expected fanuc-m, fanuc-t, mazak-m, siemens-iso-m or siemens-din)"));
  }

  bool readAxes(const toml::node& node) {
    const toml::array* arr = ctx_.array(node, "axes");
    if (!arr) return false;
    if (arr->empty()) {
      ctx_.error(kBadAxes, ctx_.at(node), "'axes' is empty: a machine has at least one axis");
      return false;
    }
    if (arr->size() > static_cast<size_t>(kMaxAxes)) {
      ctx_.error(kBadAxes, ctx_.at(node),
                 cat("'axes' lists ", arr->size(), " axes; at most ", kMaxAxes, " are supported"));
      return false;
    }
    bool ok = true;
    for (const toml::node& el : *arr) {
      auto name = ctx_.string(el, "axes");
      if (!name) {
        ok = false;
        continue;
      }
      if (!isAxisName(*name)) {
        ctx_.error(kBadAxes, ctx_.at(el),
                   cat("invalid axis name '", *name,
                       "': an upper-case letter, then upper-case letters or digits "
                       "(at most 8 characters)"));
        ok = false;
        continue;
      }
      if (m_.axisIndex(*name) >= 0) {
        ctx_.error(kBadAxes, ctx_.at(el), cat("axis '", *name, "' is listed twice"));
        ok = false;
        continue;
      }
      AxisConfig axis;
      axis.name = *name;
      m_.axes.push_back(std::move(axis));
    }
    return ok;
  }

  void readParams(const toml::table& t) {
    for (const auto& [key_ptr, node_ptr] : inFileOrder(t)) {
      const toml::key& key = *key_ptr;
      const toml::node& node = *node_ptr;
      const ParamSpec* spec = findParameter(key.str());
      if (!spec) {
        ctx_.unknownKey(key, "[machine.params]");
        continue;
      }
      if (auto value = readParam(*spec, node, m_.axes, ctx_)) {
        m_.params.set(std::string(key.str()), std::move(*value));
        param_locations_[std::string(key.str())] = ctx_.at(node);
      }
    }
  }

  // rotary_axes (when given) names exactly the rotary axes; otherwise A, B and C are rotary.
  // software_limits sets travel limits. Both were checked against the axes already.
  void applyAxisKinds() {
    const std::vector<std::string>* rotary = m_.params.getStringList("rotary_axes");
    for (AxisConfig& a : m_.axes) {
      bool is_rotary = rotary ? std::find(rotary->begin(), rotary->end(), a.name) != rotary->end()
                              : (a.name == "A" || a.name == "B" || a.name == "C");
      a.kind = is_rotary ? AxisKind::Rotary : AxisKind::Linear;
    }
    if (const auto* modulo = m_.params.getStringList("modulo_axes")) {
      for (const std::string& name : *modulo) {
        int i = m_.axisIndex(name);
        if (i >= 0 && m_.axes[i].kind != AxisKind::Rotary)
          ctx_.error(kBadValue, param_locations_["modulo_axes"],
                     cat("modulo axis '", name, "' is not a rotary axis (see 'rotary_axes')"));
      }
    }
    if (const ParamAxisRanges* limits = m_.params.getAxisRanges("software_limits")) {
      for (const auto& [name, range] : limits->by_axis) {
        int i = m_.axisIndex(name);
        if (i < 0) continue;
        m_.axes[i].min_travel = range.first;
        m_.axes[i].max_travel = range.second;
        travel_from_params_.insert(i);
      }
    }
  }

  void readDiameterAxes(const toml::node& node) {
    const toml::array* arr = ctx_.array(node, "diameter_axes");
    if (!arr) return;
    for (const toml::node& el : *arr) {
      auto name = ctx_.string(el, "diameter_axes");
      if (!name) continue;
      int i = requireAxis(m_.axes, *name, ctx_.at(el), "diameter_axes", ctx_);
      if (i < 0) continue;
      if (m_.axes[i].kind == AxisKind::Rotary)
        ctx_.error(kBadValue, ctx_.at(el),
                   cat("rotary axis '", *name, "' cannot be a diameter axis"));
      m_.axes[i].diameter = true;
    }
  }

  void readOffsets(const toml::table& t) {
    static constexpr std::string_view kPrefixes[] = {
        "second_geometry", "geometry", "wear", "H", "D", "T"};
    for (const auto& [key_ptr, node_ptr] : inFileOrder(t)) {
      const toml::key& key = *key_ptr;
      const toml::node& node = *node_ptr;
      std::string_view name = key.str();
      std::string_view prefix;
      for (std::string_view p : kPrefixes)
        if (name.starts_with(p)) {
          prefix = p;
          break;
        }
      std::optional<int> number;
      if (!prefix.empty()) number = parseNumber(name.substr(prefix.size()));
      if (!number) {
        ctx_.error(kUnknownKey, ctx_.at(key),
                   cat("unknown key '", name,
                       "' in [machine.offsets] (expected H<n>, D<n>, T<n>, "
                       "geometry<n>, wear<n> or second_geometry<n>)"));
        continue;
      }
      if (*number < 1 || *number > kMaxRegister) {
        ctx_.error(kBadValue, ctx_.at(key),
                   cat("offset register number in '", name, "' must be 1 to ", kMaxRegister));
        continue;
      }
      std::string canonical = cat(prefix, *number);
      if (!registers_seen_.insert(canonical).second) {
        ctx_.error(kBadValue, ctx_.at(key), cat("offset register ", canonical, " is given twice"));
        continue;
      }
      if (prefix == "H" || (prefix == "D" && !node.is_table())) {
        auto v = ctx_.number(node, name);
        if (!v) continue;
        (prefix == "H" ? m_.tool_offsets.length : m_.tool_offsets.radius)[*number] = *v;
        continue;
      }
      auto offset = readLatheOffset(node, name);
      if (!offset) continue;
      auto& lathe = m_.lathe_offsets;
      auto& target = prefix == "T"          ? lathe.combined
                     : prefix == "D"        ? lathe.edge
                     : prefix == "geometry" ? lathe.geometry
                     : prefix == "wear"     ? lathe.wear
                                            : lathe.second_geometry;
      target[*number] = *offset;
    }
  }

  // { x = .., z = .., radius = .., tip = .. }; every key optional (0).
  std::optional<LatheOffset> readLatheOffset(const toml::node& node, std::string_view what) {
    const toml::table* t = node.as_table();
    if (!t) {
      ctx_.wrongType(node, what, "a table { x, z, radius, tip }");
      return std::nullopt;
    }
    LatheOffset out;
    bool ok = true;
    for (const auto& [key_ptr, value_ptr] : inFileOrder(*t)) {
      const toml::key& key = *key_ptr;
      const toml::node& value = *value_ptr;
      const std::string what_key = cat(what, ".", key.str());
      if (key == "x" || key == "z" || key == "radius") {
        auto v = ctx_.number(value, what_key);
        if (!v) {
          ok = false;
          continue;
        }
        if (key == "radius" && *v < 0) {
          ctx_.error(kBadValue, ctx_.at(value), cat("'", what_key, "' must not be negative"));
          ok = false;
          continue;
        }
        (key == "x" ? out.x : key == "z" ? out.z : out.radius) = *v;
      } else if (key == "tip") {
        auto v = ctx_.integer(value, what_key);
        if (!v) {
          ok = false;
        } else if (*v < 0 || *v > 9) {
          ctx_.error(kBadValue, ctx_.at(value),
                     cat("'", what_key, "' (tool tip direction) must be 0 to 9"));
          ok = false;
        } else {
          out.tip = static_cast<int>(*v);
        }
      } else {
        ctx_.error(kUnknownKey, ctx_.at(key),
                   cat("unknown key '", key.str(), "' in offset register '", what,
                       "' (expected x, z, radius, tip)"));
        ok = false;
      }
    }
    if (!ok) return std::nullopt;
    return out;
  }

  void readWork(const toml::table& t) {
    for (const auto& [key_ptr, node_ptr] : inFileOrder(t)) {
      const toml::key& key = *key_ptr;
      const toml::node& node = *node_ptr;
      // `G54.1P1 = [..]` without quotes is the dotted key G54 -> "1P1": say so.
      if (key == "G54" && node.is_table() && isDottedAdditionalOffset(*node.as_table())) {
        ctx_.error(kWrongType, ctx_.at(key),
                   "'G54' is a table: write additional work offsets in quotes, "
                   "\"G54.1P1\" = [...] (an unquoted dot makes a TOML sub-table)");
        continue;
      }
      int number = 0, max_number = 0;
      auto name = workOffsetName(key.str(), &number, &max_number);
      if (!name) {
        ctx_.error(kUnknownKey, ctx_.at(key),
                   cat("unknown key '", key.str(),
                       "' in [machine.work] (expected G54..G59, \"G54.1P<n>\" or G54P<n>)"));
        continue;
      }
      if (number != 0 && (number < 1 || number > max_number)) {
        ctx_.error(kBadValue, ctx_.at(key),
                   cat("work offset number in '", key.str(), "' must be 1 to ", max_number));
        continue;
      }
      if (m_.work_offsets.count(*name)) {
        ctx_.error(kBadValue, ctx_.at(key), cat("work offset ", *name, " is given twice"));
        continue;
      }
      if (auto values = readAxisValues(node, key.str())) m_.work_offsets[*name] = *values;
    }
  }

  // Per-axis values: a list in axis order ([0.0, 0.0, 0.0]) or a table ({ X = .., Z = .. }).
  std::optional<AxisValues> readAxisValues(const toml::node& node, std::string_view what) {
    AxisValues out = zeroAxes();
    bool ok = true;
    if (const toml::array* arr = node.as_array()) {
      if (arr->size() != m_.axes.size()) {
        ctx_.error(kBadValue, ctx_.at(node),
                   cat("'", what, "' has ", arr->size(), " values but the machine has ",
                       m_.axes.size(), " axes (", axisList(m_.axes), ")"));
        return std::nullopt;
      }
      for (size_t i = 0; i < arr->size(); ++i) {
        if (auto v = ctx_.number(*arr->get(i), what))
          out[i] = *v;
        else
          ok = false;
      }
    } else if (const toml::table* t = node.as_table()) {
      for (const auto& [key_ptr, value_ptr] : inFileOrder(*t)) {
        const toml::key& key = *key_ptr;
        const toml::node& value = *value_ptr;
        int i = requireAxis(m_.axes, key.str(), ctx_.at(key), what, ctx_);
        auto v = ctx_.number(value, what);
        if (i < 0 || !v)
          ok = false;
        else
          out[i] = *v;
      }
    } else {
      ctx_.wrongType(node, what, "a list of numbers in axis order or a table by axis name");
      return std::nullopt;
    }
    if (!ok) return std::nullopt;
    for (std::size_t i = 0; i < m_.axes.size(); ++i) {
      if (std::abs(out[i]) <= bounds::kMaxPosition) continue;
      ctx_.error(kBadValue, ctx_.at(node),
                 cat("'", what, "' of ", m_.axes[i].name, " is ", out[i],
                     ": positions must be within +-", bounds::kMaxPosition));
      return std::nullopt;
    }
    return out;
  }

  // [machine.probe]: `Z = -42.5`, the trigger plane of the simulated skip signal per axis,
  // machine coordinates (probe.h).
  void readProbe(const toml::table& t) {
    for (const auto& [key_ptr, value_ptr] : inFileOrder(t)) {
      const toml::key& key = *key_ptr;
      const int i = requireAxis(m_.axes, key.str(), ctx_.at(key), "machine.probe", ctx_);
      const std::optional<double> v = ctx_.number(*value_ptr, key.str());
      if (i < 0 || !v) continue;
      if (!(std::abs(*v) <= bounds::kMaxPosition)) {
        ctx_.error(kBadValue, ctx_.at(*value_ptr),
                   cat("the probe trigger of ", m_.axes[i].name, " is ", *v,
                       ": positions must be within +-", bounds::kMaxPosition));
        continue;
      }
      m_.probe.axes |= static_cast<AxisMask>(1u << i);
      m_.probe.trigger[i] = *v;
    }
  }

  // [machine.signals]: `1005 = 1` (or `"#1005" = 1`), the interface input signals a program
  // reads (signals.h).
  void readSignals(const toml::table& t) {
    for (const auto& [key_ptr, value_ptr] : inFileOrder(t)) {
      const toml::key& key = *key_ptr;
      std::string_view name = key.str();
      if (!name.empty() && name.front() == '#') name.remove_prefix(1);
      int64_t n = 0;
      const auto [end, ec] = std::from_chars(name.data(), name.data() + name.size(), n);
      if (name.empty() || ec != std::errc() || end != name.data() + name.size()) {
        ctx_.error(kUnknownKey, ctx_.at(key),
                   cat("unknown key '", key.str(), "' in [machine.signals] (a variable number "
                       "#1000 to #1035)"));
        continue;
      }
      const std::optional<double> v = ctx_.number(*value_ptr, key.str());
      if (!v) continue;
      if (std::optional<std::string> refused = checkInputSignal(n, *v)) {
        ctx_.error(kBadValue, ctx_.at(*value_ptr), *refused);
        continue;
      }
      m_.signals.values[static_cast<int>(n)] = *v;
    }
  }

  // Limits and servo parameters (servo_keys.cpp) of each axis.
  void readAxisLimits(const toml::table& t) {
    for (const auto& [key_ptr, node_ptr] : inFileOrder(t)) {
      const toml::key& key = *key_ptr;
      const toml::node& node = *node_ptr;
      int i = requireAxis(m_.axes, key.str(), ctx_.at(key), "machine.axis", ctx_);
      if (i < 0) continue;
      const std::string table_name = cat("[machine.axis.", key.str(), "]");
      const toml::table* limits = ctx_.table(node, cat("machine.axis.", key.str()));
      if (!limits) continue;
      AxisConfig& axis = m_.axes[i];
      for (const auto& [lkey_ptr, value_ptr] : inFileOrder(*limits)) {
        const toml::key& lkey = *lkey_ptr;
        const toml::node& value = *value_ptr;
        double* field = lkey == "min_travel"         ? &axis.min_travel
                        : lkey == "max_travel"       ? &axis.max_travel
                        : lkey == "rapid_velocity"   ? &axis.rapid_velocity
                        : lkey == "max_velocity"     ? &axis.max_velocity
                        : lkey == "max_acceleration" ? &axis.max_acceleration
                        : lkey == "max_jerk"         ? &axis.max_jerk
                                                     : nullptr;
        if (!field) {
          if (!readServoKey(lkey, value, axis, ctx_)) ctx_.unknownKey(lkey, table_name);
          continue;
        }
        auto v = ctx_.number(value, lkey.str());
        if (!v) continue;
        const bool is_travel = field == &axis.min_travel || field == &axis.max_travel;
        if (is_travel && travel_from_params_.count(i)) {
          ctx_.error(kBadValue, ctx_.at(lkey),
                     cat("travel limits of ", axis.name,
                         " are given twice: in 'software_limits' and in ", table_name));
          continue;
        }
        const auto [low, high] = axisLimitRange(lkey.str());
        if (!(*v >= low && *v <= high)) {
          ctx_.error(kBadValue, ctx_.at(value),
                     cat("'", lkey.str(), "' of ", axis.name, " must be at least ", low,
                         " and at most ", high, ", not ", *v));
          continue;
        }
        *field = *v;
      }
      if (!(axis.min_travel < axis.max_travel))
        ctx_.error(kBadValue, ctx_.at(node),
                   cat("min_travel ", axis.min_travel, " of ", axis.name,
                       " must be below max_travel ", axis.max_travel));
    }
  }

  // NCC0307 for every [machine.params] key the selected dialect does not apply.
  void warnParamsWithoutEffect() {
    const std::optional<Dialect> dialect =
        options_.dialect ? options_.dialect : m_.dialect ? m_.dialect : options_.default_dialect;
    if (!dialect) return;
    for (const auto& [key, where] : param_locations_) {
      const ParamSpec* spec = findParameter(key);
      if (!spec || paramApplies(*spec, *dialect)) continue;
      ctx_.warning(kNoEffect, where,
                   cat("parameter '", key, "' has no effect in ", dialectName(*dialect),
                       spec->applied_in.empty()
                           ? " (ncc does not apply it in any dialect yet)"
                           : cat(" (ncc applies it in ", spec->applied_in, ")")));
    }
  }

  // The sane range of an axis limit (bounds.h).
  static std::pair<double, double> axisLimitRange(std::string_view key) {
    if (key == "rapid_velocity" || key == "max_velocity")
      return {bounds::kMinVelocity, bounds::kMaxVelocity};
    if (key == "max_acceleration") return {bounds::kMinAcceleration, bounds::kMaxAcceleration};
    if (key == "max_jerk") return {bounds::kMinJerk, bounds::kMaxJerk};
    return {-bounds::kMaxCoordinate, bounds::kMaxCoordinate};  // travel
  }

  // A start position outside an axis' travel range: the machine could not stand there (a real
  // control would be in overtravel at power-on). Reported at the position's value.
  void checkStartWithinTravel() {
    if (!start_node_) return;
    if (const std::optional<TravelViolation> v = travelViolation(m_.axes, m_.start_position)) {
      const AxisConfig& a = m_.axes[static_cast<std::size_t>(v->axis)];
      const auto it = start_value_locations_.find(v->axis);
      ctx_.error(kBadValue, it != start_value_locations_.end() ? it->second : ctx_.at(*start_node_),
                 cat("start position ", v->position, " of ", a.name, " is outside its travel [",
                     a.min_travel, ", ", a.max_travel, "]"));
    }
  }

  void readStart(const toml::table& t) {
    for (const auto& [key_ptr, node_ptr] : inFileOrder(t)) {
      const toml::key& key = *key_ptr;
      const toml::node& node = *node_ptr;
      if (key != "position") {
        ctx_.unknownKey(key, "[start]");
        continue;
      }
      if (!node.is_table()) {
        ctx_.wrongType(node, "position", "a table by axis name ({ X = 0.0, ... })");
        continue;
      }
      if (auto values = readAxisValues(node, "position")) {
        m_.start_position = *values;
        start_node_ = &node;
        for (const auto& [key_ptr2, value_ptr2] : *node.as_table()) {
          const int i = m_.axisIndex(key_ptr2.str());
          if (i >= 0) start_value_locations_[i] = ctx_.at(value_ptr2);
        }
      }
    }
  }

  TomlContext& ctx_;
  const MachineFileOptions& options_;
  MachineConfig m_;
  std::set<std::string> registers_seen_;
  std::set<int> travel_from_params_;
  std::map<std::string, SourceLocation> param_locations_;
  const toml::node* start_node_ = nullptr;                 // [start] position, when read
  std::map<int, SourceLocation> start_value_locations_;    // axis -> its value in it
};

std::optional<MachineConfig> parseRegistered(std::string_view text, uint32_t file,
                                             DiagnosticEngine& diags,
                                             const MachineFileOptions& options,
                                             const std::string& display_name) {
  TomlContext ctx(file, diags);
  try {
#if TOML_EXCEPTIONS
    toml::table root;
    try {
      root = toml::parse(text, display_name);
    } catch (const toml::parse_error& e) {
      ctx.error(kSyntax, ctx.at(e.source()), std::string(e.description()));
      return std::nullopt;
    }
#else
    toml::parse_result parsed = toml::parse(text, display_name);
    if (!parsed) {
      ctx.error(kSyntax, ctx.at(parsed.error().source()),
                std::string(parsed.error().description()));
      return std::nullopt;
    }
    toml::table root = std::move(parsed).table();
#endif
    return MachineFileReader(ctx, options).read(root);
  } catch (const std::exception& e) {
    // Only resource exhaustion can get here; never let it leave the API.
    ctx.error(kCannotRead, ctx.fileOnly(), cat("cannot read the machine file: ", e.what()));
    return std::nullopt;
  }
}

}  // namespace
}  // namespace machine_file

std::optional<MachineConfig> parseMachineFile(std::string_view toml_text, std::string display_name,
                                              SourceManager& sources, DiagnosticEngine& diags,
                                              const MachineFileOptions& options) {
  uint32_t file = sources.addBuffer(display_name, std::string(toml_text));
  return machine_file::parseRegistered(toml_text, file, diags, options, display_name);
}

std::optional<MachineConfig> loadMachineFile(const std::filesystem::path& path,
                                             SourceManager& sources, DiagnosticEngine& diags,
                                             const MachineFileOptions& options) {
  uint32_t file = sources.addFile(path);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    diags.error(std::string(machine_file::kCannotRead), SourceLocation{file, 0, 0},
                "cannot read the machine file: it is a directory");
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (in) text << in.rdbuf();
  if (!in || in.bad()) {
    diags.error(std::string(machine_file::kCannotRead), SourceLocation{file, 0, 0},
                "cannot read the machine file: no such file or not readable");
    return std::nullopt;
  }
  return machine_file::parseRegistered(text.str(), file, diags, options, sources.displayName(file));
}

}  // namespace ncc
