#include "value_rules.h"

#include <cmath>
#include <iterator>

namespace ncc::passes {

namespace {
constexpr double kMmPerInch = 25.4;
}

ValueRules ValueRules::fromParams(const ParameterSet& params, std::string_view decimal_default) {
  ValueRules r;
  r.standard = params.getString("decimal_point", std::string(decimal_default)) == "standard";
  if (params.getString("increment_system", "IS-B") == "IS-C") {
    r.mm_increment = 0.0001;
    r.inch_increment = 0.00001;
    r.deg_increment = 0.0001;
    r.time_increment = 0.0001;
  }
  if (params.getBool("input_unit_x10", false)) r.x10 = 10.0;
  return r;
}

double ValueRules::linear(double v, bool point, ir::Units units) const {
  bool inch = units == ir::Units::Inch;
  if (standard && !point) v *= (inch ? inch_increment : mm_increment) * x10;
  return inch ? v * kMmPerInch : v;
}

double ValueRules::rotary(double v, bool point) const {
  return (standard && !point) ? v * deg_increment * x10 : v;
}

double ValueRules::offset(double v, bool point, ir::Units units) const {
  bool inch = units == ir::Units::Inch;
  if (standard && !point) v *= inch ? inch_increment : mm_increment;
  return inch ? v * kMmPerInch : v;
}

double ValueRules::dwellX(double v, bool point) const {
  return (standard && !point) ? v * time_increment : v;
}

double ValueRules::maxCount() const {
  // Asked for every word of every block: a table rather than pow (exact either way).
  static constexpr double kPowersOfTen[] = {1e0, 1e1, 1e2, 1e3, 1e4,  1e5,  1e6,  1e7,  1e8,
                                            1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16};
  if (digits >= 0 && digits < static_cast<int>(std::size(kPowersOfTen)))
    return kPowersOfTen[digits] - 1.0;
  return std::pow(10.0, digits) - 1.0;
}

double ValueRules::lengthIncrement(ir::Units units) const {
  return units == ir::Units::Inch ? inch_increment : mm_increment;
}

double ValueRules::feedInput(double v, bool point, ir::Units units, ir::FeedMode mode) const {
  bool inch = units == ir::Units::Inch;
  if (standard && !point) {
    if (mode == ir::FeedMode::PerRevolution) v *= inch ? 0.0001 : 0.01;
    else if (mode == ir::FeedMode::PerMinute && inch) v *= 0.01;
  }
  return v;
}

double ValueRules::feed(double v, bool point, ir::Units units, ir::FeedMode mode) const {
  v = feedInput(v, point, units, mode);
  if (mode == ir::FeedMode::InverseTime) return v;
  return units == ir::Units::Inch ? v * kMmPerInch : v;
}

}  // namespace ncc::passes
