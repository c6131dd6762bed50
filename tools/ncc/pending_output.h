#pragma once
// Where a command's text output goes: stdout, or a file that appears only when the command
// succeeds. The file is written as `PATH.tmp` while the command streams into it and renamed to
// PATH by commit(); discard() (or destruction without commit) removes it, so a failed command
// never leaves a partial file and memory does not grow with the output.
#include <fstream>
#include <ostream>
#include <string>

namespace ncc::cli {

class PendingOutput {
 public:
  // An empty path means stdout. Returns false (after printing why) when PATH.tmp cannot be created.
  bool open(const std::string& path);
  std::ostream& stream();
  // Makes the output final; false (after printing why) on a write or rename error.
  bool commit();
  void discard();
  ~PendingOutput() { discard(); }

 private:
  std::string path_;
  std::string temp_;
  std::ofstream file_;
};

}  // namespace ncc::cli
