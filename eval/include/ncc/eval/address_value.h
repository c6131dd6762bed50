#pragma once
// The value an address word takes from a macro expression: `X#1`, `X-#2`, `G#8`, `M[3.5]`,
// `P#1`. Three outcomes: the word is dropped (the value is vacant: "G0 X#1 Y1000. with #1
// vacant is G0 Y1000.", Mazak §13-9-3 2. B), a value, or a failure (AddressValue: the value
// is outside what the address can hold). docs/macro.md, Values and vacant.
#include <cstdint>
#include <optional>
#include <string_view>

#include "ncc/eval/failure.h"
#include "ncc/eval/macro_rules.h"
#include "ncc/eval/value.h"

namespace ncc::eval {

enum class AddressShape : uint8_t {
  Real,     // axes, I J K R F Q E ...: a number, rounded to the least input increment
  Integer,  // D H L M N O P S T: a whole number (rules.address_rounding)
  GCode,    // G: a whole number with at most one decimal (G54.1), from 0 to 999.9
};

// The usual shape of an address ("X", "G", ",R"): G -> GCode; D H L M N O P S T ->
// Integer; everything else Real. A caller that knows better (Mazak's G51 P scale factor
// takes a point) passes its own shape.
AddressShape addressShape(std::string_view address);

struct AddressValue {
  bool dropped = false;  // vacant: the block is read as if the word were not written
  double value = 0.0;    // when not dropped
};

struct AddressLimits {
  // Real: the least input increment (0.001 mm); 0 keeps the value as computed.
  double increment = 0.0;
  // Digits the address holds: Integer at most 10^digits - 1, Real at most that many
  // increments (when `increment` is set).
  int digits = 8;
};

// The word's value; nullopt after filling `failure` (AddressValue, at `loc`).
std::optional<AddressValue> addressValue(const Value& value, AddressShape shape,
                                         const MacroRules& rules, AddressLimits limits,
                                         SourceLocation loc, Failure& failure);

}  // namespace ncc::eval
