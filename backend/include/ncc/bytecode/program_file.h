#pragma once
// An open bytecode file that a paged Program (program.h, Program::paged) reads its code and
// line table from. Reads are positional (pread), so any number of readers share one handle;
// the descriptor stays open as long as a Program or reader holds it, which also keeps an
// already unlinked temporary file (ncc run's compiled source) readable until the run ends.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>

namespace ncc::bytecode {

class ProgramFile {
 public:
  // Opens `path` for reading; nullptr when it cannot be opened.
  static std::shared_ptr<const ProgramFile> open(const std::filesystem::path& path);
  // Takes ownership of an open, readable descriptor.
  static std::shared_ptr<const ProgramFile> adopt(int fd);

  ProgramFile(const ProgramFile&) = delete;
  ProgramFile& operator=(const ProgramFile&) = delete;
  ~ProgramFile();

  // Size in bytes, or -1 when it cannot be found.
  int64_t size() const;
  // Reads up to `count` bytes at `offset` into `out`; returns how many were read (fewer only
  // at the end of the file or on an error). Never allocates.
  std::size_t read(uint64_t offset, uint8_t* out, std::size_t count) const;

 private:
  explicit ProgramFile(int fd) : fd_(fd) {}
  int fd_;
};

}  // namespace ncc::bytecode
