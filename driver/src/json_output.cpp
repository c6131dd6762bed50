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

// The file's own name (no folders), JSON-escaped.
std::string fileName(const bytecode::Program& program, uint32_t index) {
  std::string name = index < program.strings.size()
                         ? std::filesystem::path(program.strings[index]).filename().string()
                         : std::string();
  std::string escaped;
  for (char c : name) {
    if (c == '"' || c == '\\') escaped += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      escaped += absl::StrFormat("\\u%04x", c);
      continue;
    }
    escaped += c;
  }
  return escaped;
}

}  // namespace

void writeMoveJson(std::ostream& out, const vm::MotionPrimitive& m, const bytecode::Program& program) {
  out << "{\"line\": " << m.where.line << ", \"file\": \"" << fileName(program, m.where.file)
      << "\", \"kind\": \"" << kindName(m.kind) << '"';
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
    out << '"' << vars[i].first << "\": " << jsonNumber(vars[i].second);
  }
  out << "}\n";
}

}  // namespace ncc::driver
