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
