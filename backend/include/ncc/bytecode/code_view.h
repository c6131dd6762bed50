#pragma once
// Reads a program's code and line table wherever they are: in the Program's vectors, or, for a
// paged program (program.h), in its file through two bounded windows (one for the code, one
// for the line table) of kPageSize bytes each, refilled on demand. The verifier and the
// executor read through it, so a paged run's memory does not grow with the program.
//
// Forward reading (the executor's and the verifier's usual order) refills a window once per
// page; a jump, a call or a line lookup inside the current window costs nothing more.
// Construction sizes everything; the reads allocate nothing and never throw (a read error
// looks like a truncated instruction or a missing line entry).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "ncc/bytecode/instruction.h"
#include "ncc/bytecode/program.h"

namespace ncc::bytecode {

class CodeView {
 public:
  static constexpr std::size_t kPageSize = 256 * 1024;

  // `program` must outlive the view.
  explicit CodeView(const Program& program);

  uint32_t codeSize() const { return code_size_; }
  // Decodes the instruction at `offset`, exactly like decode() over the whole code.
  DecodeStatus decode(uint32_t offset, int axis_count, Instruction& out, uint32_t& size);
  // The code byte at `offset` (< codeSize()), 0 when it cannot be read.
  uint8_t byteAt(uint32_t offset);

  std::size_t lineCount() const { return line_count_; }
  // Line entry `index` (< lineCount()); nullopt only on a read error.
  std::optional<LineEntry> line(std::size_t index);
  // The entry covering `offset` (the last one at or before it), starting from entry `hint`
  // (updated to the entry found): O(1) when offsets are asked in order.
  std::optional<LineEntry> lineFor(uint32_t offset, std::size_t& hint);

 private:
  // Bytes [begin, begin + count) of a file section of `limit` bytes at `base`; fewer at the
  // section's end. Refills the window when they are not all in it.
  class Window {
   public:
    Window() = default;
    Window(const ProgramFile* file, uint64_t base, uint64_t limit);
    std::span<const uint8_t> bytes(uint64_t begin, std::size_t count);
    // Whether [begin, begin + count) is in the window now (no refill).
    bool holds(uint64_t begin, std::size_t count) const {
      return begin >= start_ && begin + count <= start_ + filled_;
    }
    uint64_t start() const { return start_; }
    std::size_t filled() const { return filled_; }

   private:
    const ProgramFile* file_ = nullptr;
    uint64_t base_ = 0, limit_ = 0;
    std::vector<uint8_t> buffer_;
    uint64_t start_ = 0;  // section offset of buffer_[0]
    std::size_t filled_ = 0;
  };

  std::optional<std::size_t> searchLine(uint32_t offset);

  const Program& program_;
  const uint32_t code_size_;
  const std::size_t line_count_;
  Window code_window_, line_window_;  // paged programs only
};

}  // namespace ncc::bytecode
