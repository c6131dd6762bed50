#include "ncc/frontend/program_library.h"

#include <algorithm>
#include <fstream>
#include <set>
#include <system_error>

namespace ncc::frontend {

namespace {

std::string lowerAscii(std::string s) {
  for (char& c : s)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c + 32);
  return s;
}

// The extension of a pattern's name, lower case, with its dot (".nc"); empty if none.
std::string patternExtension(const std::string& pattern) {
  const std::string name = std::filesystem::path(pattern).filename().string();
  const size_t dot = name.rfind('.');
  if (dot == std::string::npos || dot == 0) return {};
  return lowerAscii(name.substr(dot));
}

bool readable(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  std::ifstream in(path, std::ios::binary);
  return in.is_open();
}

}  // namespace

ProgramLibrary::ProgramLibrary(SourceManager& sources, std::filesystem::path folder,
                               std::vector<std::string> name_patterns, ReaderOptions options)
    : sources_(sources),
      folder_(std::move(folder)),
      patterns_(std::move(name_patterns)),
      options_(options) {}

std::string ProgramLibrary::formatName(const std::string& pattern, int64_t number) {
  const std::string digits = std::to_string(number);
  std::string out;
  size_t i = 0;
  while (i < pattern.size()) {
    if (pattern[i] == '{') {
      const size_t close = pattern.find('}', i);
      if (close != std::string::npos) {
        const std::string spec = pattern.substr(i + 1, close - i - 1);
        if (spec.empty()) {
          out += digits;
          i = close + 1;
          continue;
        }
        // ":0w": zero-padded to w digits (w 1..20, the digits of an int64)
        if (spec.size() >= 3 && spec.size() <= 4 && spec[0] == ':' && spec[1] == '0' &&
            std::all_of(spec.begin() + 2, spec.end(), [](char c) { return c >= '0' && c <= '9'; })) {
          const size_t width = std::stoul(spec.substr(2));
          if (width >= 1 && width <= 20) {
            if (digits.size() < width) out.append(width - digits.size(), '0');
            out += digits;
            i = close + 1;
            continue;
          }
        }
      }
    }
    out += pattern[i++];
  }
  return out;
}

ProgramIndex& ProgramLibrary::index(uint32_t file) {
  std::unique_ptr<ProgramIndex>& slot = indexes_[file];
  if (!slot) slot = std::make_unique<ProgramIndex>(sources_, file, options_);
  return *slot;
}

const std::vector<std::string>& ProgramLibrary::folderFiles() {
  if (listed_) return files_;
  listed_ = true;
  std::error_code ec;
  std::filesystem::directory_iterator it(folder_, ec);
  for (; !ec && it != std::filesystem::directory_iterator(); it.increment(ec)) {
    std::error_code type_ec;
    if (it->is_regular_file(type_ec)) files_.push_back(it->path().filename().string());
  }
  std::sort(files_.begin(), files_.end());
  return files_;
}

std::optional<ProgramLibrary::Found> ProgramLibrary::findByName(int64_t number) {
  for (const std::string& pattern : patterns_) {
    const std::string name = formatName(pattern, number);
    std::filesystem::path path = folder_ / name;
    if (!readable(path)) {
      // A file whose name matches ignoring case (O0010.NC for O{:04}.nc).
      const std::string lower = lowerAscii(name);
      path.clear();
      for (const std::string& file : folderFiles()) {
        if (lowerAscii(file) == lower && readable(folder_ / file)) {
          path = folder_ / file;
          break;
        }
      }
      if (path.empty()) continue;
    }
    const uint32_t file = sources_.addFile(path.lexically_normal());
    const std::optional<BlockPosition> o_block = index(file).findProgram(number);
    return Found{file, o_block.value_or(BlockPosition{})};
  }
  return std::nullopt;
}

std::optional<ProgramLibrary::Found> ProgramLibrary::findByFirstProgram(int64_t number) {
  if (!first_numbers_) {
    std::set<std::string> extensions;
    for (const std::string& pattern : patterns_)
      if (std::string ext = patternExtension(pattern); !ext.empty()) extensions.insert(ext);
    first_numbers_.emplace();
    for (const std::string& file : folderFiles()) {
      const size_t dot = file.rfind('.');
      if (dot == std::string::npos || !extensions.count(lowerAscii(file.substr(dot)))) continue;
      (*first_numbers_)[file] = ProgramIndex::firstProgramNumberOf(folder_ / file, options_);
    }
  }
  for (const auto& [file, first] : *first_numbers_) {  // std::map: sorted by name
    if (first != number) continue;
    const uint32_t id = sources_.addFile((folder_ / file).lexically_normal());
    const std::optional<BlockPosition> o_block = index(id).findProgram(number);
    if (o_block) return Found{id, *o_block};
  }
  return std::nullopt;
}

std::optional<ProgramLibrary::Found> ProgramLibrary::find(int64_t number, uint32_t calling_file) {
  if (number < 0) return std::nullopt;
  if (std::optional<BlockPosition> here = index(calling_file).findProgram(number))
    return Found{calling_file, *here};
  return findInFolder(number);
}

std::optional<ProgramLibrary::Found> ProgramLibrary::findInFolder(int64_t number) {
  if (number < 0 || folder_.empty()) return std::nullopt;
  if (std::optional<Found> by_name = findByName(number)) return by_name;
  return findByFirstProgram(number);
}

}  // namespace ncc::frontend
