#include "ncc/bytecode/instruction.h"

#include "bytes.h"

namespace ncc::bytecode {

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
  auto readAxes = [&](AxisValues& axes) {
    for (int i = 0; i < axis_count; ++i, p += 8) axes[i] = bytes::getF64(p);
  };
  switch (op) {
    case Opcode::Rapid:
      out.flags = *p++;
      readAxes(out.axes);
      break;
    case Opcode::Line:
      out.flags = *p++;
      out.value = bytes::getF64(p), p += 8;
      readAxes(out.axes);
      break;
    case Opcode::Arc:
      out.flags = *p++;
      out.plane = static_cast<ArcPlane>(*p++);
      out.axis1 = *p++;
      out.axis2 = *p++;
      out.turns = bytes::getU32(p), p += 4;
      out.value = bytes::getF64(p), p += 8;
      readAxes(out.axes);
      out.center1 = bytes::getF64(p), p += 8;
      out.center2 = bytes::getF64(p), p += 8;
      break;
    case Opcode::Dwell:
      out.flags = *p++;
      out.value = bytes::getF64(p);
      break;
    case Opcode::SpindleSpeed:
    case Opcode::Push:
      out.value = bytes::getF64(p);
      break;
    case Opcode::ToolSelect:
    case Opcode::MCode:
      out.code = static_cast<int64_t>(bytes::getU64(p));
      break;
    case Opcode::RefCheck:
      out.mask = bytes::getU16(p), p += 2;
      out.reference = *p++;
      readAxes(out.axes);
      break;
    case Opcode::Load:
    case Opcode::Store:
      out.variable = bytes::getU32(p);
      break;
    case Opcode::Jump:
    case Opcode::JumpIfFalse:
      out.target = bytes::getU32(p);
      break;
    default:
      break;
  }
  size = length;
  return DecodeStatus::Ok;
}

uint32_t encode(const Instruction& in, int axis_count, uint8_t* buffer) {
  uint8_t* p = buffer;
  bytes::putU8(p, static_cast<uint8_t>(in.op));
  auto writeAxes = [&](const AxisValues& axes) {
    for (int i = 0; i < axis_count; ++i) bytes::putF64(p, axes[i]);
  };
  switch (in.op) {
    case Opcode::Rapid:
      bytes::putU8(p, in.flags);
      writeAxes(in.axes);
      break;
    case Opcode::Line:
      bytes::putU8(p, in.flags);
      bytes::putF64(p, in.value);
      writeAxes(in.axes);
      break;
    case Opcode::Arc:
      bytes::putU8(p, in.flags);
      bytes::putU8(p, static_cast<uint8_t>(in.plane));
      bytes::putU8(p, in.axis1);
      bytes::putU8(p, in.axis2);
      bytes::putU32(p, in.turns);
      bytes::putF64(p, in.value);
      writeAxes(in.axes);
      bytes::putF64(p, in.center1);
      bytes::putF64(p, in.center2);
      break;
    case Opcode::Dwell:
      bytes::putU8(p, in.flags);
      bytes::putF64(p, in.value);
      break;
    case Opcode::SpindleSpeed:
    case Opcode::Push:
      bytes::putF64(p, in.value);
      break;
    case Opcode::ToolSelect:
    case Opcode::MCode:
      bytes::putU64(p, static_cast<uint64_t>(in.code));
      break;
    case Opcode::RefCheck:
      bytes::putU16(p, in.mask);
      bytes::putU8(p, in.reference);
      writeAxes(in.axes);
      break;
    case Opcode::Load:
    case Opcode::Store:
      bytes::putU32(p, in.variable);
      break;
    case Opcode::Jump:
    case Opcode::JumpIfFalse:
      bytes::putU32(p, in.target);
      break;
    default:
      break;
  }
  return static_cast<uint32_t>(p - buffer);
}

}  // namespace ncc::bytecode
