#pragma once
// Obtain a verified program for `ncc run` and `ncc dis`: compile the source, or load a .ncb
// file. Running it is simulate.h's: every output mode runs the whole controller, since the
// planner's and the servo's alarms exist only there (one verdict whatever is emitted).
#include <cstdint>
#include <filesystem>
#include <optional>

#include "ncc/bytecode/program.h"
#include "ncc/driver/session.h"

namespace ncc::driver {

// True when `path` names a bytecode file (by its magic number, else by the .ncb extension).
bool isBytecodeFile(const std::filesystem::path& path);
// True when the session's input (a file, or the standard input's bytes) is bytecode.
bool isBytecodeInput(const Session& session);

// Where a loaded program's code and line table are held (bytecode/program.h).
enum class Residence {
  InMemory,  // in the Program's vectors (disassembly, tests)
  // Left in a file and read through a bounded window, so memory does not grow with the
  // program: a .ncb input is read where it is; a source is compiled into an anonymous scratch
  // file in $TMPDIR (unlinked at once; scratch_file.h). Bytecode from the standard input stays
  // in memory (it was read whole already).
  Paged,
};

// Compiles the session's input (or loads it when it is bytecode) and verifies the result
// against the session's machine (`check_machine`: its axes and that it was compiled for that
// machine; off for disassembly, which reads the axes from the file). Errors are reported to
// the session's diagnostics, except that a scratch file that cannot be made (NCC0004, a
// problem of the environment, not of the program) goes to `setup_error` when one is given.
bool loadProgram(Session& session, bytecode::Program& program, bool check_machine = true,
                 Residence residence = Residence::InMemory,
                 std::optional<SetupError>* setup_error = nullptr);

}  // namespace ncc::driver
