#pragma once
// Lines of one source, read one at a time: a file is streamed (never loaded whole), an
// in-memory buffer is walked in place. Lines end at LF; a CR before the LF is dropped, and
// so is a UTF-8 byte order mark at the start of the source.
#include <fstream>
#include <string>
#include <string_view>

#include "ncc/support/source_manager.h"

namespace ncc::frontend {

class LineSource {
 public:
  LineSource(const SourceManager& sources, uint32_t file);
  // False when the source could not be opened.
  bool ok() const { return ok_; }
  // The next line into `line` (its capacity is reused); false at end of input.
  bool next(std::string& line);

 private:
  bool ok_ = false;
  bool first_line_ = true;
  const std::string* buffer_ = nullptr;
  size_t offset_ = 0;
  std::ifstream stream_;
};

}  // namespace ncc::frontend
