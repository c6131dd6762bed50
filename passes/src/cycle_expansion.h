#pragma once
// The `cycles` pass: replaces each ir::HoleCycle (one hole of a canned cycle, decoded by
// lowering_cycles.cpp) by the rapid, feed, dwell and spindle operations of its sequence, in
// work space, before work-to-machine. Moves of zero length are not emitted. docs/cycles.md
// lists each cycle's sequence; the per-dialect differences arrive as the HoleCycle's data.
#include <functional>
#include <vector>

#include "ncc/ir/ir.h"

namespace ncc::passes {

// The operations of one hole, in order.
std::vector<ir::Operation> expandHoleCycle(const ir::HoleCycle& cycle, int axis_count);
// The same, handed to `emit` one at a time as they are made.
using OperationEmitter = std::function<void(ir::Operation&&)>;
void expandHoleCycle(const ir::HoleCycle& cycle, int axis_count, const OperationEmitter& emit);

class CycleExpansionPass : public ir::BlockSink {
 public:
  CycleExpansionPass(ir::BlockSink& next, int axis_count) : next_(next), axis_count_(axis_count) {}
  void accept(ir::Block&& block) override;
  void finish() override { next_.finish(); }

 private:
  // The most operations one block passes on: a hole of 99 000 pecks goes on in parts.
  static constexpr size_t kMaxOperations = 256;
  ir::BlockSink& next_;
  int axis_count_;
};

}  // namespace ncc::passes
