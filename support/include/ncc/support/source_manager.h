#pragma once
// Owns the names of every source file of a run and reads their lines on demand, so that
// diagnostics can quote the offending line without the frontend keeping whole files in memory.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "ncc/support/source_location.h"

namespace ncc {

class SourceManager {
 public:
  SourceManager();

  // Registers a file by path and returns its id (>= 1). The same path registered twice
  // returns the same id.
  uint32_t addFile(const std::filesystem::path& path);
  // Registers an in-memory buffer (tests, fuzzing, stdin) under a display name.
  uint32_t addBuffer(std::string display_name, std::string contents);

  const std::string& displayName(uint32_t file) const;
  const std::filesystem::path& path(uint32_t file) const;
  // In-memory contents for buffers; nullptr for files read from disk.
  const std::string* buffer(uint32_t file) const;
  size_t fileCount() const { return files_.size() - 1; }

  // The text of one line (without its terminator); empty if it cannot be read.
  std::string lineText(uint32_t file, uint32_t line) const;

 private:
  struct Entry {
    std::filesystem::path path;
    std::string display_name;
    bool in_memory = false;
    std::string contents;
  };
  std::vector<Entry> files_;  // index 0 is the "no file" entry
};

}  // namespace ncc
