#pragma once
// The bounds of a run, applied while compiling (docs/cli.md, Bounds). The run stops a program
// at its simulated-time limit (--max-time, NCC7208) and its instruction budget (--max-steps,
// NCC7204); the compiler, which runs every loop and call of the program ahead of time, stops at
// the same bounds, so that `compile`, `check` and `run` end every endless program and give one
// verdict. The time is a lower bound (vm::minimumSeconds at the highest feed override, 200 %),
// the steps a lower bound of the VM's instructions (one per IR operation): a compile stopped
// here holds a program that the run would stop inside.
#include <cstdint>
#include <optional>
#include <string>

#include "ncc/driver/session.h"
#include "ncc/ir/ir.h"
#include "ncc/machine/machine_config.h"

namespace ncc::driver {

class RunBudgetSink final : public ir::BlockSink {
 public:
  RunBudgetSink(const MachineConfig& machine, const RunBounds& bounds, ir::BlockSink& next);

  // Counts the block and passes it on; once a bound is passed, blocks go no further.
  void accept(ir::Block&& block) override;
  void finish() override { next_.finish(); }

  // The bound passed, at the block that passed it: the code the run raises (NCC7208, NCC7204)
  // and a message naming the bound.
  struct Exceeded {
    SourceLocation loc;
    std::string code;
    std::string message;
  };
  const std::optional<Exceeded>& exceeded() const { return exceeded_; }

 private:
  double leastSeconds(const ir::Operation& op, const ir::Block& block);

  const MachineConfig& machine_;
  RunBounds bounds_;
  ir::BlockSink& next_;
  double seconds_ = 0.0;
  uint64_t steps_ = 0;
  double spindle_rpm_ = 0.0;
  AxisValues at_{};
  bool at_known_ = false;  // the first move starts where the machine is: not counted
  bool prepared_ = false;  // the rest is prepared at run time: the VM bounds it
  std::optional<Exceeded> exceeded_;
};

}  // namespace ncc::driver
