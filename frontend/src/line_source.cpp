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
    if (!streamedLine(line)) return false;
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  // A UTF-8 byte order mark some editors write is not part of the first line.
  if (line_offset_ == 0 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
  return true;
}

// The line up to the next LF from the chunk, reading chunks as needed: one memchr per line
// rather than getline's per-character stream calls. The offset is counted, not asked of the
// stream (tellg() costs a system call).
bool LineSource::streamedLine(std::string& line) {
  line.clear();
  bool read_any = false;
  for (;;) {
    if (chunk_pos_ == chunk_end_ && !fill()) return read_any;  // a last line without LF
    read_any = true;
    const char* from = chunk_.data() + chunk_pos_;
    const size_t n = chunk_end_ - chunk_pos_;
    const char* lf = static_cast<const char*>(std::memchr(from, '\n', n));
    const size_t take = lf ? static_cast<size_t>(lf - from) : n;
    line.append(from, take);
    const size_t used = lf ? take + 1 : take;
    chunk_pos_ += used;
    next_offset_ += used;
    if (lf) return true;
  }
}

bool LineSource::fill() {
  if (stream_eof_) return false;
  if (chunk_.empty()) chunk_.resize(kChunk);
  errno = 0;
  stream_.read(chunk_.data(), static_cast<std::streamsize>(chunk_.size()));
  // A read error is not the end of the file (badbit, not eofbit).
  if (stream_.bad()) throw SourceReadError(path_, errno ? std::strerror(errno) : "read error");
  chunk_pos_ = 0;
  chunk_end_ = static_cast<size_t>(stream_.gcount());
  if (!stream_) stream_eof_ = true;  // a short read: the end of the file
  return chunk_end_ > 0;
}

void LineSource::seek(uint64_t offset) {
  if (!ok_) return;
  line_offset_ = next_offset_ = offset;
  if (buffer_) return;
  chunk_pos_ = chunk_end_ = 0;
  stream_eof_ = false;
  stream_.clear();
  stream_.seekg(static_cast<std::streamoff>(offset));
}

}  // namespace ncc::frontend
