#include "ncc/vm/machine_check.h"

#include <cmath>
#include <string>

#include "absl/strings/str_cat.h"

namespace ncc::vm {
namespace {

// The machine file's upper bound for [machine] ipo_cycle (machine_file.cpp).
constexpr double kMaxIpoCycle = 0.1;

bytecode::Error problem(const std::string& what, double value, const std::string& rule) {
  return {"NCC7115", absl::StrCat("machine configuration: ", what, " is ", value, "; it must be ",
                                  rule)};
}

bool positive(double v) { return std::isfinite(v) && v > 0.0; }
bool nonNegative(double v) { return std::isfinite(v) && v >= 0.0; }

}  // namespace

std::optional<bytecode::Error> checkMachine(const MachineConfig& m) {
  if (!(positive(m.ipo_cycle_seconds) && m.ipo_cycle_seconds <= kMaxIpoCycle))
    return problem("ipo_cycle", m.ipo_cycle_seconds, "above 0 and at most 0.1 s");
  if (!positive(m.chord_tolerance)) return problem("chord_tolerance", m.chord_tolerance, "above 0");
  if (!nonNegative(m.corner_tolerance))
    return problem("corner_tolerance", m.corner_tolerance, "at least 0");
  for (const AxisConfig& a : m.axes) {
    const std::string& name = a.name;
    const struct {
      const char* key;
      double value;
    } positives[] = {{"rapid_velocity", a.rapid_velocity},
                     {"max_velocity", a.max_velocity},
                     {"max_acceleration", a.max_acceleration},
                     {"max_jerk", a.max_jerk},
                     {"kv", a.servo.kv},
                     {"pitch_error.step", a.servo.pitch_error.step},
                     {"pitch_compensation.step", a.servo.pitch_compensation.step}};
    for (const auto& [key, value] : positives)
      if (!positive(value)) return problem(absl::StrCat(key, " of ", name), value, "above 0");
    if (!nonNegative(a.servo.equiv_speedctrl_time))
      return problem(absl::StrCat("equiv_speedctrl_time of ", name), a.servo.equiv_speedctrl_time,
                     "at least 0");
    if (!(std::isfinite(a.min_travel) && std::isfinite(a.max_travel) &&
          a.min_travel < a.max_travel))
      return problem(absl::StrCat("min_travel of ", name), a.min_travel,
                     absl::StrCat("finite and below max_travel ", a.max_travel));
  }
  return std::nullopt;
}

}  // namespace ncc::vm
