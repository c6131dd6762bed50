#include "ncc/bytecode/format.h"

#include <algorithm>
#include <initializer_list>

#include "ncc/machine/axes.h"

namespace ncc::bytecode {

namespace {

using enum Operand;

constexpr uint8_t kMotionFlags = kFlagExactStop;

// The opcode table, indexed by opcode byte; a null mnemonic marks an unused byte. Everything
// about an opcode's bytes is here: encode() and decode() (instruction.cpp) read and write its
// operands in this order, instructionSize() adds their sizes, the verifier checks each operand
// by its kind and follows the stack effect and flow, the disassembler prints the listing.
//
// To add an opcode: give it a byte in `Opcode` (format.h), a row here, a row in the table of
// docs/bytecode.md and, if it takes an operand no opcode has yet, an `Operand` kind with its
// size (fixedSize below), its field in Instruction and its cases in encode/decode
// (instruction.cpp), the verifier's check (verifier.cpp, checkOperand), the disassembler's
// rendering (disassembler.cpp, renderOperand) and the round-trip test's sample: each switch over
// Operand lists every kind without a default, so -Wswitch (-Wall) names the ones forgotten.
// Then teach the executor (vm/src/executor.cpp) to run it. Either changes the format: raise
// the version (the minor for an addition: a loader refuses a minor newer than its own).
constexpr std::array<OpcodeInfo, 256> makeTable() {
  std::array<OpcodeInfo, 256> t{};
  auto set = [&t](Opcode op, const char* mnemonic, std::initializer_list<Operand> operands,
                  const char* listing, uint8_t flags = 0, int8_t pops = 0, int8_t pushes = 0,
                  Flow flow = Flow::Next) {
    OpcodeInfo& info = t[static_cast<uint8_t>(op)];
    info = OpcodeInfo{mnemonic, {}, 0, listing, flags, pops, pushes, flow};
    for (Operand kind : operands) info.operand_kinds[info.operand_count++] = kind;
  };
  // opcode, mnemonic, operands in byte order, listing, allowed flags, pops, pushes, flow
  set(Opcode::End, "END", {}, "", 0, 0, 0, Flow::Stop);
  set(Opcode::Rapid, "RAPID", {Flags, Target}, "{target}[ {flags}]",
      kMotionFlags | kFlagPerAxis);
  set(Opcode::Line, "LINE", {Flags, Feed, Target}, "{target} F{feed}[ {flags}]",
      kMotionFlags | kFlagFeedPerRev | kFlagFixedOverride);
  set(Opcode::Arc, "ARC", {Flags, Plane, PlaneAxes, Turns, Feed, Target, Centre},
      "{plane} {clockwise} {target} centre {centre} F{feed}[ turns {turns}][ {flags}]",
      kMotionFlags | kFlagFeedPerRev | kFlagClockwise | kFlagFixedOverride);
  // G31: the skip position (stop point - origin, in inches with kFlagInch) goes to the
  // Results variables.
  set(Opcode::Skip, "SKIP", {Flags, Feed, Results, Target, Origin},
      "{target} F{feed} origin {origin}[ #{results}][ {flags}]",
      kMotionFlags | kFlagFeedPerRev | kFlagFixedOverride | kFlagInch);
  set(Opcode::Dwell, "DWELL", {Flags, Amount}, "{amount} {revolutions}", kFlagRevolutions);
  set(Opcode::SpindleSpeed, "SPINDLE_SPEED", {Speed}, "S{speed}");
  set(Opcode::SpindleCW, "SPINDLE_CW", {}, "");
  set(Opcode::SpindleCCW, "SPINDLE_CCW", {}, "");
  set(Opcode::SpindleStop, "SPINDLE_STOP", {}, "");
  set(Opcode::SpindleOrient, "SPINDLE_ORIENT", {}, "");
  set(Opcode::ToolSelect, "TOOL_SELECT", {Code}, "T{code}");
  set(Opcode::ToolChange, "TOOL_CHANGE", {}, "");
  set(Opcode::CoolantOn, "COOLANT_ON", {}, "");
  set(Opcode::CoolantOff, "COOLANT_OFF", {}, "");
  set(Opcode::ProgramStop, "PROGRAM_STOP", {}, "");
  set(Opcode::OptionalStop, "OPTIONAL_STOP", {}, "");
  // Control passes to the VM's block preparation for good: it never comes back to the code.
  set(Opcode::Prepare, "PREPARE", {}, "", 0, 0, 0, Flow::Stop);
  set(Opcode::ProgramEnd, "PROGRAM_END", {}, "", 0, 0, 0, Flow::Stop);
  set(Opcode::ProgramEndRewind, "PROGRAM_END_REWIND", {}, "", 0, 0, 0, Flow::Stop);
  set(Opcode::MCode, "M_CODE", {Code}, "M{code}");
  set(Opcode::RefCheck, "REFCHECK", {Mask, Reference, Position}, "ref{reference} {position}");
  set(Opcode::Push, "PUSH", {Constant}, "{constant}", 0, 0, 1);
  set(Opcode::PushVacant, "PUSH_VACANT", {}, "", 0, 0, 1);
  set(Opcode::Load, "LOAD", {Variable}, "#{variable}", 0, 0, 1);
  set(Opcode::Store, "STORE", {Assigned}, "#{variable}", 0, 1, 0);
  set(Opcode::Pop, "POP", {}, "", 0, 1, 0);
  set(Opcode::Add, "ADD", {}, "", 0, 2, 1);
  set(Opcode::Sub, "SUB", {}, "", 0, 2, 1);
  set(Opcode::Mul, "MUL", {}, "", 0, 2, 1);
  set(Opcode::Div, "DIV", {}, "", 0, 2, 1);
  set(Opcode::Neg, "NEG", {}, "", 0, 1, 1);
  set(Opcode::CmpEq, "CMP_EQ", {}, "", 0, 2, 1);
  set(Opcode::CmpNe, "CMP_NE", {}, "", 0, 2, 1);
  set(Opcode::CmpLt, "CMP_LT", {}, "", 0, 2, 1);
  set(Opcode::CmpLe, "CMP_LE", {}, "", 0, 2, 1);
  set(Opcode::CmpGt, "CMP_GT", {}, "", 0, 2, 1);
  set(Opcode::CmpGe, "CMP_GE", {}, "", 0, 2, 1);
  set(Opcode::Jump, "JUMP", {JumpTarget}, "{jump}", 0, 0, 0, Flow::Jump);
  set(Opcode::JumpIfFalse, "JUMP_IF_FALSE", {JumpTarget}, "{jump}", 0, 1, 0, Flow::Branch);
  return t;
}

constexpr std::array<OpcodeInfo, 256> kTable = makeTable();

// Flag bits in listing order; the two with a word for "clear" print where their listing names
// them, the others under {flags} when set.
constexpr std::array<FlagInfo, 7> kFlags = {{
    {kFlagFeedPerRev, "feed-per-rev", "per-rev", ""},
    {kFlagPerAxis, "per-axis", "per-axis", ""},
    {kFlagExactStop, "exact-stop", "exact-stop", ""},
    {kFlagFixedOverride, "fixed-override", "fixed-override", ""},
    {kFlagClockwise, "clockwise", "CW", "CCW"},
    {kFlagRevolutions, "revolutions", "rev", "s"},
    {kFlagInch, "inch", "inch", ""},
}};

constexpr uint32_t kAxisVector = 0xFFFFFFFFu;  // size marker: 8 bytes per configured axis

constexpr uint32_t fixedSize(Operand kind) {
  switch (kind) {
    case Flags:
    case Plane:
    case Reference: return 1;
    case PlaneAxes:
    case Mask: return 2;
    case Turns:
    case Variable:
    case Assigned:
    case Results:
    case JumpTarget: return 4;
    case Feed:
    case Amount:
    case Speed:
    case Constant:
    case Code: return 8;
    case Centre: return 16;
    case Target:
    case Position:
    case Origin: return kAxisVector;
  }
  return 0;
}

// Instruction sizes as a + b * axis_count, per opcode byte: decode() asks for every
// instruction, so they are added up once, here.
struct Size {
  uint32_t fixed = 0;
  uint32_t vectors = 0;
};

constexpr std::array<Size, 256> makeSizes() {
  std::array<Size, 256> sizes{};
  for (int byte = 0; byte < 256; ++byte) {
    Size& s = sizes[byte];
    s.fixed = 1;  // the opcode
    for (Operand kind : kTable[byte].operands()) {
      if (fixedSize(kind) == kAxisVector) ++s.vectors;
      else s.fixed += fixedSize(kind);
    }
  }
  return sizes;
}

constexpr std::array<Size, 256> kSizes = makeSizes();

constexpr uint32_t largestSize() {
  uint32_t largest = 0;
  for (const Size& s : kSizes) largest = std::max(largest, s.fixed + s.vectors * 8u * kMaxAxes);
  return largest;
}

}  // namespace

bool OpcodeInfo::hasOperand(Operand kind) const {
  for (Operand o : operands())
    if (o == kind) return true;
  return false;
}

const OpcodeInfo* opcodeInfo(uint8_t byte) {
  const OpcodeInfo& info = kTable[byte];
  return info.mnemonic == nullptr ? nullptr : &info;
}

const OpcodeInfo& opcodeInfo(Opcode op) { return kTable[static_cast<uint8_t>(op)]; }

const char* operandName(Operand kind) {
  switch (kind) {
    case Flags: return "flags";
    case Plane: return "plane";
    case PlaneAxes: return "axes";
    case Turns: return "turns";
    case Feed: return "feed";
    case Amount: return "amount";
    case Speed: return "speed";
    case Constant: return "constant";
    case Target: return "target";
    case Centre: return "centre";
    case Mask: return "mask";
    case Reference: return "reference";
    case Position: return "position";
    case Variable:
    case Assigned: return "variable";
    case JumpTarget: return "jump";
    case Code: return "code";
    case Results: return "results";
    case Origin: return "origin";
  }
  return "?";
}

uint32_t operandSize(Operand kind, int axis_count) {
  const uint32_t size = fixedSize(kind);
  return size == kAxisVector ? 8u * static_cast<uint32_t>(axis_count) : size;
}

std::span<const FlagInfo> flagTable() { return kFlags; }

uint32_t instructionSize(Opcode op, int axis_count) {
  const Size& s = kSizes[static_cast<uint8_t>(op)];
  return s.fixed + s.vectors * 8u * static_cast<uint32_t>(axis_count);
}

uint32_t maxInstructionSize() {
  static constexpr uint32_t kLargest = largestSize();
  return kLargest;
}

}  // namespace ncc::bytecode
