#pragma once
// Checks everything about a loaded program before it runs, so that the executor can trust it:
// every instruction decodes and ends inside the code, opcodes and flag bits are known, operands
// are in range (axis indices, variable numbers, codes, finite doubles, positive feeds,
// coordinates, dwells and extra arc turns within the bounds of format.h), jump
// targets are instruction starts, the value stack never underflows, stays within
// kMaxStackDepth and has one depth at every join, execution cannot run off the end of the code,
// an end of program is reachable, the line table is ordered and points at instruction starts
// and existing strings, unit entries are instruction starts, and the axes match the machine.
//
// It reads the code and line table through bytecode::CodeView in a few forward passes, in
// memory proportional to the program's jumps and units, so a paged program (loader.h,
// loadPaged) is verified without holding its code (docs/bytecode.md, "Paged loading").
#include <optional>

#include "ncc/bytecode/error.h"
#include "ncc/bytecode/program.h"
#include "ncc/machine/machine_config.h"

namespace ncc::bytecode {

struct VerifyOptions {
  // The machine the program will run on; nullptr skips the machine checks.
  const MachineConfig* machine = nullptr;
  // Also require header.config_hash == machine->configHash().
  bool check_config_hash = true;
};

// Returns the first problem found, or nullopt when the program is safe to run.
std::optional<Error> verify(const Program& program, const VerifyOptions& options = {});

}  // namespace ncc::bytecode
