#pragma once
// A source file whose read failed part way (an I/O error, a folder, /proc/self/mem): thrown by
// the reader, so that a failed read never passes for the end of the file and the rest of the
// program for absent. The command reports it as NCC0001 (the input cannot be read).
#include <filesystem>
#include <stdexcept>
#include <string>

namespace ncc {

class SourceReadError : public std::runtime_error {
 public:
  SourceReadError(const std::filesystem::path& path, const std::string& why)
      : std::runtime_error("cannot read '" + path.string() + "': " + why) {}
};

}  // namespace ncc
