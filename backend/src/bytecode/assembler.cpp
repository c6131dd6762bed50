#include "ncc/bytecode/assembler.h"

#include <array>
#include <cassert>

namespace ncc::bytecode {

Assembler::Assembler(Header header) { program_.header = std::move(header); }

Assembler& Assembler::at(uint32_t file, uint32_t line, uint32_t column) {
  LineEntry entry{offset(), file, line, column};
  if (!program_.lines.empty() && program_.lines.back().offset == entry.offset)
    program_.lines.back() = entry;
  else
    program_.lines.push_back(entry);
  return *this;
}

Assembler& Assembler::emit(const Instruction& instruction) {
  std::array<uint8_t, 128> buffer;
  assert(maxInstructionSize() <= buffer.size());
  const uint32_t size = encode(instruction, program_.axisCount(), buffer.data());
  program_.code.insert(program_.code.end(), buffer.begin(), buffer.begin() + size);
  return *this;
}

Assembler& Assembler::op(Opcode opcode) {
  Instruction in;
  in.op = opcode;
  return emit(in);
}

Assembler& Assembler::rapid(const AxisValues& to, uint8_t flags) {
  Instruction in;
  in.op = Opcode::Rapid;
  in.flags = flags;
  in.axes = to;
  return emit(in);
}

Assembler& Assembler::line(const AxisValues& to, double feed, uint8_t flags) {
  Instruction in;
  in.op = Opcode::Line;
  in.flags = flags;
  in.value = feed;
  in.axes = to;
  return emit(in);
}

Assembler& Assembler::skip(const AxisValues& to, double feed, uint32_t first_variable,
                           const AxisValues& origin, uint8_t flags) {
  Instruction in;
  in.op = Opcode::Skip;
  in.flags = flags;
  in.value = feed;
  in.variable = first_variable;
  in.axes = to;
  in.origin = origin;
  return emit(in);
}

Assembler& Assembler::arc(const AxisValues& to, uint8_t axis1, uint8_t axis2, double center1,
                          double center2, double feed, uint8_t flags, ArcPlane plane,
                          uint32_t turns) {
  Instruction in;
  in.op = Opcode::Arc;
  in.flags = flags;
  in.plane = plane;
  in.axis1 = axis1;
  in.axis2 = axis2;
  in.turns = turns;
  in.value = feed;
  in.axes = to;
  in.center1 = center1;
  in.center2 = center2;
  return emit(in);
}

Assembler& Assembler::dwell(double amount, uint8_t flags) {
  Instruction in;
  in.op = Opcode::Dwell;
  in.flags = flags;
  in.value = amount;
  return emit(in);
}

Assembler& Assembler::spindleSpeed(double rpm) {
  Instruction in;
  in.op = Opcode::SpindleSpeed;
  in.value = rpm;
  return emit(in);
}

Assembler& Assembler::toolSelect(int64_t tool) {
  Instruction in;
  in.op = Opcode::ToolSelect;
  in.code = tool;
  return emit(in);
}

Assembler& Assembler::mCode(int64_t code) {
  Instruction in;
  in.op = Opcode::MCode;
  in.code = code;
  return emit(in);
}

Assembler& Assembler::refCheck(uint16_t mask, uint8_t reference, const AxisValues& position) {
  Instruction in;
  in.op = Opcode::RefCheck;
  in.mask = mask;
  in.reference = reference;
  in.axes = position;
  return emit(in);
}

Assembler& Assembler::push(double value) {
  Instruction in;
  in.op = Opcode::Push;
  in.value = value;
  return emit(in);
}

Assembler& Assembler::load(uint32_t variable) {
  Instruction in;
  in.op = Opcode::Load;
  in.variable = variable;
  return emit(in);
}

Assembler& Assembler::store(uint32_t variable) {
  Instruction in;
  in.op = Opcode::Store;
  in.variable = variable;
  return emit(in);
}

Assembler::Label Assembler::newLabel() {
  labels_.push_back(-1);
  return static_cast<Label>(labels_.size() - 1);
}

Assembler& Assembler::bind(Label label) {
  labels_.at(label) = offset();
  return *this;
}

Assembler& Assembler::jump(Opcode jump_opcode, Label label) {
  fixups_.push_back({offset(), label});
  Instruction in;
  in.op = jump_opcode;
  return emit(in);
}

Program Assembler::finish(std::vector<std::string> strings, uint32_t unit_name) {
  for (const auto& [jump_offset, label] : fixups_) {
    // The jump again, now with its target, over the one emitted: the same opcode and size.
    const int64_t target = labels_.at(label);
    Instruction in;
    in.op = static_cast<Opcode>(program_.code[jump_offset]);
    in.target = target < 0 ? 0xFFFFFFFFu : static_cast<uint32_t>(target);
    encode(in, program_.axisCount(), program_.code.data() + jump_offset);
  }
  program_.strings = std::move(strings);
  program_.units = {Unit{0, unit_name}};
  return std::move(program_);
}

}  // namespace ncc::bytecode
