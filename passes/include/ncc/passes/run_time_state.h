#pragma once
// What only the running machine knows, asked by lowering and the system variables when the
// VM prepares blocks while the program runs (docs/runtime.md). The compiler has none: a block
// that needs one of these values is where its ahead-of-time preparation stops.
#include <cstdint>
#include <optional>

#include "ncc/eval/value.h"
#include "ncc/machine/axes.h"

namespace ncc::passes {

class RunTimeState {
 public:
  virtual ~RunTimeState() = default;
  // False while the VM replays the blocks the compiler prepared ahead of time: they are
  // prepared again on what the compiler knew, so that the state is the compiler's.
  virtual bool running() const = 0;
  // The commanded machine position after every block prepared so far has run: where a G31
  // stopped, for the axes it moved.
  virtual AxisValues machinePosition() const = 0;
  // The run's time, s, when the block is prepared (the controller's IPO time then; 0 for an
  // executor run alone): the timers #3001/#3002 count it.
  virtual double seconds() const = 0;
  // The skip position #number (#5061..) as the last G31 stored it; vacant before any.
  virtual eval::Value skipVariable(int64_t number) const = 0;
  // Interface inputs (#1000..), servo lag: nullopt when the VM does not simulate it, which
  // stops the run (NotSupported).
  virtual std::optional<eval::Value> machineVariable(int64_t number) const = 0;
};

}  // namespace ncc::passes
