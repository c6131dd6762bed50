#include "ncc/bytecode/instruction.h"

#include "bytes.h"

namespace ncc::bytecode {

namespace {

// One operand at `p` (advanced past it) into its field of `out`.
void readOperand(Operand kind, const uint8_t*& p, int axis_count, Instruction& out) {
  auto f64 = [&p] {
    const double v = bytes::getF64(p);
    p += 8;
    return v;
  };
  switch (kind) {
    case Operand::Flags: out.flags = *p++; return;
    case Operand::Plane: out.plane = static_cast<ArcPlane>(*p++); return;
    case Operand::PlaneAxes:
      out.axis1 = *p++;
      out.axis2 = *p++;
      return;
    case Operand::Turns: out.turns = bytes::getU32(p), p += 4; return;
    case Operand::Feed:
    case Operand::Amount:
    case Operand::Speed:
    case Operand::Constant: out.value = f64(); return;
    case Operand::Target:
    case Operand::Position:
      for (int i = 0; i < axis_count; ++i) out.axes[i] = f64();
      return;
    case Operand::Centre:
      out.center1 = f64();
      out.center2 = f64();
      return;
    case Operand::Mask: out.mask = bytes::getU16(p), p += 2; return;
    case Operand::Reference: out.reference = *p++; return;
    case Operand::Variable:
    case Operand::Assigned:
    case Operand::Results: out.variable = bytes::getU32(p), p += 4; return;
    case Operand::Origin:
      for (int i = 0; i < axis_count; ++i) out.origin[i] = f64();
      return;
    case Operand::JumpTarget: out.target = bytes::getU32(p), p += 4; return;
    case Operand::Code: out.code = static_cast<int64_t>(bytes::getU64(p)), p += 8; return;
  }
}

// The field of `in` an operand of this kind holds, at `p` (advanced past it).
void writeOperand(Operand kind, const Instruction& in, int axis_count, uint8_t*& p) {
  switch (kind) {
    case Operand::Flags: bytes::putU8(p, in.flags); return;
    case Operand::Plane: bytes::putU8(p, static_cast<uint8_t>(in.plane)); return;
    case Operand::PlaneAxes:
      bytes::putU8(p, in.axis1);
      bytes::putU8(p, in.axis2);
      return;
    case Operand::Turns: bytes::putU32(p, in.turns); return;
    case Operand::Feed:
    case Operand::Amount:
    case Operand::Speed:
    case Operand::Constant: bytes::putF64(p, in.value); return;
    case Operand::Target:
    case Operand::Position:
      for (int i = 0; i < axis_count; ++i) bytes::putF64(p, in.axes[i]);
      return;
    case Operand::Centre:
      bytes::putF64(p, in.center1);
      bytes::putF64(p, in.center2);
      return;
    case Operand::Mask: bytes::putU16(p, in.mask); return;
    case Operand::Reference: bytes::putU8(p, in.reference); return;
    case Operand::Variable:
    case Operand::Assigned:
    case Operand::Results: bytes::putU32(p, in.variable); return;
    case Operand::Origin:
      for (int i = 0; i < axis_count; ++i) bytes::putF64(p, in.origin[i]);
      return;
    case Operand::JumpTarget: bytes::putU32(p, in.target); return;
    case Operand::Code: bytes::putU64(p, static_cast<uint64_t>(in.code)); return;
  }
}

}  // namespace

DecodeStatus decode(std::span<const uint8_t> code, uint32_t offset, int axis_count,
                    Instruction& out, uint32_t& size) {
  size = 0;
  if (offset >= code.size()) return DecodeStatus::Truncated;
  const OpcodeInfo* info = opcodeInfo(code[offset]);
  if (info == nullptr || axis_count < 0 || axis_count > kMaxAxes) return DecodeStatus::BadOpcode;
  const Opcode op = static_cast<Opcode>(code[offset]);
  const uint32_t length = instructionSize(op, axis_count);
  if (code.size() - offset < length) return DecodeStatus::Truncated;

  out = Instruction{};
  out.op = op;
  const uint8_t* p = code.data() + offset + 1;
  for (Operand kind : info->operands()) readOperand(kind, p, axis_count, out);
  size = length;
  return DecodeStatus::Ok;
}

uint32_t encode(const Instruction& in, int axis_count, uint8_t* buffer) {
  uint8_t* p = buffer;
  bytes::putU8(p, static_cast<uint8_t>(in.op));
  if (const OpcodeInfo* info = opcodeInfo(static_cast<uint8_t>(in.op)))
    for (Operand kind : info->operands()) writeOperand(kind, in, axis_count, p);
  return static_cast<uint32_t>(p - buffer);
}

}  // namespace ncc::bytecode
