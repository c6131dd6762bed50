#pragma once
// Lexical facts shared by the ANTLR path and the fast path.
#include <cstddef>
#include <string>
#include <string_view>

namespace ncc::frontend {

// The text the ANTLR lexer sees: ASCII letters upper-cased, bytes >= 0x80 replaced by 0x01
// (only valid inside comments, whose text is taken from the original). Same length, so
// every index is a column of the original.
std::string lexicalForm(std::string_view text);

// "'@'", or "'\x01'" style for bytes that do not print.
std::string describeChar(char c);

inline bool isBlank(char c) { return c == ' ' || c == '\t'; }
inline bool isDigit(char c) { return c >= '0' && c <= '9'; }
inline bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
inline char upperAscii(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 32) : c; }

// The addresses that may follow a comma: ,A (angle) ,C (chamfer) ,R (corner radius).
inline bool isCommaAddressLetter(char upper) {
  return upper == 'A' || upper == 'C' || upper == 'R';
}

// Function names are kept in one spelling: the Mazak short forms ATN, SQR, RND become
// ATAN, SQRT, ROUND.
std::string canonicalFunctionName(std::string_view written_upper);

}  // namespace ncc::frontend
