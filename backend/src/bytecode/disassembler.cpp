#include "ncc/bytecode/disassembler.h"

#include <charconv>
#include <sstream>
#include <string_view>

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

// The words of the flags set that the opcode accepts and its listing does not name, in
// flagTable() order.
std::string flagWords(std::string_view listing, const Instruction& in) {
  std::string words;
  for (const FlagInfo& flag : flagTable()) {
    const bool named = listing.find(absl::StrCat("{", flag.name, "}")) != std::string_view::npos;
    if ((in.flags & flag.bit) && (opcodeInfo(in.op).allowed_flags & flag.bit) && !named)
      absl::StrAppend(&words, words.empty() ? "" : " ", flag.when_set);
  }
  return words;
}

// The text of one operand (a placeholder of the opcode's listing).
std::string renderOperand(Operand kind, std::string_view listing, const Program& program,
                          const Instruction& in) {
  const uint16_t all = static_cast<uint16_t>((1u << program.axisCount()) - 1);
  switch (kind) {
    case Operand::Flags: return flagWords(listing, in);
    case Operand::Plane: {
      const uint8_t plane = static_cast<uint8_t>(in.plane);
      return plane < 3 ? kPlaneNames[plane] : "?";
    }
    case Operand::PlaneAxes:
      return absl::StrCat(axisName(program, in.axis1), " ", axisName(program, in.axis2));
    case Operand::Turns: return in.turns == 0 ? "" : absl::StrCat(in.turns);
    case Operand::Feed:
    case Operand::Amount:
    case Operand::Speed:
    case Operand::Constant: return formatNumber(in.value);
    case Operand::Target: return axesText(program, in.axes, all);
    case Operand::Centre:
      return absl::StrCat(axisName(program, in.axis1), formatNumber(in.center1), " ",
                          axisName(program, in.axis2), formatNumber(in.center2));
    case Operand::Mask: return absl::StrCat(absl::Hex(in.mask, absl::kZeroPad4));
    case Operand::Reference: return absl::StrCat(in.reference);
    case Operand::Position: return axesText(program, in.axes, in.mask);
    case Operand::Variable:
    case Operand::Assigned: return absl::StrCat(in.variable);
    case Operand::JumpTarget: return absl::StrCat(absl::Hex(in.target, absl::kZeroPad6));
    case Operand::Code: return absl::StrCat(in.code);
    case Operand::Results: return in.variable == 0 ? "" : absl::StrCat(in.variable);
    case Operand::Origin: return axesText(program, in.origin, all);
  }
  return "?";
}

// The text of placeholder `name` of the listing: an operand ({flags}: the words of the flags
// set that the listing does not name) or one flag by name (its word for set or clear).
std::string render(std::string_view name, std::string_view listing, const Program& program,
                   const Instruction& in) {
  for (Operand kind : opcodeInfo(in.op).operands())
    if (name == operandName(kind)) return renderOperand(kind, listing, program, in);
  for (const FlagInfo& flag : flagTable())
    if (name == flag.name) return (in.flags & flag.bit) ? flag.when_set : flag.when_clear;
  return "";
}

// The operands as the opcode's listing template says (format.h, OpcodeInfo::listing).
std::string operands(const Program& program, const Instruction& in) {
  const std::string_view listing = opcodeInfo(in.op).listing;
  std::string out;
  std::string optional;          // the [part] being read
  bool in_optional = false;
  bool printed = false;          // a placeholder of that part printed something
  for (std::size_t i = 0; i < listing.size(); ++i) {
    std::string& text = in_optional ? optional : out;
    const char c = listing[i];
    if (c == '[') {
      in_optional = true;
      optional.clear();
      printed = false;
    } else if (c == ']') {
      if (printed) out += optional;
      in_optional = false;
    } else if (c == '{') {
      const std::size_t close = listing.find('}', i);
      if (close == std::string_view::npos) break;  // the table test rules this out
      const std::string value = render(listing.substr(i + 1, close - i - 1), listing, program, in);
      printed = printed || !value.empty();
      text += value;
      i = close;
    } else {
      text += c;
    }
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
  for (const VariableName& n : program.variable_names)
    out << "; variable   #" << n.number << " "
        << (n.name < program.strings.size() ? program.strings[n.name] : "?") << "\n";
  if (!program.blocks.empty())
    out << "; blocks     " << program.blocks.size() << " bytes (the block store of PREPARE)\n";
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
                           opcodeInfo(in.op).mnemonic,
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
