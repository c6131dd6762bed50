#pragma once
// An anonymous scratch file for `ncc run`'s compiled bytecode: created with mkstemp in $TMPDIR
// (else /tmp) and unlinked at once, so nothing is left behind whatever ends the process
// (an exit, an error, a signal, even SIGKILL). The stream writes it (seekable, as the bytecode
// writer needs); read_fd reads it back for as long as it stays open.
#include <fstream>
#include <string>

namespace ncc::driver {

struct ScratchFile {
  std::fstream stream;  // open for writing
  int read_fd = -1;     // the same file, open for reading; the caller owns it
  std::string error;    // set when the file could not be made
};

ScratchFile makeScratchFile();

}  // namespace ncc::driver
