#include "pending_output.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <iostream>
#include <system_error>

#include "cli.h"

namespace ncc::cli {

namespace {

// The temporary file a signal must remove. Written only outside the handler, with the flag
// cleared first, so the handler never sees a half-written path.
char g_temp_path[4096];
volatile std::sig_atomic_t g_temp_registered = 0;

// Async-signal-safe: unlink, restore the default action, re-raise so the exit status says
// which signal ended the command.
extern "C" void removeTempAndReraise(int sig) {
  if (g_temp_registered) unlink(g_temp_path);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

void installSignalHandlers() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  struct sigaction action {};
  action.sa_handler = removeTempAndReraise;
  sigemptyset(&action.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    // A signal the caller ignores (nohup, a background job's SIGINT) stays ignored.
    struct sigaction current {};
    if (sigaction(sig, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
    sigaction(sig, &action, nullptr);
  }
}

void unregisterTemp() { g_temp_registered = 0; }

// The mode a new file gets (0666 less the umask), or the existing output's own.
mode_t finalMode(const std::string& path) {
  struct stat existing {};
  if (stat(path.c_str(), &existing) == 0) return existing.st_mode & 07777;
  const mode_t mask = umask(0);
  umask(mask);
  return 0666 & ~mask;
}

// `path` with its symbolic links followed while it is one (at most 40 hops, as the kernel
// allows): the file an output replaces, so that a link stays a link. A dangling link gives
// the path it names (the output creates it, as a shell's `>` does).
std::filesystem::path followLinks(std::filesystem::path path, std::error_code& ec) {
  for (int hops = 0; hops < 40; ++hops) {
    const std::filesystem::file_status status = std::filesystem::symlink_status(path, ec);
    if (status.type() == std::filesystem::file_type::not_found) ec.clear();  // created later
    if (ec || !std::filesystem::is_symlink(status)) return path;
    std::filesystem::path target = std::filesystem::read_symlink(path, ec);
    if (ec) return path;
    path = target.is_absolute() ? target : path.parent_path() / target;
  }
  ec = std::make_error_code(std::errc::too_many_symbolic_link_levels);
  return path;
}

}  // namespace

bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ec;
  const std::filesystem::path ra = followLinks(a, ec);
  const std::filesystem::path rb = followLinks(b, ec);
  const bool a_exists = std::filesystem::exists(ra, ec);
  const bool b_exists = std::filesystem::exists(rb, ec);
  if (a_exists && b_exists) return std::filesystem::equivalent(ra, rb, ec) && !ec;
  if (a_exists || b_exists) return false;
  // Neither exists yet (an output and the --vars file a run creates): the same path, once
  // made absolute with the links of its folders followed.
  const std::filesystem::path ca = std::filesystem::weakly_canonical(ra, ec);
  if (ec) return false;
  const std::filesystem::path cb = std::filesystem::weakly_canonical(rb, ec);
  return !ec && ca == cb;
}

bool outputIsAnInput(const std::filesystem::path& output,
                     const std::vector<driver::InputFile>& inputs) {
  for (const driver::InputFile& input : inputs) {
    if (sameFile(output, input.path)) {
      const std::string role = input.role;
      const std::string what = role == "the program"
                                   ? "its own source"  // the usual slip: -o part.nc
                                   : role;
      const std::string why = role == "the variables file"
                                  ? "-o names the --vars file, which is read and written back"
                                  : "-o names a file this command reads";
      printError("NCC0005", "refusing to write the output over " + what + " '" +
                                input.path.string() + "' (" + why + ")");
      return true;
    }
  }
  return false;
}

bool PendingOutput::open(const std::string& path, std::vector<driver::InputFile> inputs) {
  path_ = path == "-" ? std::string() : path;
  inputs_ = std::move(inputs);
  if (path_.empty()) return true;
  if (outputIsAnInput(path_, inputs_)) return false;
  struct stat existing {};
  if (stat(path_.c_str(), &existing) == 0) {  // through links, as the kernel resolves them
    if (S_ISDIR(existing.st_mode)) {  // said now, not after a long run
      printError("NCC0004", "cannot write '" + path_ + "': it is a folder");
      return false;
    }
    if (S_ISFIFO(existing.st_mode) || S_ISCHR(existing.st_mode) || S_ISBLK(existing.st_mode)) {
      // Written in place, as a stream: renaming a file onto /dev/null or a FIFO would replace
      // it. A FIFO blocks here until a reader opens it, as a shell's `>` does.
      in_place_ = true;
      file_.open(path_, std::ios::binary | std::ios::out);
      if (!file_) {
        printError("NCC0004", "cannot write '" + path_ + "': " + std::strerror(errno));
        in_place_ = false;
        return false;
      }
      return true;
    }
    if (!S_ISREG(existing.st_mode)) {  // a socket: nothing to write into, nothing to replace
      printError("NCC0004", "cannot write '" + path_ + "': not a regular file, FIFO or device");
      return false;
    }
  }
  std::error_code ec;
  const std::filesystem::path target = followLinks(path_, ec);
  if (ec) {
    printError("NCC0004", "cannot write '" + path_ + "': " + ec.message());
    return false;
  }
  target_ = target.string();
  std::filesystem::path folder = target.parent_path();
  if (folder.empty()) folder = ".";
  std::string pattern = (folder / ("." + target.filename().string() + ".XXXXXX")).string();
  installSignalHandlers();
  // mkstemp fills in the name in place, in the buffer the signal handler reads; the handler
  // is armed once the file exists.
  g_temp_registered = 0;
  int fd = -1;
  errno = ENAMETOOLONG;
  if (pattern.size() < sizeof g_temp_path) {
    std::memcpy(g_temp_path, pattern.c_str(), pattern.size() + 1);
    fd = mkstemp(g_temp_path);
    if (fd >= 0) {
      g_temp_registered = 1;
      pattern = g_temp_path;
      fchmod(fd, finalMode(target_));
      close(fd);
    }
  }
  if (fd < 0) {
    printError("NCC0004", "cannot write '" + path_ + "': " + std::strerror(errno));
    return false;
  }
  temp_ = pattern;
  file_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!file_) {
    printError("NCC0004", "cannot write '" + path_ + "'");
    discard();
    return false;
  }
  return true;
}

void PendingOutput::addInputs(const std::vector<driver::InputFile>& inputs) {
  inputs_.insert(inputs_.end(), inputs.begin(), inputs.end());
}

std::ostream& PendingOutput::stream() { return path_.empty() ? std::cout : file_; }

bool PendingOutput::commit() {
  if (path_.empty()) {
    std::cout.flush();
    if (!std::cout) {
      printError("NCC0004", "cannot write to stdout");
      return false;
    }
    return true;
  }
  if (outputIsAnInput(path_, inputs_)) {
    discard();
    return false;
  }
  file_.flush();
  const bool written = static_cast<bool>(file_);
  file_.close();
  if (in_place_) {
    in_place_ = false;
    if (!written) printError("NCC0004", "cannot write '" + path_ + "'");
    return written;
  }
  std::error_code ec;
  if (written) std::filesystem::rename(temp_, target_, ec);
  if (!written || ec) {
    printError("NCC0004", "cannot write '" + path_ + "'" + (ec ? ": " + ec.message() : ""));
    discard();
    return false;
  }
  unregisterTemp();
  temp_.clear();
  return true;
}

void PendingOutput::discard() {
  if (in_place_) {  // what was written is the reader's already
    file_.close();
    in_place_ = false;
  }
  if (temp_.empty()) return;
  file_.close();
  std::error_code ec;
  std::filesystem::remove(temp_, ec);
  unregisterTemp();
  temp_.clear();
}

}  // namespace ncc::cli
