#pragma once
// Where the evaluator's blocks come from: a stack of cursors over the program's files, which
// can seek back (GOTO, WHILE, M99 P) and find other programs (M98 P, G65 P). The compiler
// reads source files (driver/src/source_program_store.cpp); nothing here parses text.
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>

#include "ncc/eval/macro_rules.h"
#include "ncc/frontend/ast.h"
#include "ncc/frontend/block_position.h"
#include "ncc/frontend/language.h"

namespace ncc::eval {

// A block's place: its file and where it starts there.
struct ProgramPoint {
  uint32_t file = 0;
  frontend::BlockPosition position;
  friend bool operator==(const ProgramPoint&, const ProgramPoint&) = default;
};

// Reads the blocks of one file from any point.
class BlockCursor {
 public:
  virtual ~BlockCursor() = default;
  // The next block; nullptr at the end of the file. The block is the cursor's: it stays valid
  // until the next call of next() or seek() (a replayed loop body is not copied each turn).
  // Unreadable blocks are reported and skipped (rejectedBlocks() counts them).
  virtual const ast::Block* next() = 0;
  // Where the block last returned by next() starts.
  virtual ProgramPoint lastPoint() const = 0;
  // Continues at `point` (in this cursor's file).
  virtual void seek(const ProgramPoint& point) = 0;
  virtual uint64_t rejectedBlocks() const = 0;
  virtual uint32_t file() const = 0;
};

class ProgramStore {
 public:
  virtual ~ProgramStore() = default;
  // A cursor at the start of `file`.
  virtual std::unique_ptr<BlockCursor> open(uint32_t file) = 0;
  // Program O number: in the calling file first, then the program folder. The point is the
  // program's O block (or the start of a file found by name).
  virtual std::optional<ProgramPoint> findProgram(int64_t number, uint32_t calling_file) = 0;
  // A program called by name (a code macro of the machine file: M6 -> "M6_MAKRO"): a file of
  // the program folder with that name, as given or with the extension of a program file.
  virtual std::optional<ProgramPoint> findProgramNamed(std::string_view name) = 0;
  // The block starting with N n in search order from `from`, within [begin, end) of its file.
  virtual std::optional<ProgramPoint> findSequence(int64_t n, const ProgramPoint& from,
                                                   SequenceSearch order,
                                                   const ProgramPoint& begin,
                                                   const ProgramPoint& end) = 0;
  // The same for the block carrying DIN jump label `label` (upper case, `MA1:`).
  virtual std::optional<ProgramPoint> findLabel(std::string_view label, const ProgramPoint& from,
                                                SequenceSearch order, const ProgramPoint& begin,
                                                const ProgramPoint& end) = 0;
  // The end of the program that starts at `start`: the next block with an O number, or the
  // end of the file.
  virtual ProgramPoint programEnd(const ProgramPoint& start) = 0;
};

}  // namespace ncc::eval
