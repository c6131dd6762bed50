#pragma once
// The block store: the parsed blocks of every program a run may reach, carried in the compiled
// bytecode so that the VM can evaluate and lower blocks itself when they wait for a value known
// only at run time (the G31 skip position, interface signals). It holds what the compiler's
// SourceProgramStore reads from source files, already parsed, plus the answers the program
// folder gave at compile time; StoredProgramStore serves it to the evaluator with the same
// semantics, without text or parser. The compiler builds it in driver/src/block_store_builder.h.
//
// Encoding (encodeBlockStore): little-endian, "NCBS" then a u16 version (3). Unsigned integers
// are LEB128 varints, signed ones zigzag varints, strings a varint length and bytes; a number
// is written as m / 10^k (one varint: zigzag(m) << 4 | k) when that gives its double back bit
// for bit, as every decimal literal of a program does, else as its IEEE bit pattern (-0.0, NaN
// payloads, computed values round-trip exactly). The syntax tree is written by its schema
// (ast::Schema): a node is a mask of the members that differ from their default, then those
// members. Block positions are delta-coded within a file and source locations relative to the
// node or list item before them, which keeps a CAM program's store near the size of its text.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ncc/eval/loop_limits.h"
#include "ncc/eval/program_store.h"
#include "ncc/frontend/ast.h"
#include "ncc/frontend/block_position.h"
#include "ncc/frontend/language.h"

namespace ncc::eval {

struct StoredBlock {
  // How the block's text starts, as the compiler's ProgramIndex reads it (not the parser): only
  // a block whose first word is N n is a GOTO target, only one whose first word is O n (or :n)
  // starts a program. The parser also accepts an N or O later in the block (`G1 N10`), so this
  // cannot be told from `block` alone.
  enum class Start : uint8_t { Other, Sequence, Program };

  frontend::BlockPosition position;  // as the BlockReader reported it (BlockCursor::lastPoint)
  Start start = Start::Other;        // Sequence needs block.sequence, Program block.program_number
  ast::Block block;
};

struct StoredFile {
  uint32_t id = 0;    // the compiler's source file id (SourceLocation::file of its blocks)
  std::string name;   // file name without folders ("O0012.nc")
  // Every block the reader returned up to the end of the record, in file order (strictly
  // increasing positions): the closing '%' block, when there is one, is the last; text after
  // it is not part of the program and is not stored.
  std::vector<StoredBlock> blocks;
  // The end of the record: the closing '%' block, or the end of the file (the reader's position
  // there: offset = size). ProgramIndex::programEnd's answer for the last program.
  frontend::BlockPosition record_end;
};

struct BlockStore {
  uint32_t main_file = 0;           // id of the main program's file (one of `files`)
  uint64_t ahead_blocks = 0;        // blocks the compiler already prepared ahead of time
  LoopLimits limits;                // --max-idle-blocks, --max-back-jumps
  std::map<int64_t, double> saved_variables;  // --vars values loaded at compile time
  std::vector<StoredFile> files;                // ids unique
  // Programs of the program folder, resolved at compile time as ProgramLibrary steps 2-3 do
  // (by file name, then by first O number): number -> its O block, or the start of a file
  // found by name without one. Every point names a file of `files`.
  std::map<int64_t, ProgramPoint> folder_programs;
  // Programs called by name (code macros "M6_MAKRO"): the name as the evaluator asks -> start.
  std::map<std::string, ProgramPoint> named_programs;
};

// Expressions deeper than this are refused by the decoder (it recurses); the builder reports a
// deeper block instead of storing it.
inline constexpr int kMaxStoredNesting = 1024;
// The nesting depth of a block's expressions and statements (1 for a literal).
int blockNesting(const ast::Block& block);

std::vector<uint8_t> encodeBlockStore(const BlockStore& store);
// nullopt with `error` set on malformed input: truncated, a bad magic or version, an unknown
// enum value, a count beyond the remaining bytes, nesting deeper than kMaxStoredNesting,
// positions out of order, a point naming a file not stored, trailing bytes. Never allocates
// more than the input's size allows.
std::optional<BlockStore> decodeBlockStore(std::span<const uint8_t> bytes, std::string& error);

// A ProgramStore over a block store (the VM's block source), answering as SourceProgramStore:
// findProgram: an O block of the calling file, then folder_programs; findProgramNamed:
// named_programs; findSequence and programEnd: over the stored blocks' Start marks with
// ProgramIndex's search orders and [begin, end) bounds; seek: to the first block at or after
// the position. A program the compile never resolved in the folder (a call whose number is
// computed) is not found here even if the folder held it: the store has only what the builder
// put in.
// A stored block was parsed in the language its position names (G290/G291 switch the reader),
// so the blocks of a file that switches language are served as they were read.
class StoredProgramStore final : public ProgramStore {
 public:
  // `store` must outlive this object and every cursor it opens; cursors share its blocks.
  explicit StoredProgramStore(const BlockStore& store);
  ~StoredProgramStore() override;

  // A cursor at the start of `file`; a file not stored gives a cursor with no blocks.
  std::unique_ptr<BlockCursor> open(uint32_t file) override;
  std::optional<ProgramPoint> findProgram(int64_t number, uint32_t calling_file) override;
  std::optional<ProgramPoint> findProgramNamed(std::string_view name) override;
  std::optional<ProgramPoint> findSequence(int64_t n, const ProgramPoint& from,
                                           SequenceSearch order, const ProgramPoint& begin,
                                           const ProgramPoint& end) override;
  std::optional<ProgramPoint> findLabel(std::string_view label, const ProgramPoint& from,
                                        SequenceSearch order, const ProgramPoint& begin,
                                        const ProgramPoint& end) override;
  ProgramPoint programEnd(const ProgramPoint& start) override;

 private:
  struct FileIndex;
  class Cursor;
  FileIndex* fileIndex(uint32_t file);

  const BlockStore& store_;
  std::map<uint32_t, std::unique_ptr<FileIndex>> files_;
};

}  // namespace ncc::eval
