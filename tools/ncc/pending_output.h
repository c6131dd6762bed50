#pragma once
// Where a command's output goes: stdout (no path, or "-"), or a file that appears whole or
// not at all. The file is written under a unique temporary name in the output's folder
// (mkstemp: `.NAME.XXXXXX`, so a user's own `NAME.tmp` is never touched) while the command
// streams into it, and renamed to the path by commit(); discard(), destruction without
// commit, SIGINT, SIGTERM and SIGHUP remove it. Memory does not grow with the output.
//
// A path that is a symbolic link is written through: the temporary file is made beside the
// file the link names and renamed onto it, so the link stays a link. A path that is a FIFO or
// a character or block device is written in place as a stream, like stdout (renaming a file
// onto /dev/null would replace the device).
//
// An output is never one of the command's inputs (the source, a called subprogram, the
// .ncb, the machine file, the --vars file even before it exists): compared by filesystem
// identity, at open() and again at commit() (a subprogram may be found only while compiling).
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include "ncc/driver/session.h"

namespace ncc::cli {

class PendingOutput {
 public:
  PendingOutput() = default;
  PendingOutput(const PendingOutput&) = delete;
  PendingOutput& operator=(const PendingOutput&) = delete;
  ~PendingOutput() { discard(); }

  // `path` empty or "-" means stdout. `inputs`: the files the output must not replace.
  // Returns false after printing why (NCC0005 an input, NCC0004 cannot create).
  bool open(const std::string& path, std::vector<driver::InputFile> inputs = {});
  // More inputs, found after open() (the compile's subprograms); checked at commit().
  void addInputs(const std::vector<driver::InputFile>& inputs);
  std::ostream& stream();
  bool toStdout() const { return path_.empty(); }
  // Written as it comes (stdout, a FIFO, a device): it cannot seek, and what was written
  // stays written when the command fails.
  bool isStream() const { return path_.empty() || in_place_; }
  // Makes the output final; false (after printing why) on a write or rename error, or when the
  // path has become one of the inputs.
  bool commit();
  void discard();

 private:
  std::string path_;    // as given; empty: stdout
  std::string target_;  // path_ with its symbolic links followed: the file replaced
  std::string temp_;    // empty: no temporary file exists
  bool in_place_ = false;  // a FIFO or a device, opened and written directly
  std::vector<driver::InputFile> inputs_;
  std::ofstream file_;
};

// True (after printing NCC0005) when `output` names the same file as one of `inputs`: by
// filesystem identity when both exist, else by their paths with symbolic links followed (an
// input that does not exist yet, the --vars file a run creates).
bool outputIsAnInput(const std::filesystem::path& output,
                     const std::vector<driver::InputFile>& inputs);

// Whether `a` and `b` name one file, existing or not, through any symbolic link, hard link or
// spelling of the path.
bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace ncc::cli
