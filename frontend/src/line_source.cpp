#include "line_source.h"

namespace ncc::frontend {

LineSource::LineSource(const SourceManager& sources, uint32_t file) {
  buffer_ = sources.buffer(file);
  if (buffer_) {
    ok_ = true;
    return;
  }
  if (file == 0 || file > sources.fileCount()) return;
  stream_.open(sources.path(file), std::ios::binary);
  ok_ = stream_.is_open();
}

bool LineSource::next(std::string& line) {
  if (!ok_) return false;
  if (buffer_) {
    if (offset_ >= buffer_->size()) return false;
    size_t end = buffer_->find('\n', offset_);
    if (end == std::string::npos) end = buffer_->size();
    line.assign(*buffer_, offset_, end - offset_);
    offset_ = end + 1;
  } else if (!std::getline(stream_, line)) {
    return false;
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  // A UTF-8 byte order mark some editors write is not part of the first line.
  if (first_line_ && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
  first_line_ = false;
  return true;
}

}  // namespace ncc::frontend
