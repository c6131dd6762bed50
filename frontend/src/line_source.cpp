#include "line_source.h"

#include <cerrno>
#include <cstring>

#include "ncc/support/source_read_error.h"

namespace ncc::frontend {

LineSource::LineSource(const SourceManager& sources, uint32_t file) {
  buffer_ = sources.buffer(file);
  if (buffer_) {
    ok_ = true;
    return;
  }
  if (file == 0 || file > sources.fileCount()) return;
  path_ = sources.path(file);
  stream_.open(path_, std::ios::binary);
  ok_ = stream_.is_open();
}

LineSource::LineSource(const std::filesystem::path& path) : path_(path) {
  stream_.open(path, std::ios::binary);
  ok_ = stream_.is_open();
}

bool LineSource::next(std::string& line) {
  if (!ok_) return false;
  line_offset_ = next_offset_;
  if (buffer_) {
    if (next_offset_ >= buffer_->size()) return false;
    const size_t start = static_cast<size_t>(next_offset_);
    size_t end = buffer_->find('\n', start);
    if (end == std::string::npos) end = buffer_->size();
    line.assign(*buffer_, start, end - start);
    next_offset_ = end < buffer_->size() ? end + 1 : end;
  } else {
    errno = 0;
    if (!std::getline(stream_, line)) {
      // A read error is not the end of the file (badbit, not eofbit).
      if (stream_.bad()) throw SourceReadError(path_, errno ? std::strerror(errno) : "read error");
      return false;
    }
    // The offset is counted, not asked of the stream: tellg() costs a system call per line.
    // getline() sets eof only when the last line has no LF.
    next_offset_ += line.size() + (stream_.eof() ? 0 : 1);
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  // A UTF-8 byte order mark some editors write is not part of the first line.
  if (line_offset_ == 0 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
  return true;
}

void LineSource::seek(uint64_t offset) {
  if (!ok_) return;
  line_offset_ = next_offset_ = offset;
  if (buffer_) return;
  stream_.clear();
  stream_.seekg(static_cast<std::streamoff>(offset));
}

}  // namespace ncc::frontend
