#pragma once
// One IR operation -> its bytecode instructions (docs/bytecode.md): the backend's one mapping,
// used by the writer ahead of time and by the VM's block preparation at run time.
#include <array>
#include <optional>
#include <string>
#include <utility>

#include "ncc/bytecode/instruction.h"
#include "ncc/ir/ir.h"
#include "ncc/machine/machine_config.h"

namespace ncc::backend {

// The instructions of one IR operation: at most two, or an internal error.
struct EncodedOperation {
  std::array<bytecode::Instruction, 2> instructions{};
  int count = 0;
  std::optional<std::pair<std::string, std::string>> error;  // code, message

  EncodedOperation() = default;
  explicit EncodedOperation(const bytecode::Instruction& in) : instructions{in}, count(1) {}
};

// `op` of `block`, which must be in machine space (ir::verify with require_machine_space).
// Every IR operation kind has its case: one the encoder forgets does not compile.
EncodedOperation encodeOperation(const ir::Operation& op, const ir::Block& block,
                                 const MachineConfig& machine);

// Why `in` holds a value beyond the format's bounds (reported as NCC7017), or nullopt.
std::optional<std::string> outOfBounds(const bytecode::Instruction& in,
                                       const MachineConfig& machine);

}  // namespace ncc::backend
