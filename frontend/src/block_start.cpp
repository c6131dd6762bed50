#include "block_start.h"

#include "lexical.h"
#include "number_text.h"

namespace ncc::frontend {

BlockStart blockStart(std::string_view text) {
  using Kind = BlockStart::Kind;
  size_t i = 0;
  const auto skipBlanks = [&] {
    while (i < text.size() && isBlank(text[i])) ++i;
  };
  const auto atDigit = [&] { return i < text.size() && isDigit(text[i]); };
  skipBlanks();
  if (i < text.size() && text[i] == '%') return {Kind::Percent, 0};
  if (i < text.size() && text[i] == '/') {
    // Block skip: '/' and an optional single-digit level (the parsers refuse '/12', '/1.5').
    ++i;
    skipBlanks();
    if (atDigit()) {
      ++i;
      if (atDigit() || (i < text.size() && text[i] == '.')) return {Kind::Other, 0};
    }
  }
  for (skipBlanks(); i < text.size() && text[i] == '('; skipBlanks()) {
    const size_t close = text.find(')', i);
    if (close == std::string_view::npos) return {Kind::Other, 0};  // unclosed: an error block
    i = close + 1;
  }
  if (i == text.size()) return {Kind::Blank, 0};
  const char letter = upperAscii(text[i]);
  if (letter != 'N' && letter != 'O' && letter != ':') return {Kind::Other, 0};
  ++i;
  skipBlanks();
  const size_t digits = i;
  while (atDigit()) ++i;
  // N and O take unsigned integer digits: `N10.` or `N` alone is not a label.
  if (i == digits || (i < text.size() && text[i] == '.')) return {Kind::Other, 0};
  const std::optional<int64_t> n = readInteger(text.substr(digits, i - digits));
  if (!n) return {Kind::Other, 0};
  return {letter == 'N' ? Kind::Sequence : Kind::Program, *n};
}

std::string_view blockLabel(std::string_view text) {
  size_t i = 0;
  const auto skipBlanks = [&] {
    while (i < text.size() && isBlank(text[i])) ++i;
  };
  skipBlanks();
  if (i < text.size() && text[i] == '/') {
    ++i;
    if (i < text.size() && isDigit(text[i])) ++i;
    skipBlanks();
  }
  if (i < text.size() && (upperAscii(text[i]) == 'N' || text[i] == ':') && i + 1 < text.size() &&
      isDigit(text[i + 1])) {
    ++i;
    while (i < text.size() && isDigit(text[i])) ++i;
    skipBlanks();
  }
  const size_t first = i;
  if (i >= text.size() || !(isLetter(text[i]) || text[i] == '_')) return {};
  while (i < text.size() && (isLetter(text[i]) || isDigit(text[i]) || text[i] == '_')) ++i;
  const size_t end = i;
  skipBlanks();
  if (i >= text.size() || text[i] != ':') return {};
  return text.substr(first, end - first);
}

bool sameLabel(std::string_view written, std::string_view upper) {
  if (written.size() != upper.size() || written.empty()) return false;
  for (size_t i = 0; i < written.size(); ++i)
    if (upperAscii(written[i]) != upper[i]) return false;
  return true;
}

}  // namespace ncc::frontend
