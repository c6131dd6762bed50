#include "lexical.h"

#include "absl/strings/str_format.h"

namespace ncc::frontend {

std::string lexicalForm(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (static_cast<unsigned char>(c) >= 0x80) c = '\x01';
    else c = upperAscii(c);
  }
  return out;
}

std::string describeChar(char c) {
  unsigned char u = static_cast<unsigned char>(c);
  if (u >= 0x21 && u < 0x7f) return absl::StrFormat("'%c'", c);
  return absl::StrFormat("'\\x%02X'", u);
}

std::string canonicalFunctionName(std::string_view name) {
  if (name == "ATN") return "ATAN";
  if (name == "SQR") return "SQRT";
  if (name == "RND") return "ROUND";
  return std::string(name);
}

}  // namespace ncc::frontend
