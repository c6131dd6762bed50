#include "ncc/bytecode/format.h"

#include <array>

#include "ncc/machine/axes.h"

namespace ncc::bytecode {

namespace {

constexpr uint8_t kMotionFlags = kFlagExactStop;

// Indexed by opcode byte; an empty mnemonic marks an unused byte.
constexpr std::array<OpcodeInfo, 256> makeTable() {
  std::array<OpcodeInfo, 256> t{};
  auto set = [&t](Opcode op, const char* name, uint8_t flags, int8_t pops, int8_t pushes,
                  bool falls_through = true) {
    t[static_cast<uint8_t>(op)] = OpcodeInfo{name, flags, pops, pushes, falls_through};
  };
  set(Opcode::End, "END", 0, 0, 0, false);
  set(Opcode::Rapid, "RAPID", kMotionFlags | kFlagPerAxis, 0, 0);
  set(Opcode::Line, "LINE", kMotionFlags | kFlagFeedPerRev | kFlagFixedOverride, 0, 0);
  set(Opcode::Arc, "ARC", kMotionFlags | kFlagFeedPerRev | kFlagClockwise | kFlagFixedOverride,
      0, 0);
  set(Opcode::Dwell, "DWELL", kFlagRevolutions, 0, 0);
  set(Opcode::SpindleSpeed, "SPINDLE_SPEED", 0, 0, 0);
  set(Opcode::SpindleCW, "SPINDLE_CW", 0, 0, 0);
  set(Opcode::SpindleCCW, "SPINDLE_CCW", 0, 0, 0);
  set(Opcode::SpindleStop, "SPINDLE_STOP", 0, 0, 0);
  set(Opcode::SpindleOrient, "SPINDLE_ORIENT", 0, 0, 0);
  set(Opcode::ToolSelect, "TOOL_SELECT", 0, 0, 0);
  set(Opcode::ToolChange, "TOOL_CHANGE", 0, 0, 0);
  set(Opcode::CoolantOn, "COOLANT_ON", 0, 0, 0);
  set(Opcode::CoolantOff, "COOLANT_OFF", 0, 0, 0);
  set(Opcode::ProgramStop, "PROGRAM_STOP", 0, 0, 0);
  set(Opcode::OptionalStop, "OPTIONAL_STOP", 0, 0, 0);
  set(Opcode::ProgramEnd, "PROGRAM_END", 0, 0, 0, false);
  set(Opcode::ProgramEndRewind, "PROGRAM_END_REWIND", 0, 0, 0, false);
  set(Opcode::MCode, "M_CODE", 0, 0, 0);
  set(Opcode::RefCheck, "REFCHECK", 0, 0, 0);
  set(Opcode::Push, "PUSH", 0, 0, 1);
  set(Opcode::PushVacant, "PUSH_VACANT", 0, 0, 1);
  set(Opcode::Load, "LOAD", 0, 0, 1);
  set(Opcode::Store, "STORE", 0, 1, 0);
  set(Opcode::Pop, "POP", 0, 1, 0);
  set(Opcode::Add, "ADD", 0, 2, 1);
  set(Opcode::Sub, "SUB", 0, 2, 1);
  set(Opcode::Mul, "MUL", 0, 2, 1);
  set(Opcode::Div, "DIV", 0, 2, 1);
  set(Opcode::Neg, "NEG", 0, 1, 1);
  set(Opcode::CmpEq, "CMP_EQ", 0, 2, 1);
  set(Opcode::CmpNe, "CMP_NE", 0, 2, 1);
  set(Opcode::CmpLt, "CMP_LT", 0, 2, 1);
  set(Opcode::CmpLe, "CMP_LE", 0, 2, 1);
  set(Opcode::CmpGt, "CMP_GT", 0, 2, 1);
  set(Opcode::CmpGe, "CMP_GE", 0, 2, 1);
  set(Opcode::Jump, "JUMP", 0, 0, 0, false);
  set(Opcode::JumpIfFalse, "JUMP_IF_FALSE", 0, 1, 0);
  return t;
}

constexpr std::array<OpcodeInfo, 256> kTable = makeTable();

}  // namespace

const OpcodeInfo* opcodeInfo(uint8_t byte) {
  const OpcodeInfo& info = kTable[byte];
  return info.mnemonic == nullptr ? nullptr : &info;
}

uint32_t instructionSize(Opcode op, int axis_count) {
  const uint32_t axes = 8u * static_cast<uint32_t>(axis_count);
  switch (op) {
    case Opcode::Rapid: return 1 + 1 + axes;
    case Opcode::Line: return 1 + 1 + 8 + axes;
    case Opcode::Arc: return 1 + 1 + 1 + 1 + 1 + 4 + 8 + axes + 8 + 8;
    case Opcode::Dwell: return 1 + 1 + 8;
    case Opcode::SpindleSpeed:
    case Opcode::ToolSelect:
    case Opcode::MCode:
    case Opcode::Push: return 1 + 8;
    case Opcode::RefCheck: return 1 + 2 + 1 + axes;
    case Opcode::Load:
    case Opcode::Store:
    case Opcode::Jump:
    case Opcode::JumpIfFalse: return 1 + 4;
    default: return 1;
  }
}

uint32_t maxInstructionSize() { return instructionSize(Opcode::Arc, kMaxAxes); }

}  // namespace ncc::bytecode
