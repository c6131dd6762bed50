#include "ncc/bytecode/program_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

namespace ncc::bytecode {

std::shared_ptr<const ProgramFile> ProgramFile::open(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return nullptr;
  return adopt(fd);
}

std::shared_ptr<const ProgramFile> ProgramFile::adopt(int fd) {
  return std::shared_ptr<const ProgramFile>(new ProgramFile(fd));
}

ProgramFile::~ProgramFile() { ::close(fd_); }

int64_t ProgramFile::size() const {
  struct stat st {};
  if (::fstat(fd_, &st) != 0) return -1;
  return static_cast<int64_t>(st.st_size);
}

std::size_t ProgramFile::read(uint64_t offset, uint8_t* out, std::size_t count) const {
  std::size_t done = 0;
  while (done < count) {
    const ssize_t n = ::pread(fd_, out + done, count - done, static_cast<off_t>(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  return done;
}

}  // namespace ncc::bytecode
