#pragma once
// Builds a Program in memory instruction by instruction, with forward and backward labels.
// For hand-written bytecode: tests, fuzz seeds, and code the compiler does not emit yet
// (variables, arithmetic, jumps). The result still has to pass verify() like any file.
#include <cstdint>
#include <string>
#include <vector>

#include "ncc/bytecode/instruction.h"
#include "ncc/bytecode/program.h"

namespace ncc::bytecode {

class Assembler {
 public:
  using Label = int;

  explicit Assembler(Header header);

  // Instructions from here on come from this source position (line-table entry).
  Assembler& at(uint32_t file, uint32_t line, uint32_t column = 1);

  Assembler& emit(const Instruction& instruction);
  Assembler& op(Opcode opcode);  // an instruction without operands
  Assembler& rapid(const AxisValues& to, uint8_t flags = 0);
  Assembler& line(const AxisValues& to, double feed, uint8_t flags = 0);
  // SKIP (G31): the skip position, minus `origin`, goes to #first_variable.. (0: nowhere).
  Assembler& skip(const AxisValues& to, double feed, uint32_t first_variable,
                  const AxisValues& origin, uint8_t flags = kFlagExactStop);
  Assembler& arc(const AxisValues& to, uint8_t axis1, uint8_t axis2, double center1,
                 double center2, double feed, uint8_t flags, ArcPlane plane = ArcPlane::XY,
                 uint32_t turns = 0);
  Assembler& dwell(double amount, uint8_t flags = 0);
  Assembler& spindleSpeed(double rpm);
  Assembler& toolSelect(int64_t tool);
  Assembler& mCode(int64_t code);
  Assembler& refCheck(uint16_t mask, uint8_t reference, const AxisValues& position);
  Assembler& push(double value);
  Assembler& load(uint32_t variable);
  Assembler& store(uint32_t variable);

  Label newLabel();
  Assembler& bind(Label label);              // the label names the next instruction
  Assembler& jump(Opcode jump_opcode, Label label);  // JUMP or JUMP_IF_FALSE

  uint32_t offset() const { return static_cast<uint32_t>(program_.code.size()); }

  // Resolves labels (an unbound label jumps to offset 0xFFFFFFFF, which verify() rejects)
  // and returns the program with these strings and one unit at offset 0 named by string
  // `unit_name`.
  Program finish(std::vector<std::string> strings = {"", "test.nc"}, uint32_t unit_name = 1);

 private:
  Program program_;
  std::vector<int64_t> labels_;                        // bound offset or -1
  std::vector<std::pair<uint32_t, Label>> fixups_;     // jump offset, label
};

}  // namespace ncc::bytecode
