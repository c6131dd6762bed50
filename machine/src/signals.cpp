#include "ncc/machine/signals.h"

#include <charconv>
#include <cmath>

#include "absl/strings/str_cat.h"

namespace ncc {

std::optional<std::string> checkInputSignal(int64_t number, double value) {
  if (number < kFirstInputSignal || number > kLastInputSignal)
    return absl::StrCat("#", number, " is not an interface input signal (#", kFirstInputSignal,
                        " to #", kLastInputSignal, ")");
  if (number == kInputWord)
    return absl::StrCat("#", kInputWord, " is the word of #", kFirstInputSignal, " to #",
                        kLastInputBit, ": set those bits instead");
  if (number <= kLastInputBit) {
    if (value != 0.0 && value != 1.0)
      return absl::StrCat("#", number, " is one contact: 0 (open) or 1 (closed), not ", value);
    return std::nullopt;
  }
  if (!(value >= 0.0 && value <= 4294967295.0) || value != std::floor(value))
    return absl::StrCat("#", number, " is a 32-bit word: an integer from 0 to 4294967295, not ",
                        value);
  return std::nullopt;
}

std::optional<std::string> setSignalFromOption(InputSignals& signals, std::string_view text) {
  const size_t eq = text.find('=');
  if (eq == std::string_view::npos)
    return absl::StrCat("'", std::string(text), "' is not N=VALUE (for example 1005=1)");
  std::string_view name = text.substr(0, eq);
  if (!name.empty() && name.front() == '#') name.remove_prefix(1);
  const std::string_view number = text.substr(eq + 1);
  int64_t n = 0;
  double v = 0.0;
  const auto [name_end, name_ec] = std::from_chars(name.data(), name.data() + name.size(), n);
  if (name.empty() || name_ec != std::errc() || name_end != name.data() + name.size())
    return absl::StrCat("'", std::string(text), "' does not start with a variable number");
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), v);
  if (number.empty() || ec != std::errc() || end != number.data() + number.size())
    return absl::StrCat("'", std::string(number), "' in '", std::string(text),
                        "' is not a number");
  if (std::optional<std::string> refused = checkInputSignal(n, v)) return refused;
  signals.values[static_cast<int>(n)] = v;
  return std::nullopt;
}

double inputSignalValue(const InputSignals& signals, int64_t number) {
  if (number == kInputWord) {
    double word = 0.0;
    for (const auto& [n, v] : signals.values)
      if (n >= kFirstInputSignal && n <= kLastInputBit && v != 0.0)
        word += std::ldexp(1.0, n - kFirstInputSignal);
    return word;
  }
  const auto it = signals.values.find(static_cast<int>(number));
  return it == signals.values.end() ? 0.0 : it->second;
}

}  // namespace ncc
