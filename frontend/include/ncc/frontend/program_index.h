#pragma once
// The N labels and O numbers of one file, found by scanning its text (not parsing it), for
// Macro B jumps and subprogram calls. A block "starts with N n" when, after blanks, an
// optional block skip '/', '/1'..'/9' and ( ) comments, its first word is N n (n10 and N 10
// too, as the parsers read them); "starts with O n" likewise with `O n` or `:n`.
//
// Nothing is indexed up front (CAM programs carry an N on every line of millions): a lookup
// scans the file from where the control would start searching and stops at the first match,
// and its answer is cached, so a loop that jumps to the same label ten thousand times scans
// once. The O blocks (few) are found by one scan of the whole file, on the first lookup that
// needs them. A file is never held in memory; a scan opens it, reads, and closes it.
//
// The program's text ends at the end of the record: the '%' block after the first block that
// is not blank (text after it is never executed, see the driver), or the end of the file.
// Nothing after it is found.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ncc/frontend/block_position.h"
#include "ncc/frontend/block_reader.h"
#include "ncc/support/source_manager.h"

namespace ncc::frontend {

enum class SequenceSearch : uint8_t {
  ForwardThenFromStart,  // GOTO on FANUC: after the current block to the end, then from the start
  FromStart,             // M99 P n, M98 restarts: from the start
  Forward,               // DIN GOTOF: after the current block to the end
  Backward,              // DIN GOTOB: the nearest before, from the current block (included) back
};

// A range of blocks [first, end): a block is in it when first <= its position < end.
using BlockRange = std::pair<BlockPosition, BlockPosition>;

class ProgramIndex {
 public:
  // `sources` must outlive the index. `options`: the ';' rule of the reader that will seek to
  // the positions returned (a DIN initial language reads ';' as an annotation).
  ProgramIndex(const SourceManager& sources, uint32_t file, ReaderOptions options);

  // The first block starting with N n in search order, nullopt if none.
  // `from` is the block the search starts after (the GOTO block, or the M98 block).
  // ForwardThenFromStart: the blocks after `from` to the end, then from the start up to and
  // including `from`. FromStart: from the start to the end.
  // `within`: only the blocks of this range (a subprogram's own text: ProgramLibrary::find's
  // start to programEnd(start)); "start" and "end" above are then the range's.
  std::optional<BlockPosition> findSequence(int64_t n, BlockPosition from, SequenceSearch order,
                                            std::optional<BlockRange> within = std::nullopt);
  // The same for the block that carries DIN jump label `label` (upper case): `NAME:` after the
  // block's skip mark and number (block_start.h, blockLabel).
  std::optional<BlockPosition> findLabel(std::string_view label, BlockPosition from,
                                         SequenceSearch order,
                                         std::optional<BlockRange> within = std::nullopt);

  // The block that starts program O n (`O1234` or `:1234` as the first word of a block),
  // the first one in the file; nullopt if none.
  std::optional<BlockPosition> findProgram(int64_t n);

  // The end of the program starting at `start`: the next block starting with an O number
  // after `start`, else the end of the record: the closing '%' block if there is one, else
  // the end of the file (the position a reader has at its end: offset = size).
  BlockPosition programEnd(BlockPosition start);

  // The program number of the file's first block that is not blank, a comment or '%', when
  // that block starts with O n or :n. Reads only up to that block.
  std::optional<int64_t> firstProgramNumber();

  // firstProgramNumber() of a file not registered with a SourceManager (the program library
  // looks at every file of a folder); nullopt also when it cannot be read.
  static std::optional<int64_t> firstProgramNumberOf(const std::filesystem::path& path,
                                                     ReaderOptions options);

  // The blocks of the record that start with N n or O n, in file order, and where the record
  // ends (programEnd's answer after the last program): what the lookups above answer from, for
  // a copy of the file kept as parsed blocks (the block store, eval/block_store.h). One scan,
  // not kept.
  struct Label {
    bool program;  // O n (or :n); else N n
    int64_t number;
    BlockPosition at;
  };
  std::vector<Label> labels();
  BlockPosition recordEnd();

  uint32_t file() const { return file_; }

  // Counters for tests: how many scans read the file, and how many lines they read in all.
  struct Stats {
    uint64_t scans = 0;
    uint64_t lines = 0;
  };
  const Stats& stats() const { return stats_; }

 private:
  // A block that starts with N n, or (label not empty) carries the label.
  struct Target {
    int64_t n = 0;
    std::string_view label;
  };
  std::optional<BlockPosition> find(Target target, BlockPosition from, SequenceSearch order,
                                    std::optional<BlockRange> within);
  struct Key {
    int64_t n;
    std::string label;
    uint64_t from_offset;
    uint32_t from_column;
    SequenceSearch order;
    bool has_range;
    BlockPosition first, end;
    friend bool operator==(const Key&, const Key&) = default;
  };
  struct KeyHash {
    size_t operator()(const Key& k) const;
  };
  struct ProgramBlock {
    int64_t number;
    BlockPosition at;
  };

  // Reads from `start` for the first block starting with N n that comes after `after`, up to
  // and including `through`, before `end` (each nullopt: no such limit) and before the end
  // of the record.
  // `last`: the last match before `through`, not the first (a backward search).
  std::optional<BlockPosition> scanFor(Target target, BlockPosition start,
                                       std::optional<BlockPosition> after,
                                       std::optional<BlockPosition> through,
                                       std::optional<BlockPosition> end, bool last = false);
  void scanPrograms();
  // The first block that is not blank (where a '%' stops being the opening one), and the
  // file's first program number; read once.
  void scanHead();

  // The language of the text after segment `text` read in `now` (G290 / G291 where the dialect
  // has them): the positions the index returns say their language as the reader's do.
  Language languageAfterSegment(std::string_view text, Language now) const;

  const SourceManager& sources_;
  uint32_t file_;
  bool semicolon_ends_block_;
  Language initial_language_;
  bool language_switch_;
  Stats stats_;

  std::unordered_map<Key, std::optional<BlockPosition>, KeyHash> sequences_;

  bool head_scanned_ = false;
  std::optional<BlockPosition> first_content_;  // nullopt: the file has no such block
  std::optional<int64_t> first_program_number_;

  bool programs_scanned_ = false;
  std::vector<ProgramBlock> programs_;  // in file order
  BlockPosition record_end_;            // the closing '%' block, or the end of the file
};

}  // namespace ncc::frontend
