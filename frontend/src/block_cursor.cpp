#include "block_cursor.h"

#include <algorithm>

namespace ncc::frontend {

size_t findSemicolon(std::string_view line, size_t from) {
  // Most lines have no ';' at all: one memchr says so without the character walk.
  if (line.find(';', from) == std::string_view::npos) return std::string_view::npos;
  bool in_comment = false;
  for (size_t i = from; i < line.size(); ++i) {
    const char c = line[i];
    if (in_comment) {
      in_comment = c != ')';
    } else if (c == '(') {
      in_comment = true;
    } else if (c == ';') {
      return i;
    }
  }
  return std::string_view::npos;
}

bool BlockCursor::next(Segment& segment, bool semicolon_ends_block) {
  if (!pending_) {
    if (!lines_.next(line_)) return false;
    ++line_number_;
    ++lines_read_;
    pos_ = 0;
    pending_ = true;
  }
  const std::string_view text(line_);
  const size_t semi = findSemicolon(text, pos_);
  segment.at = BlockPosition{lines_.lineOffset(), line_number_, static_cast<uint32_t>(pos_ + 1)};
  segment.annotation.reset();
  if (semi == std::string_view::npos) {
    segment.text = text.substr(pos_);
    pending_ = false;
  } else if (semicolon_ends_block) {
    segment.text = text.substr(pos_, semi - pos_);  // the rest of the line is the next block
    pos_ = semi + 1;
    pending_ = pos_ < text.size();
  } else {
    segment.text = text.substr(pos_, semi - pos_);  // ';' starts an annotation to end of line
    segment.annotation = text.substr(semi + 1);
    pending_ = false;
  }
  return true;
}

BlockPosition BlockCursor::position() const {
  if (pending_)
    return BlockPosition{lines_.lineOffset(), line_number_, static_cast<uint32_t>(pos_ + 1)};
  return BlockPosition{lines_.nextOffset(), line_number_ + 1, 1};
}

void BlockCursor::seek(BlockPosition p) {
  lines_.seek(p.offset);
  line_number_ = p.line - 1;
  pending_ = false;
  if (p.column <= 1) return;  // the line is read by the next call, as in straight reading
  // A block after a ';': read its line now and start there.
  if (!lines_.next(line_)) return;
  ++line_number_;
  ++lines_read_;
  pos_ = std::min<size_t>(p.column - 1, line_.size());
  pending_ = true;
}

}  // namespace ncc::frontend
