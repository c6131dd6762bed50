#pragma once
// The blocks of text of one source, not parsed, each with its BlockPosition: lines are cut at
// ';' when the caller says ';' ends a block, else ';' starts an annotation to the end of the
// line. BlockReader and ProgramIndex both walk a source through this class, so the positions
// one returns are the positions the other seeks to.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "line_source.h"
#include "ncc/frontend/block_position.h"

namespace ncc::frontend {

// The first ';' at or after `from` that is not inside a ( ) comment, or npos.
size_t findSemicolon(std::string_view line, size_t from);

class BlockCursor {
 public:
  BlockCursor(const SourceManager& sources, uint32_t file) : lines_(sources, file) {}
  explicit BlockCursor(const std::filesystem::path& path) : lines_(path) {}

  bool ok() const { return lines_.ok(); }

  struct Segment {
    std::string_view text;  // without the ';' that ended it; valid until the next call
    std::optional<std::string_view> annotation;  // after a ';' that does not end the block
    BlockPosition at;
  };
  // The next block of text (possibly blank); false at end of input.
  bool next(Segment& segment, bool semicolon_ends_block);

  // Where the next segment starts; at the end of input, the offset is the source's size.
  BlockPosition position() const;
  // Continues at `p` (a position of this source from this class).
  void seek(BlockPosition p);

  uint64_t linesRead() const { return lines_read_; }

 private:
  LineSource lines_;
  std::string line_;  // the current physical line
  uint32_t line_number_ = 0;
  size_t pos_ = 0;        // where the next block of `line_` starts
  bool pending_ = false;  // `line_` has text left to read
  uint64_t lines_read_ = 0;
};

}  // namespace ncc::frontend
