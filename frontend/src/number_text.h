#pragma once
// Numbers as written in a block: both parsers (ANTLR and the fast path) read and print them
// through these functions, so the two paths cannot disagree on a value.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace ncc::frontend {

struct NumberText {
  double value = 0.0;
  bool has_point = false;
  uint8_t digits = 0;  // digits written, capped at 255
};

// Reads an unsigned number `10`, `10.`, `.5`, `1.25` (the NUMBER token). nullopt when the
// value does not fit a double (hundreds of digits).
std::optional<NumberText> readNumber(std::string_view text);

// Reads an unsigned integer without a point that fits int64 (N, O, skip level, loop id).
std::optional<int64_t> readInteger(std::string_view text);

// Shortest text that reads back as `value`; with `has_point` it always shows a point
// ("10.", "1.5", "-0.25"), without it an integer-valued number prints as an integer.
std::string formatNumber(double value, bool has_point);

}  // namespace ncc::frontend
