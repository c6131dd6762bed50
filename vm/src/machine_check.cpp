#include "ncc/vm/machine_check.h"

#include <cmath>
#include <string>
#include <string_view>

#include "absl/strings/str_cat.h"
#include "ncc/machine/bounds.h"
#include "ncc/machine/travel.h"

namespace ncc::vm {
namespace {

bytecode::Error problem(const std::string& what, double value, const std::string& rule) {
  return {"NCC7115", absl::StrCat("machine configuration: ", what, " is ", value, "; it must be ",
                                  rule)};
}

bool positive(double v) { return std::isfinite(v) && v > 0.0; }
bool within(double v, double low, double high) { return v >= low && v <= high; }
std::string rangeRule(double low, double high) {
  return absl::StrCat("at least ", low, " and at most ", high);
}
bool nonNegative(double v) { return std::isfinite(v) && v >= 0.0; }

struct Value {
  std::string_view key;
  double value;
  NumberRange range;  // Any: finite
};

bool holds(const Value& v) {
  switch (v.range) {
    case NumberRange::Positive: return positive(v.value);
    case NumberRange::NonNegative: return nonNegative(v.value);
    case NumberRange::Any: return std::isfinite(v.value);
  }
  return false;
}

const char* rangeText(NumberRange range) {
  switch (range) {
    case NumberRange::Positive: return "above 0";
    case NumberRange::NonNegative: return "at least 0";
    case NumberRange::Any: return "finite";
  }
  return "";
}

std::optional<bytecode::Error> checkValue(const Value& v, const std::string& axis) {
  if (holds(v)) return std::nullopt;
  return problem(absl::StrCat(std::string(v.key), " of ", axis), v.value, rangeText(v.range));
}

// A pitch table's start and values: a NaN there makes every actual position NaN. Its grid and
// slopes (pitchTableFault): support points that coincide made a lookup walk the grid point by
// point, and an infinite slope gave infinite positions.
std::optional<bytecode::Error> checkTable(const PitchTable& table, const char* key,
                                          const std::string& axis) {
  if (!std::isfinite(table.start))
    return problem(absl::StrCat(key, ".start of ", axis), table.start, "finite");
  for (std::size_t i = 0; i < table.values.size(); ++i)
    if (!std::isfinite(table.values[i]))
      return problem(absl::StrCat(key, ".values[", i, "] of ", axis), table.values[i], "finite");
  if (!(table.step > 0.0)) return std::nullopt;  // reported as the step's range
  if (const std::optional<PitchTableFault> fault = pitchTableFault(table)) {
    const std::size_t k = fault->index;
    if (fault->kind == PitchTableFault::Kind::Grid)
      return problem(absl::StrCat(key, ".step of ", axis), table.step,
                     absl::StrCat("large enough that start + k step gives ", table.values.size(),
                                  " distinct finite support points (point ", k, " is ",
                                  pitchSupport(table.start, table.step, k), ")"));
    return problem(absl::StrCat(key, ".values[", k, "] of ", axis), table.values[k],
                   absl::StrCat("within a finite slope of values[", k - 1, "] over the step ",
                                table.step));
  }
  return std::nullopt;
}

}  // namespace

std::optional<bytecode::Error> checkMachine(const MachineConfig& m) {
  using namespace bounds;
  if (!within(m.ipo_cycle_seconds, kMinIpoCycle, kMaxIpoCycle))
    return problem("ipo_cycle", m.ipo_cycle_seconds,
                   absl::StrCat(rangeRule(kMinIpoCycle, kMaxIpoCycle), " s"));
  if (!within(m.chord_tolerance, kMinChordTolerance, kMaxChordTolerance))
    return problem("chord_tolerance", m.chord_tolerance,
                   rangeRule(kMinChordTolerance, kMaxChordTolerance));
  if (m.corner_tolerance != 0.0 &&
      !within(m.corner_tolerance, kMinCornerTolerance, kMaxCornerTolerance))
    return problem("corner_tolerance", m.corner_tolerance,
                   absl::StrCat("0 or ", rangeRule(kMinCornerTolerance, kMaxCornerTolerance)));
  for (std::size_t i = 0; i < m.axes.size(); ++i) {
    const AxisConfig& a = m.axes[i];
    const std::string& name = a.name;
    // The machine file's ranges, which a configuration built in code skips.
    const ServoConfig& servo = a.servo;
    struct Limit {
      const char* key;
      double value, low, high;
    };
    const Limit limits[] = {
        {"rapid_velocity", a.rapid_velocity, kMinVelocity, kMaxVelocity},
        {"max_velocity", a.max_velocity, kMinVelocity, kMaxVelocity},
        {"max_acceleration", a.max_acceleration, kMinAcceleration, kMaxAcceleration},
        {"max_jerk", a.max_jerk, kMinJerk, kMaxJerk}};
    for (const Limit& l : limits)
      if (!within(l.value, l.low, l.high))
        return problem(absl::StrCat(l.key, " of ", name), l.value, rangeRule(l.low, l.high));
    for (const ServoNumberKey& k : servoNumberKeys())
      if (auto e = checkValue({k.name, servo.*k.field, k.range}, name)) return e;
    const Value steps[] = {
        {"pitch_error.step", servo.pitch_error.step, NumberRange::Positive},
        {"pitch_compensation.step", servo.pitch_compensation.step, NumberRange::Positive}};
    for (const Value& v : steps)
      if (auto e = checkValue(v, name)) return e;
    if (auto e = checkTable(servo.pitch_error, "pitch_error", name)) return e;
    if (auto e = checkTable(servo.pitch_compensation, "pitch_compensation", name)) return e;
    if (i < m.start_position.size() && !within(m.start_position[i], -kMaxPosition, kMaxPosition))
      return problem(absl::StrCat("start_position of ", name), m.start_position[i],
                     absl::StrCat("within +-", kMaxPosition));
    if (!(within(a.min_travel, -kMaxCoordinate, kMaxCoordinate) &&
          within(a.max_travel, -kMaxCoordinate, kMaxCoordinate) && a.min_travel < a.max_travel))
      return problem(absl::StrCat("min_travel of ", name), a.min_travel,
                     absl::StrCat("within +-", kMaxCoordinate, " and below max_travel ",
                                  a.max_travel));
  }
  if (const std::optional<TravelViolation> v = travelViolation(m.axes, m.start_position)) {
    const AxisConfig& a = m.axes[static_cast<std::size_t>(v->axis)];
    return problem(absl::StrCat("start_position of ", a.name), v->position,
                   absl::StrCat("within its travel [", a.min_travel, ", ", a.max_travel, "]"));
  }
  return std::nullopt;
}

}  // namespace ncc::vm
