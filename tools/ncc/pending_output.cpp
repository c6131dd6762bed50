#include "pending_output.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

namespace ncc::cli {

bool PendingOutput::open(const std::string& path) {
  path_ = path;
  if (path_.empty()) return true;
  temp_ = path_ + ".tmp";
  file_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!file_) {
    std::cerr << "ncc: error: cannot write '" << path_ << "'\n";
    temp_.clear();
    return false;
  }
  return true;
}

std::ostream& PendingOutput::stream() { return path_.empty() ? std::cout : file_; }

bool PendingOutput::commit() {
  if (path_.empty()) {
    std::cout.flush();
    return true;
  }
  file_.flush();
  bool written = static_cast<bool>(file_);
  file_.close();
  std::error_code ec;
  if (written) std::filesystem::rename(temp_, path_, ec);
  if (!written || ec) {
    std::cerr << "ncc: error: cannot write '" << path_ << "'\n";
    discard();
    return false;
  }
  temp_.clear();
  return true;
}

void PendingOutput::discard() {
  if (temp_.empty()) return;
  file_.close();
  std::error_code ec;
  std::filesystem::remove(temp_, ec);
  temp_.clear();
}

}  // namespace ncc::cli
