#pragma once
// Small hand-assembled programs shared by the bytecode tests.
#include <sstream>
#include <string>
#include <vector>

#include <cstdio>
#include <optional>
#include <unistd.h>

#include "ncc/bytecode/assembler.h"
#include "ncc/bytecode/loader.h"
#include "ncc/bytecode/program_file.h"
#include "ncc/bytecode/writer.h"

namespace ncc::test {

inline bytecode::Header xyzHeader() {
  bytecode::Header header;
  header.axes = {{"X", AxisKind::Linear}, {"Y", AxisKind::Linear}, {"Z", AxisKind::Linear}};
  return header;
}

// RAPID, LINE, END with a line table: a valid three-axis program.
inline bytecode::Program smallProgram() {
  bytecode::Assembler a(xyzHeader());
  a.at(1, 1).rapid({1.0, 2.0, 3.0});
  a.at(1, 2).line({4.0, 5.0, 6.0}, 100.0);
  a.at(1, 3).op(bytecode::Opcode::End);
  return a.finish();
}

// A valid program with every opcode of the format and every flag (disassembly golden
// every_opcode.dis, opcode table tests).
inline bytecode::Program everyOpcodeProgram() {
  using bytecode::Opcode;
  bytecode::Assembler a(xyzHeader());
  const bytecode::Assembler::Label skip = a.newLabel(), over = a.newLabel();
  a.at(1, 1).push(1.5).op(Opcode::PushVacant).op(Opcode::Add);
  for (Opcode op : {Opcode::Sub, Opcode::Mul, Opcode::Div}) a.push(-2.25).op(op);
  a.op(Opcode::Neg).store(100);
  a.at(1, 2).load(100).push(0.0).op(Opcode::CmpEq).jump(Opcode::JumpIfFalse, skip);
  for (Opcode op : {Opcode::CmpNe, Opcode::CmpLt, Opcode::CmpLe, Opcode::CmpGt, Opcode::CmpGe})
    a.load(100).push(1e-7).op(op).op(Opcode::Pop);
  a.bind(skip).jump(Opcode::Jump, over);
  a.bind(over).at(1, 3).toolSelect(12).op(Opcode::ToolChange).spindleSpeed(2500.5);
  a.op(Opcode::SpindleCW).op(Opcode::SpindleCCW).op(Opcode::SpindleStop);
  a.op(Opcode::SpindleOrient).op(Opcode::CoolantOn).op(Opcode::CoolantOff).mCode(99999999);
  a.at(1, 4).rapid({1.0, -2.0, 3.5});
  a.rapid({0.0, 0.0, 0.0}, bytecode::kFlagPerAxis | bytecode::kFlagExactStop);
  a.at(1, 5).line({10.0, 0.0, -1.0}, 0.25,
                  bytecode::kFlagFeedPerRev | bytecode::kFlagExactStop |
                      bytecode::kFlagFixedOverride);
  a.at(1, 6).arc({20.0, 0.0, -1.0}, 0, 1, 15.0, 0.0, 300.0, bytecode::kFlagClockwise);
  a.arc({20.0, 0.0, -3.0}, 2, 0, -2.0, 15.0, 0.5,
        bytecode::kFlagFeedPerRev | bytecode::kFlagExactStop | bytecode::kFlagFixedOverride,
        bytecode::ArcPlane::ZX, 3);
  a.arc({20.0, 0.0, -3.0}, 1, 2, 0.0, -3.0, 100.0, 0, bytecode::ArcPlane::YZ);
  a.at(1, 7).dwell(2.5).dwell(3.0, bytecode::kFlagRevolutions);
  a.at(1, 8).refCheck(0b101, 2, {20.0, 0.0, -3.0});
  a.op(Opcode::ProgramStop).op(Opcode::OptionalStop);
  a.at(1, 10).skip({20.0, 0.0, -50.0}, 100.0, 5061, {10.0, 0.0, -5.0});
  a.skip({20.0, 0.0, -60.0}, 0.5, 0, {0.0, 0.0, 0.0},
         bytecode::kFlagExactStop | bytecode::kFlagFeedPerRev | bytecode::kFlagFixedOverride |
             bytecode::kFlagInch);
  a.at(1, 9).op(Opcode::ProgramEnd).op(Opcode::ProgramEndRewind).op(Opcode::Prepare);
  a.op(Opcode::End);
  bytecode::Program program = a.finish();
  program.blocks = {'N', 'C', 'B', 'S'};  // PREPARE needs a block store (not decoded here)
  return program;
}

inline std::vector<uint8_t> serialise(const bytecode::Program& program) {
  std::ostringstream out;
  bytecode::write(program, out);
  const std::string s = out.str();
  return {s.begin(), s.end()};
}

// The same program paged (loader.h, loadPaged): written to an unlinked temporary file and
// loaded with its code and line table left in it. nullopt when the writer or the loader
// refuses it (a program only the verifier would see in memory).
inline std::optional<bytecode::Program> paged(const bytecode::Program& program) {
  const std::vector<uint8_t> bytes = serialise(program);
  bytecode::Program loaded;
  if (bytes.empty() || bytecode::load(bytes, loaded)) return std::nullopt;
  char name[] = "/tmp/ncc-paged-test-XXXXXX";
  const int fd = mkstemp(name);
  if (fd < 0) return std::nullopt;
  unlink(name);
  std::shared_ptr<const bytecode::ProgramFile> file = bytecode::ProgramFile::adopt(fd);
  if (::write(fd, bytes.data(), bytes.size()) != static_cast<ssize_t>(bytes.size()))
    return std::nullopt;
  if (bytecode::loadPaged(file, loaded)) return std::nullopt;
  return loaded;
}

}  // namespace ncc::test
