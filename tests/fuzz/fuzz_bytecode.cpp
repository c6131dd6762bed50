// libFuzzer target: random bytes (as given, and with their checksum sealed) through load + verify, and through the executor (bounded)
// and the disassembler when they pass. Nothing may crash, hang or read out of bounds.
//   clang++ -fsanitize=fuzzer,address,undefined ... ; ./fuzz_bytecode -max_total_time=60
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <span>
#include <sstream>
#include <vector>

#include "ncc/bytecode/checksum.h"
#include "ncc/bytecode/disassembler.h"
#include "ncc/bytecode/loader.h"
#include "ncc/bytecode/verifier.h"
#include "ncc/bytecode/writer.h"
#include "ncc/vm/executor.h"

namespace {

// A machine with the program's own axes, so that inputs get past the axis check.
ncc::MachineConfig machineFor(const ncc::bytecode::Program& program) {
  ncc::MachineConfig machine;
  for (const ncc::bytecode::AxisInfo& axis : program.header.axes) {
    ncc::AxisConfig config;
    config.name = axis.name;
    config.kind = axis.kind;
    machine.axes.push_back(config);
  }
  return machine;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  ncc::bytecode::Program program;
  // As given: a mutated file almost always stops at the checksum (NCC7016)...
  if (!ncc::bytecode::load(std::span<const uint8_t>(data, size), program)) {
  } else if (size >= ncc::bytecode::kFixedHeaderSize) {
    // ...so also with the checksum made to match, to reach every check behind it.
    std::vector<uint8_t> sealed(data, data + size);
    ncc::bytecode::sealChecksum(sealed);
    if (ncc::bytecode::load(sealed, program)) return 0;
  } else {
    return 0;
  }

  // The disassembler must cope with any loaded program, verified or not.
  std::ostringstream listing;
  ncc::bytecode::disassemble(program, listing);

  const ncc::MachineConfig machine = machineFor(program);
  ncc::bytecode::VerifyOptions options;
  options.machine = &machine;
  options.check_config_hash = false;
  if (ncc::bytecode::verify(program, options)) return 0;

  ncc::vm::Executor executor(program, machine);
  executor.setStepLimit(100000);
  ncc::vm::Event event;
  while (executor.next(event)) {
  }
  executor.variables();

  // A verified program re-encodes and loads back to the same code.
  std::ostringstream again;
  if (!ncc::bytecode::write(program, again)) {
    const std::string bytes = again.str();
    ncc::bytecode::Program reloaded;
    if (ncc::bytecode::load(std::span<const uint8_t>(
                                reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()),
                            reloaded) ||
        reloaded.code != program.code)
      __builtin_trap();
  }
  return 0;
}
