#pragma once
// One instruction, decoded into plain fields (no allocation), and its byte encoding. The
// verifier, the disassembler, the executor and the writers all go through these two functions,
// which read and write the operands the opcode table (format.h, OpcodeInfo) lists: the one
// definition of the operand layout.
#include <cstdint>
#include <span>

#include "ncc/bytecode/format.h"
#include "ncc/machine/axes.h"

namespace ncc::bytecode {

struct Instruction {
  Opcode op = Opcode::End;
  uint8_t flags = 0;          // kFlag* bits (motion, dwell)
  ArcPlane plane = ArcPlane::XY;
  uint8_t axis1 = 0;          // ARC: indices of the two plane axes (first, second)
  uint8_t axis2 = 1;
  uint32_t turns = 0;         // ARC: full circles beyond the first
  uint16_t mask = 0;          // REFCHECK: axes checked
  uint8_t reference = 1;      // REFCHECK: reference point number
  uint32_t variable = 0;      // LOAD, STORE; SKIP: first result variable (0: none)
  uint32_t target = 0;        // JUMP, JUMP_IF_FALSE: code offset
  int64_t code = 0;           // TOOL_SELECT T, M_CODE M
  double value = 0.0;         // LINE/ARC feed, DWELL amount, SPINDLE_SPEED, PUSH constant
  AxisValues axes{};          // RAPID/LINE/ARC target, REFCHECK position (axis_count used)
  double center1 = 0.0;       // ARC centre on axis1 and axis2
  double center2 = 0.0;
  AxisValues origin{};        // SKIP: machine coordinates of the work zero
};

enum class DecodeStatus : uint8_t { Ok, Truncated, BadOpcode };

// Decodes the instruction at `offset` of `code`; `size` receives its encoded length.
// Bounds-checked: never reads outside `code`. Operand values are not validated (verifier.h).
DecodeStatus decode(std::span<const uint8_t> code, uint32_t offset, int axis_count,
                    Instruction& out, uint32_t& size);

// Encodes into `buffer` (at least maxInstructionSize() bytes); returns the length written.
uint32_t encode(const Instruction& in, int axis_count, uint8_t* buffer);

}  // namespace ncc::bytecode
