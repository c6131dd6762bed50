#pragma once
// The VM's block preparation (docs/runtime.md): after PREPARE, the executor's instructions
// come from here. The program's remaining blocks, from the block store the compiler wrote
// (eval/block_store.h), go through the same evaluation and lowering as in the compiler
// (prepare::BlockLoop), with the running machine behind the values the compiler could not
// know: where a G31 stopped (#5061.., the axes it moved). Each prepared block is encoded by
// the backend's one IR-to-bytecode mapping (backend/encode.h).
//
// Not real-time: a step allocates (evaluation, lowering). It runs in the controller's
// preparation (Controller::prepare), never in the tick's real-time part.
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ncc/bytecode/instruction.h"
#include "ncc/bytecode/program.h"
#include "ncc/eval/value.h"
#include "ncc/machine/machine_config.h"
#include "ncc/vm/events.h"

#include <map>
#include <string>

namespace ncc::vm {

struct PreparedInstruction {
  bytecode::Instruction instruction;
  SourcePosition where;
};

// What the running machine tells the preparation: the executor's state.
struct RunningMachine {
  std::function<AxisValues()> position;                   // commanded, machine coordinates
  std::function<eval::Value(uint32_t number)> variable;   // the executor's #number
  std::function<double()> seconds;                        // the run's time (Executor::setClock)
};

class BlockPreparation {
 public:
  // Decodes the program's block store and replays the blocks the compiler prepared ahead
  // (their instructions are in the code before PREPARE), emitting nothing. nullptr with
  // `error` set when the store does not decode or does not replay.
  static std::unique_ptr<BlockPreparation> create(const bytecode::Program& program,
                                                  const MachineConfig& machine,
                                                  RunningMachine running, std::string& error);
  ~BlockPreparation();

  // Prepares blocks until at least one instruction is in `out` (cleared first). False at the
  // end of the program, with `alarm` set when a block raised one (the manual's alarm number,
  // at the block).
  bool next(std::vector<PreparedInstruction>& out, std::optional<Alarm>& alarm);
  // The run's instruction budget (--max-steps, 0: none) bounds the blocks it prepares without
  // a move or a dwell too, as they execute no instruction: a damaged or endless store ends.
  void boundIdleBlocks(uint64_t max_steps);
  // The names of the DIN variables the prepared blocks wrote (named_variables.h), which the
  // bytecode's name table could not list: they were declared after PREPARE.
  const std::map<uint32_t, std::string>& variableNames() const;

 private:
  struct Impl;
  explicit BlockPreparation(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace ncc::vm
