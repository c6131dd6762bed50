#include "number_text.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace ncc::frontend {

std::optional<NumberText> readNumber(std::string_view text) {
  NumberText n;
  size_t digits = 0;
  for (char c : text) {
    if (c == '.') n.has_point = true;
    else ++digits;
  }
  n.digits = static_cast<uint8_t>(digits > 255 ? 255 : digits);
  // from_chars does not accept a trailing point ("10.") in every library; it also accepts
  // ".5" only through the general format, which is what we use.
  std::string_view body = text;
  if (!body.empty() && body.back() == '.') body.remove_suffix(1);
  if (body.empty()) return std::nullopt;
  double value = 0.0;
  auto [end, ec] = std::from_chars(body.data(), body.data() + body.size(), value,
                                   std::chars_format::fixed);
  if (ec != std::errc() || end != body.data() + body.size() || !std::isfinite(value))
    return std::nullopt;
  n.value = value;
  return n;
}

std::optional<int64_t> readInteger(std::string_view text) {
  if (text.empty()) return std::nullopt;
  int64_t value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < 0) return std::nullopt;
  return value;
}

std::string formatNumber(double value, bool has_point) {
  char buf[400];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed);
  std::string out = ec == std::errc() ? std::string(buf, end) : std::string("?");
  if (has_point && out.find('.') == std::string::npos) out += '.';
  return out;
}

}  // namespace ncc::frontend
