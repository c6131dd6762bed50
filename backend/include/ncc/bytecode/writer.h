#pragma once
// Writes a bytecode file to a seekable stream without holding the program in memory: the
// header is written first with an empty section table, code goes to the stream through a
// fixed-size buffer, the line table is spooled to a temporary file, and finish() appends line
// table, string pool and units, then seeks back to patch the section table and the checksum
// (checksum.h), which is hashed as the bytes go out. Code already written is therefore never
// rewritten. Memory use is independent of program length (the string pool and units are small
// and supplied at the end).
#include <array>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "ncc/bytecode/checksum.h"
#include "ncc/bytecode/error.h"
#include "ncc/bytecode/instruction.h"
#include "ncc/bytecode/program.h"

namespace ncc::bytecode {

class StreamWriter {
 public:
  // Writes the header (its section table still zero). `header.axes` fixes the axis count.
  StreamWriter(std::ostream& out, Header header);
  ~StreamWriter();
  StreamWriter(const StreamWriter&) = delete;
  StreamWriter& operator=(const StreamWriter&) = delete;

  // Code offset the next instruction will have.
  uint32_t offset() const { return code_size_; }
  int axisCount() const { return static_cast<int>(header_.axes.size()); }

  // Appends one instruction; returns its code offset.
  uint32_t emit(const Instruction& instruction);
  // Appends raw, already encoded code bytes (re-encoding a loaded program).
  void emitRaw(const uint8_t* data, size_t size);
  // Records that code from offset() on comes from this source position. A repeat of the last
  // position adds nothing; a second entry at the same offset replaces the first.
  void addLine(uint32_t file, uint32_t line, uint32_t column);

  // Appends line table, strings and units and patches the section table. The stream is left
  // positioned at the end of the file. Returns the first error (also kept in error()).
  // `blocks`: the block store (2.2), appended after the units; empty for none. `names`: the
  // variables the program names (2.3), by number ascending, their names in `strings`; the
  // header's variable count grows to hold them.
  std::optional<Error> finish(const std::vector<std::string>& strings,
                              const std::vector<Unit>& units,
                              std::span<const uint8_t> blocks = {},
                              const std::vector<VariableName>& names = {});

  const std::optional<Error>& error() const { return error_; }

 private:
  void fail(std::string code, std::string message);
  void writeBytes(const uint8_t* data, size_t size);
  void writeHashed(const uint8_t* data, size_t size);  // bytes after the fixed header
  void flushCode();  // the buffered code bytes to the stream
  bool codeFits(size_t size);  // false (NCC7010 reported) if `size` more code bytes do not fit
  void spoolLine(const LineEntry& entry, bool replace_last);

  std::ostream& out_;
  Header header_;
  std::ostream::pos_type start_;  // stream position of the header
  uint32_t header_size_ = 0;
  uint32_t code_size_ = 0;
  // Code bytes not yet written: one stream write per buffer, not per instruction.
  std::array<uint8_t, 1 << 16> code_buffer_;
  size_t code_buffered_ = 0;
  std::FILE* spool_ = nullptr;      // line table entries, kLineEntrySize bytes each
  std::string memory_spool_;        // used only if no temporary file can be created
  uint64_t line_count_ = 0;
  std::optional<LineEntry> last_line_;
  Fnv1a64 hash_;                    // checksum of every byte after the fixed header so far
  bool finished_ = false;
  std::optional<Error> error_;
};

// Serialises a whole in-memory program (tests, tools): the same bytes as the streaming path.
std::optional<Error> write(const Program& program, std::ostream& out);

}  // namespace ncc::bytecode
