#include "ncc/driver/json_output.h"

#include <cmath>
#include <filesystem>

#include "absl/strings/str_format.h"

namespace ncc::driver {

std::string jsonNumber(double value) {
  if (!std::isfinite(value)) return "null";
  std::string text = absl::StrFormat("%.6f", value);
  while (text.size() > 1 && text.back() == '0' && text[text.size() - 2] != '.') text.pop_back();
  if (text == "-0.0") text = "0.0";
  return text;
}

namespace {

const char* kindName(vm::MotionPrimitive::Kind kind) {
  switch (kind) {
    case vm::MotionPrimitive::Kind::Rapid: return "rapid";
    case vm::MotionPrimitive::Kind::Line: return "line";
    case vm::MotionPrimitive::Kind::Arc: return "arc";
    case vm::MotionPrimitive::Kind::Dwell: return "dwell";
  }
  return "rapid";
}

// Axis names are letters and digits only (machine file rules), so they need no escaping.
void writeAxes(std::ostream& out, const bytecode::Program& program, const AxisValues& values,
               int only_a = -1, int only_b = -1) {
  out << '{';
  bool first = true;
  for (int i = 0; i < program.axisCount(); ++i) {
    if (only_a >= 0 && i != only_a && i != only_b) continue;
    if (!first) out << ", ";
    first = false;
    out << '"' << program.header.axes[i].name << "\": " << jsonNumber(values[i]);
  }
  out << '}';
}

// Length of the well-formed UTF-8 sequence at the start of `s` (RFC 3629: no overlong forms,
// no surrogates, at most U+10FFFF), or 0.
size_t utf8Length(std::string_view s) {
  const auto byte = [&](size_t i) { return static_cast<unsigned char>(s[i]); };
  const unsigned char c = byte(0);
  size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // range of the second byte
  if (c >= 0xC2 && c <= 0xDF) n = 2;
  else if (c >= 0xE0 && c <= 0xEF) n = 3, lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
  else if (c >= 0xF0 && c <= 0xF4) n = 4, lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
  else return 0;
  if (s.size() < n || byte(1) < lo || byte(1) > hi) return 0;
  for (size_t i = 2; i < n; ++i)
    if (byte(i) < 0x80 || byte(i) > 0xBF) return 0;
  return n;
}

}  // namespace

std::string sourceFileName(const bytecode::Program& program, uint32_t index) {
  return index < program.strings.size()
             ? std::filesystem::path(program.strings[index]).filename().string()
             : std::string();
}

std::string jsonString(std::string_view text) {
  std::string quoted = "\"";
  for (size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += static_cast<char>(c);
    } else if (c < 0x20 || c == 0x7F) {
      quoted += absl::StrFormat("\\u%04x", c);
    } else if (c >= 0x80) {
      const size_t n = utf8Length(text.substr(i));
      if (n == 0) {  // not UTF-8: the replacement character, so the JSON stays valid
        quoted += "\\ufffd";
        ++i;
        continue;
      }
      quoted.append(text.substr(i, n));
      i += n;
      continue;
    } else {
      quoted += static_cast<char>(c);
    }
    ++i;
  }
  quoted += '"';
  return quoted;
}

void writeMoveJson(std::ostream& out, const vm::MotionPrimitive& m, const bytecode::Program& program) {
  out << "{\"line\": " << m.where.line << ", \"file\": " << jsonString(sourceFileName(program, m.where.file))
      << ", \"kind\": \"" << kindName(m.kind) << '"';
  if (m.kind == vm::MotionPrimitive::Kind::Dwell) {
    out << ", \"seconds\": " << jsonNumber(m.seconds);
    if (m.revolutions) out << ", \"revolutions\": true";
    out << "}\n";
    return;
  }
  out << ", \"to\": ";
  writeAxes(out, program, m.to);
  if (m.kind == vm::MotionPrimitive::Kind::Arc) {
    out << ", \"center\": ";
    writeAxes(out, program, m.center, m.axis1, m.axis2);
    out << ", \"cw\": " << (m.cw ? "true" : "false");
  }
  if (m.kind == vm::MotionPrimitive::Kind::Line || m.kind == vm::MotionPrimitive::Kind::Arc) {
    out << ", \"feed\": " << jsonNumber(m.feed);
    if (m.feed_per_rev) out << ", \"feed_per_rev\": true";
  }
  out << "}\n";
}

void writeVariablesJson(std::ostream& out, const std::vector<std::pair<std::string, double>>& vars) {
  out << '{';
  for (size_t i = 0; i < vars.size(); ++i) {
    if (i) out << ", ";
    out << jsonString(vars[i].first) << ": " << jsonNumber(vars[i].second);
  }
  out << "}\n";
}

void writeAlarmJson(std::ostream& out, const vm::Alarm& alarm, const bytecode::Program& program) {
  out << "{\"kind\": \"alarm\", \"code\": " << jsonString(alarm.code) << ", \"line\": "
      << alarm.where.line << ", \"file\": " << jsonString(sourceFileName(program, alarm.where.file))
      << ", \"message\": " << jsonString(alarm.message) << "}\n";
}

}  // namespace ncc::driver
