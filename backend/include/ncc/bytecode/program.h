#pragma once
// A loaded bytecode file: header, string pool, code, line table and program units. Produced
// by the loader (loader.h), checked by the verifier (verifier.h), run by the VM.
//
// The code and the line table grow with the program (about 50 bytes a block); they are held
// either in the vectors below or, for a paged program (loadPaged), left in the file and read
// through a bounded window (code_view.h), so that running a long program takes no more memory
// than running a short one. Header, strings and units are always in memory (they are small).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ncc/bytecode/format.h"
#include "ncc/bytecode/program_file.h"
#include "ncc/machine/dialect.h"
#include "ncc/machine/machine_config.h"

namespace ncc::bytecode {

struct AxisInfo {
  std::string name;  // "X", "Y", ...
  AxisKind kind = AxisKind::Linear;
  friend bool operator==(const AxisInfo&, const AxisInfo&) = default;
};

struct Header {
  uint16_t version_major = kVersionMajor;
  uint16_t version_minor = kVersionMinor;
  Dialect dialect = Dialect::FanucM;
  uint64_t config_hash = 0;             // MachineConfig::configHash() it was compiled for
  uint32_t variable_count = kDefaultVariableCount;
  std::vector<AxisInfo> axes;           // configured axes, in machine order
  friend bool operator==(const Header&, const Header&) = default;
};

// Source position of the code from `offset` up to the next entry's offset.
struct LineEntry {
  uint32_t offset = 0;  // code offset of an instruction start
  uint32_t file = 0;    // index into the string pool (the compiler's source file id)
  uint32_t line = 0;
  uint32_t column = 0;
  friend bool operator==(const LineEntry&, const LineEntry&) = default;
};

struct Unit {
  uint32_t entry = 0;  // code offset where the unit starts
  uint32_t name = 0;   // string pool index of its name
  friend bool operator==(const Unit&, const Unit&) = default;
};

// A variable the program names (2.3): `--emit=vars` prints it by its name, not as #number.
struct VariableName {
  uint32_t number = 0;
  uint32_t name = 0;  // string pool index
  friend bool operator==(const VariableName&, const VariableName&) = default;
};

// Where a paged program's code and line table are in its file.
struct PagedSections {
  std::shared_ptr<const ProgramFile> file;
  uint64_t code_offset = 0;
  uint32_t code_size = 0;
  uint64_t lines_offset = 0;
  uint32_t line_count = 0;  // entries of kLineEntrySize bytes
};

struct Program {
  Header header;
  std::vector<std::string> strings;  // index 0 is "" (no file)
  std::vector<uint8_t> code;         // empty when paged
  std::vector<LineEntry> lines;      // sorted by offset; empty when paged
  std::vector<Unit> units;           // units[0] is the main program
  std::vector<VariableName> variable_names;  // by number, ascending (2.3; empty before)
  std::optional<PagedSections> paged;  // set: code and lines are read from the file
  // The block store (2.2): every block the run may still prepare, as the compiler parsed them
  // (eval/block_store.h), for PREPARE. Empty when the compiler prepared the whole program.
  std::vector<uint8_t> blocks;

  int axisCount() const { return static_cast<int>(header.axes.size()); }
  uint32_t codeSize() const {
    return paged ? paged->code_size : static_cast<uint32_t>(code.size());
  }
  // In-memory programs only (the disassembler's): a paged program's entries are read through
  // CodeView (code_view.h).
  // The entry covering `offset` (the last one at or before it), or nullptr.
  const LineEntry* lineFor(uint32_t offset) const;
  // The same, starting from entry `hint` (updated to the entry found, where there is one):
  // O(1) when offsets are asked in order, as an executor asks them.
  const LineEntry* lineFor(uint32_t offset, std::size_t& hint) const;
};

}  // namespace ncc::bytecode
