#pragma once
// Lines of one source, read one at a time: a file is streamed (never loaded whole), an
// in-memory buffer is walked in place. Lines end at LF; a CR before the LF is dropped, and
// so is a UTF-8 byte order mark at the start of the source.
//
// Every line has a byte offset (where its first byte is in the source, the BOM counted), so
// that a reader can come back to a line with seek(): Macro B jumps (GOTO, loops, subprogram
// returns) re-read text already read.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "ncc/support/source_manager.h"

namespace ncc::frontend {

class LineSource {
 public:
  LineSource(const SourceManager& sources, uint32_t file);
  // A file not registered with a SourceManager (the program library peeks at the first
  // blocks of the files of a folder without registering them all).
  explicit LineSource(const std::filesystem::path& path);
  // False when the source could not be opened.
  bool ok() const { return ok_; }
  // The next line into `line` (its capacity is reused); false at end of input. Throws
  // SourceReadError when reading the file fails.
  bool next(std::string& line);

  // Byte offset of the line last returned by next() (0 before the first).
  uint64_t lineOffset() const { return line_offset_; }
  // Byte offset of the line the next call to next() returns (the source's size at its end).
  uint64_t nextOffset() const { return next_offset_; }
  // Continues reading at `offset`, which must be the start of a line (a lineOffset() or
  // nextOffset() of this source). Offset 0 drops the byte order mark again.
  void seek(uint64_t offset);

 private:
  bool streamedLine(std::string& line);
  bool fill();

  static constexpr size_t kChunk = 64 * 1024;
  bool ok_ = false;
  const std::string* buffer_ = nullptr;
  std::ifstream stream_;
  std::vector<char> chunk_;  // read ahead from stream_: [chunk_pos_, chunk_end_) not yet used
  size_t chunk_pos_ = 0;
  size_t chunk_end_ = 0;
  bool stream_eof_ = false;
  std::filesystem::path path_;  // of the file streamed, for SourceReadError
  uint64_t line_offset_ = 0;
  uint64_t next_offset_ = 0;
};

}  // namespace ncc::frontend
