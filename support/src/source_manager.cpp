#include "ncc/support/source_manager.h"

#include <fstream>

namespace ncc {

SourceManager::SourceManager() { files_.push_back(Entry{}); }

uint32_t SourceManager::addFile(const std::filesystem::path& path) {
  for (uint32_t i = 1; i < files_.size(); ++i)
    if (!files_[i].in_memory && files_[i].path == path) return i;
  files_.push_back(Entry{path, path.string(), false, {}});
  return static_cast<uint32_t>(files_.size() - 1);
}

uint32_t SourceManager::addBuffer(std::string display_name, std::string contents) {
  files_.push_back(Entry{display_name, display_name, true, std::move(contents)});
  return static_cast<uint32_t>(files_.size() - 1);
}

const std::string& SourceManager::displayName(uint32_t file) const {
  return files_.at(file < files_.size() ? file : 0).display_name;
}

const std::filesystem::path& SourceManager::path(uint32_t file) const {
  return files_.at(file < files_.size() ? file : 0).path;
}

const std::string* SourceManager::buffer(uint32_t file) const {
  if (file == 0 || file >= files_.size() || !files_[file].in_memory) return nullptr;
  return &files_[file].contents;
}

namespace {
// Returns line `line` (1-based) of `text`; lines end at LF, a CR before it is dropped.
std::string nthLine(std::string_view text, uint32_t line) {
  uint32_t current = 1;
  size_t start = 0;
  while (current < line) {
    size_t nl = text.find('\n', start);
    if (nl == std::string_view::npos) return {};
    start = nl + 1;
    ++current;
  }
  size_t end = text.find('\n', start);
  std::string_view out = text.substr(start, end == std::string_view::npos ? text.npos : end - start);
  if (!out.empty() && out.back() == '\r') out.remove_suffix(1);
  return std::string(out);
}
}  // namespace

std::string SourceManager::lineText(uint32_t file, uint32_t line) const {
  if (file == 0 || file >= files_.size() || line == 0) return {};
  const Entry& e = files_[file];
  if (e.in_memory) return nthLine(e.contents, line);
  // Files are streamed by the frontend, not kept: re-read the one line a diagnostic needs.
  std::ifstream in(e.path, std::ios::binary);
  std::string text;
  for (uint32_t n = 1; std::getline(in, text); ++n) {
    if (n == line) {
      if (!text.empty() && text.back() == '\r') text.pop_back();
      return text;
    }
  }
  return {};
}

}  // namespace ncc
