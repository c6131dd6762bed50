#pragma once
// Small hand-assembled programs shared by the bytecode tests.
#include <sstream>
#include <string>
#include <vector>

#include "ncc/bytecode/assembler.h"
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

inline std::vector<uint8_t> serialise(const bytecode::Program& program) {
  std::ostringstream out;
  bytecode::write(program, out);
  const std::string s = out.str();
  return {s.begin(), s.end()};
}

}  // namespace ncc::test
