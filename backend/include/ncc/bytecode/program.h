#pragma once
// A loaded bytecode file: header, string pool, code, line table and program units. Produced
// by the loader (loader.h), checked by the verifier (verifier.h), run by the VM.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ncc/bytecode/format.h"
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

struct Program {
  Header header;
  std::vector<std::string> strings;  // index 0 is "" (no file)
  std::vector<uint8_t> code;
  std::vector<LineEntry> lines;      // sorted by offset
  std::vector<Unit> units;           // units[0] is the main program

  int axisCount() const { return static_cast<int>(header.axes.size()); }
  // The entry covering `offset` (the last one at or before it), or nullptr.
  const LineEntry* lineFor(uint32_t offset) const;
  // The same, starting from entry `hint` (updated to the entry found, where there is one):
  // O(1) when offsets are asked in order, as an executor asks them.
  const LineEntry* lineFor(uint32_t offset, std::size_t& hint) const;
};

}  // namespace ncc::bytecode
