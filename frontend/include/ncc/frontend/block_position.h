#pragma once
// Where a block starts in its source: what Macro B control flow (GOTO, WHILE loops, subprogram
// calls and returns) needs to come back to a block already read or to jump ahead. A position
// says which language its text is read in, so that coming back to a block reads it as it was
// read the first time (a GOTO back across a G290).
#include <cstdint>

#include "ncc/frontend/language.h"

namespace ncc::frontend {

struct BlockPosition {
  uint64_t offset = 0;  // byte offset of the block's physical line (a BOM counts)
  uint32_t line = 1;    // 1-based line number
  // 1-based column where the block's text starts within the line: 1, or just after the ';'
  // that ended the previous block on the same line. Blanks before the first word are part of
  // the block, so this is not always the column of the block's first word (Block::loc).
  uint32_t column = 1;
  // The language the text from here is read in: the reader's when it stood here, switched by
  // the G290 / G291 blocks before it in text order (block_reader.h).
  Language language = Language::Iso;
  friend bool operator==(const BlockPosition&, const BlockPosition&) = default;
};

// Text order: by offset, then column (the line follows from the offset).
inline bool operator<(const BlockPosition& a, const BlockPosition& b) {
  return a.offset != b.offset ? a.offset < b.offset : a.column < b.column;
}
inline bool operator<=(const BlockPosition& a, const BlockPosition& b) { return !(b < a); }

// The language the text from `p` is read in, in a file that starts in `initial`: the start of
// a file is read in the file's first language whatever position named it (a caller that only
// knows "the file's start" writes BlockPosition{}).
inline Language languageAt(const BlockPosition& p, Language initial) {
  return p.offset == 0 && p.column <= 1 ? initial : p.language;
}

}  // namespace ncc::frontend
