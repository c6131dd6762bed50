#include "scratch_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace ncc::driver {

ScratchFile makeScratchFile() {
  ScratchFile result;
  const char* dir = std::getenv("TMPDIR");
  std::string pattern = std::string(dir != nullptr && *dir != '\0' ? dir : "/tmp") +
                        "/ncc-run-XXXXXX.ncb";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  // The file has a name only between mkstemps and unlink: the signals that end a command
  // wait until it has none.
  sigset_t block, previous;
  sigemptyset(&block);
  sigaddset(&block, SIGINT);
  sigaddset(&block, SIGTERM);
  sigaddset(&block, SIGHUP);
  sigprocmask(SIG_BLOCK, &block, &previous);
  const int fd = mkstemps(name.data(), 4);
  if (fd < 0) {
    result.error = std::string("cannot create a temporary file in '") + pattern.substr(0, pattern.rfind('/')) +
                   "': " + std::strerror(errno);
  } else {
    result.read_fd = ::open(name.data(), O_RDONLY | O_CLOEXEC);
    result.stream.open(name.data(), std::ios::binary | std::ios::in | std::ios::out |
                                        std::ios::trunc);
    ::unlink(name.data());
    ::close(fd);
    if (result.read_fd < 0 || !result.stream.is_open()) {
      result.error = std::string("cannot open the temporary file: ") + std::strerror(errno);
      if (result.read_fd >= 0) ::close(result.read_fd);
      result.read_fd = -1;
    }
  }
  sigprocmask(SIG_SETMASK, &previous, nullptr);
  return result;
}

}  // namespace ncc::driver
