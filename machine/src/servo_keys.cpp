// The servo keys of [machine.axis.<NAME>]: numbers with their ranges (servoNumberKeys(),
// servo_config.h), the feed-forward mode, and the two pitch tables { start, step, values }.
#include "servo_keys.h"

#include <string_view>

#include "text.h"

namespace ncc::machine_file {
namespace {

constexpr size_t kMaxPitchPoints = 5000;  // MD 38000 MM_ENC_COMP_MAX_POINTS upper limit

bool readPitchTable(const toml::node& node, std::string_view what, const std::string& axis,
                    PitchTable& out, TomlContext& ctx) {
  const toml::table* t = node.as_table();
  if (!t) {
    ctx.wrongType(node, what, "a table { start, step, values }");
    return false;
  }
  PitchTable table;
  bool ok = true, has_values = false;
  const toml::node* step_node = nullptr;     // where a fault of the table is reported
  const toml::array* values_node = nullptr;
  for (const auto& [key_ptr, value_ptr] : inFileOrder(*t)) {
    const toml::key& key = *key_ptr;
    const toml::node& value = *value_ptr;
    const std::string what_key = cat(what, ".", key.str());
    if (key == "start") {
      if (auto v = ctx.number(value, what_key)) table.start = *v; else ok = false;
    } else if (key == "step") {
      step_node = &value;
      auto v = ctx.number(value, what_key);
      if (v && *v <= 0) {
        ctx.error(kBadValue, ctx.at(value), cat("'", what_key, "' of ", axis, " must be above 0"));
        v.reset();
      }
      if (v) table.step = *v; else ok = false;
    } else if (key == "values") {
      has_values = true;
      const toml::array* arr = ctx.array(value, what_key);
      if (!arr) {
        ok = false;
        continue;
      }
      if (arr->empty() || arr->size() > kMaxPitchPoints) {
        ctx.error(kBadValue, ctx.at(value),
                  cat("'", what_key, "' of ", axis, " must have 1 to ", kMaxPitchPoints,
                      " values, not ", arr->size()));
        ok = false;
        continue;
      }
      values_node = arr;
      for (const toml::node& el : *arr) {
        if (auto v = ctx.number(el, what_key)) table.values.push_back(*v); else ok = false;
      }
    } else {
      ctx.error(kUnknownKey, ctx.at(key),
                cat("unknown key '", key.str(), "' in '", what, "' (expected start, step, values)"));
      ok = false;
    }
  }
  if (!has_values) {
    ctx.error(kBadValue, ctx.at(node), cat("'", what, "' of ", axis, " has no 'values'"));
    ok = false;
  }
  if (ok) {
    if (const std::optional<PitchTableFault> fault = pitchTableFault(table)) {
      const std::size_t k = fault->index;
      if (fault->kind == PitchTableFault::Kind::Grid) {
        ctx.error(kBadValue, ctx.at(step_node != nullptr ? *step_node : node),
                  cat("'", what, ".step' of ", axis, " is too small for its ", table.values.size(),
                      " support points: start + ", k, " step is not a finite number above start + ",
                      k - 1, " step"));
      } else {
        ctx.error(kBadValue, ctx.at(values_node != nullptr ? *values_node->get(k) : node),
                  cat("'", what, ".values' of ", axis, ": values[", k, "] - values[", k - 1,
                      "] over the step is not a finite slope"));
      }
      ok = false;
    }
  }
  if (ok) out = std::move(table);
  return ok;
}

}  // namespace

bool readServoKey(const toml::key& key, const toml::node& node, AxisConfig& axis,
                  TomlContext& ctx) {
  ServoConfig& servo = axis.servo;
  for (const ServoNumberKey& k : servoNumberKeys()) {
    if (key.str() != k.name) continue;
    auto v = ctx.number(node, k.name);
    if (!v) return true;
    if ((k.range == NumberRange::Positive && *v <= 0) ||
        (k.range == NumberRange::NonNegative && *v < 0)) {
      ctx.error(kBadValue, ctx.at(node),
                cat("'", k.name, "' of ", axis.name, " must be ",
                    k.range == NumberRange::Positive ? "above 0" : "at least 0"));
      return true;
    }
    servo.*k.field = *v;
    return true;
  }
  if (key == "ffw_mode") {
    auto s = ctx.string(node, "ffw_mode");
    if (!s) return true;
    if (*s == "none") servo.ffw_mode = FeedForwardMode::None;
    else if (*s == "velocity") servo.ffw_mode = FeedForwardMode::Velocity;
    else if (*s == "torque") servo.ffw_mode = FeedForwardMode::Torque;
    else
      ctx.error(kBadValue, ctx.at(node),
                cat("invalid value \"", *s, "\" for 'ffw_mode': expected \"none\", \"velocity\", "
                    "\"torque\""));
    return true;
  }
  if (key == "pitch_error" || key == "pitch_compensation") {
    PitchTable& table = key == "pitch_error" ? servo.pitch_error : servo.pitch_compensation;
    readPitchTable(node, key.str(), axis.name, table, ctx);
    return true;
  }
  return false;
}

}  // namespace ncc::machine_file
