// Values of address words given by expressions. What the manuals say:
//  - a vacant value drops the address (Mazak §13-9-3 2. B: "les adresses elles-mêmes seront
//    négligées");
//  - a variable's value is read as written with a point: #100 = 10 makes X#100 X10. (Mazak
//    §13-6 C), and #1 = 2500 makes P#1 P2500 (FANUC lathe §4.2.8): the value is in units,
//    whatever the decimal-point mode;
//  - at D H L M N O S T a fraction is dropped (Mazak §2-3 note 6; its sentence on variables
//    there, "leur totalité sera considérée comme données", is unclear) or rounded to the
//    least significant digit (FANUC common): rules.address_rounding.
#include "ncc/eval/address_value.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "number_format.h"

namespace ncc::eval {

namespace {

double whole(double v, Rounding rounding) {
  // As in expression.cpp: 2.9999999999999996 is 3 (binary fractions of decimal input).
  const double r = std::round(v);
  if (std::fabs(v - r) <= 1e-9 * std::max(1.0, std::fabs(v))) return r;
  return rounding == Rounding::Nearest ? r : std::trunc(v);
}

std::optional<AddressValue> refuse(Failure& failure, SourceLocation loc, std::string message) {
  failure.error = EvalError::AddressValue;
  failure.loc = loc;
  failure.message = std::move(message);
  return std::nullopt;
}

}  // namespace

AddressShape addressShape(std::string_view address) {
  if (address.size() != 1) return AddressShape::Real;  // ,C ,R ,A
  switch (address[0]) {
    case 'G':
      return AddressShape::GCode;
    case 'D': case 'H': case 'L': case 'M': case 'N': case 'O': case 'P': case 'S': case 'T':
      return AddressShape::Integer;
    default:
      return AddressShape::Real;
  }
}

std::optional<AddressValue> addressValue(const Value& value, AddressShape shape,
                                         const MacroRules& rules, AddressLimits limits,
                                         SourceLocation loc, Failure& failure) {
  if (value.vacant) return AddressValue{.dropped = true};
  const double v = value.number;
  const double max_count = std::pow(10.0, limits.digits) - 1.0;
  switch (shape) {
    case AddressShape::Integer: {
      const double n = whole(v, rules.address_rounding);
      if (std::fabs(n) > max_count)
        return refuse(failure, loc,
                      absl::StrCat("value ", formatNumber(v), " has more than ", limits.digits,
                                   " digits"));
      return AddressValue{.value = n == 0.0 ? 0.0 : n};
    }
    case AddressShape::GCode: {
      // G codes have one decimal place (G54.1, G31.1): the value is taken to tenths.
      const double tenths = whole(v * 10.0, rules.address_rounding);
      if (tenths < 0.0 || tenths > 9999.0)
        return refuse(failure, loc,
                      absl::StrCat("G", formatNumber(v), " is not a G code (0 to 999.9)"));
      return AddressValue{.value = tenths / 10.0};
    }
    case AddressShape::Real:
      break;
  }
  if (limits.increment <= 0.0) return AddressValue{.value = v};
  // Rounded to the least significant digit of the address (FANUC common); the count of
  // increments is the digit limit of the word format.
  const double count = std::round(v / limits.increment);
  if (std::fabs(count) > max_count)
    return refuse(failure, loc,
                  absl::StrCat("value ", formatNumber(v), " has more than ", limits.digits,
                               " digits of ", formatNumber(limits.increment)));
  const double r = count * limits.increment;
  return AddressValue{.value = r == 0.0 ? 0.0 : r};
}

}  // namespace ncc::eval
