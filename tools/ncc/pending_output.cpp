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

}  // namespace

bool outputIsAnInput(const std::filesystem::path& output,
                     const std::vector<driver::InputFile>& inputs) {
  std::error_code ec;
  if (!std::filesystem::exists(output, ec)) return false;
  for (const driver::InputFile& input : inputs) {
    if (std::filesystem::equivalent(output, input.path, ec)) {
      const std::string what = std::string(input.role) == "the program"
                                   ? "its own source"  // the usual slip: -o part.nc
                                   : input.role;
      printError("NCC0005", "refusing to write the output over " + what + " '" +
                                input.path.string() + "' (-o names a file this command reads)");
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
  std::error_code ec;
  if (std::filesystem::is_directory(path_, ec)) {  // said now, not after a long run
    printError("NCC0004", "cannot write '" + path_ + "': it is a folder");
    return false;
  }
  const std::filesystem::path target(path_);
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
      fchmod(fd, finalMode(path_));
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
  std::error_code ec;
  if (written) std::filesystem::rename(temp_, path_, ec);
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
  if (temp_.empty()) return;
  file_.close();
  std::error_code ec;
  std::filesystem::remove(temp_, ec);
  unregisterTemp();
  temp_.clear();
}

}  // namespace ncc::cli
