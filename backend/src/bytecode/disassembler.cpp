#include "ncc/bytecode/disassembler.h"

#include <charconv>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "ncc/bytecode/instruction.h"

namespace ncc::bytecode {

namespace {

constexpr const char* kPlaneNames[] = {"XY", "ZX", "YZ"};

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      absl::StrAppend(&out, "\\", std::string(1, c));
    } else if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) {
      absl::StrAppend(&out, "\\x", absl::Hex(static_cast<unsigned char>(c), absl::kZeroPad2));
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string location(const Program& program, uint32_t offset) {
  const LineEntry* e = program.lineFor(offset);
  if (e == nullptr) return "-";
  std::string file = e->file < program.strings.size() ? program.strings[e->file] : "?";
  return absl::StrCat(file.empty() ? "-" : file, ":", e->line, ":", e->column);
}

std::string axesText(const Program& program, const AxisValues& values, uint16_t mask) {
  std::string out;
  for (int i = 0; i < program.axisCount(); ++i) {
    if ((mask & (1u << i)) == 0) continue;
    absl::StrAppend(&out, out.empty() ? "" : " ", program.header.axes[i].name,
                    formatNumber(values[i]));
  }
  return out;
}

std::string axisName(const Program& program, uint8_t axis) {
  return axis < program.axisCount() ? program.header.axes[axis].name : absl::StrCat("axis", axis);
}

std::string operands(const Program& program, const Instruction& in) {
  const uint16_t all = static_cast<uint16_t>((1u << program.axisCount()) - 1);
  std::string out;
  auto flag = [&](uint8_t bit, const char* word) {
    if (in.flags & bit) absl::StrAppend(&out, " ", word);
  };
  switch (in.op) {
    case Opcode::Rapid:
      out = axesText(program, in.axes, all);
      flag(kFlagPerAxis, "per-axis");
      flag(kFlagExactStop, "exact-stop");
      break;
    case Opcode::Line:
      out = absl::StrCat(axesText(program, in.axes, all), " F", formatNumber(in.value));
      flag(kFlagFeedPerRev, "per-rev");
      flag(kFlagExactStop, "exact-stop");
      flag(kFlagFixedOverride, "fixed-override");
      break;
    case Opcode::Arc: {
      const uint8_t plane = static_cast<uint8_t>(in.plane);
      out = absl::StrCat(plane < 3 ? kPlaneNames[plane] : "?", " ",
                         (in.flags & kFlagClockwise) ? "CW" : "CCW", " ",
                         axesText(program, in.axes, all), " centre ",
                         axisName(program, in.axis1), formatNumber(in.center1), " ",
                         axisName(program, in.axis2), formatNumber(in.center2), " F",
                         formatNumber(in.value));
      if (in.turns != 0) absl::StrAppend(&out, " turns ", in.turns);
      flag(kFlagFeedPerRev, "per-rev");
      flag(kFlagExactStop, "exact-stop");
      flag(kFlagFixedOverride, "fixed-override");
      break;
    }
    case Opcode::Dwell:
      out = absl::StrCat(formatNumber(in.value), (in.flags & kFlagRevolutions) ? " rev" : " s");
      break;
    case Opcode::SpindleSpeed: out = absl::StrCat("S", formatNumber(in.value)); break;
    case Opcode::ToolSelect: out = absl::StrCat("T", in.code); break;
    case Opcode::MCode: out = absl::StrCat("M", in.code); break;
    case Opcode::RefCheck:
      out = absl::StrCat("ref", in.reference, " ", axesText(program, in.axes, in.mask));
      break;
    case Opcode::Push: out = formatNumber(in.value); break;
    case Opcode::Load:
    case Opcode::Store: out = absl::StrCat("#", in.variable); break;
    case Opcode::Jump:
    case Opcode::JumpIfFalse: out = absl::StrCat(absl::Hex(in.target, absl::kZeroPad6)); break;
    default: break;
  }
  return out;
}

}  // namespace

std::string formatNumber(double v) {
  char buffer[64];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  if (ec != std::errc()) return "?";
  return std::string(buffer, end);
}

void disassemble(const Program& program, std::ostream& out) {
  const Header& h = program.header;
  out << "; ncc bytecode " << h.version_major << "." << h.version_minor << "\n";
  out << "; dialect    " << dialectName(h.dialect) << "\n";
  out << "; machine    " << absl::StrCat("0x", absl::Hex(h.config_hash, absl::kZeroPad16)) << "\n";
  out << "; axes      ";
  for (const AxisInfo& axis : h.axes)
    out << " " << axis.name << (axis.kind == AxisKind::Rotary ? "(rotary)" : "(linear)");
  out << "\n; variables  " << h.variable_count << "\n";
  for (size_t i = 0; i < program.strings.size(); ++i)
    out << "; string " << i << "   " << quoted(program.strings[i]) << "\n";
  for (size_t i = 0; i < program.units.size(); ++i) {
    const Unit& u = program.units[i];
    out << "; unit " << i << "     " << absl::StrCat(absl::Hex(u.entry, absl::kZeroPad6))
        << " " << (u.name < program.strings.size() ? quoted(program.strings[u.name]) : "?")
        << "\n";
  }
  uint32_t offset = 0;
  while (offset < program.code.size()) {
    Instruction in;
    uint32_t size = 0;
    if (decode(program.code, offset, program.axisCount(), in, size) != DecodeStatus::Ok) {
      out << absl::StrFormat("%06x  %-20s .byte 0x%02x  ; cannot decode, listing stops\n",
                             offset, location(program, offset), program.code[offset]);
      return;
    }
    const std::string args = operands(program, in);
    out << absl::StrFormat("%06x  %-20s %s%s%s\n", offset, location(program, offset),
                           opcodeInfo(static_cast<uint8_t>(in.op))->mnemonic,
                           args.empty() ? "" : " ", args);
    offset += size;
  }
}

std::string disassemble(const Program& program) {
  std::ostringstream out;
  disassemble(program, out);
  return out.str();
}

}  // namespace ncc::bytecode
