#pragma once
// Where a command's output goes: stdout (no path, or "-"), or a file that appears whole or
// not at all. The file is written under a unique temporary name in the output's folder
// (mkstemp: `.NAME.XXXXXX`, so a user's own `NAME.tmp` is never touched) while the command
// streams into it, and renamed to the path by commit(); discard(), destruction without
// commit, SIGINT, SIGTERM and SIGHUP remove it. Memory does not grow with the output.
//
// An output is never one of the command's inputs (the source, a called subprogram, the
// .ncb, the machine file): compared by filesystem identity, at open() and again at commit()
// (a subprogram may be found only while compiling).
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
  // Makes the output final; false (after printing why) on a write or rename error, or when the
  // path has become one of the inputs.
  bool commit();
  void discard();

 private:
  std::string path_;  // empty: stdout
  std::string temp_;  // empty: no temporary file exists
  std::vector<driver::InputFile> inputs_;
  std::ofstream file_;
};

// True (after printing NCC0005) when `output` exists and is the same file as one of `inputs`.
bool outputIsAnInput(const std::filesystem::path& output,
                     const std::vector<driver::InputFile>& inputs);

}  // namespace ncc::cli
