#pragma once
// Work -> machine coordinates: adds each block's frame (work offset, G92/G52 shift, tool
// length) to every work-space target and arc centre, and marks them machine space.
// Later transforms (rotation, scaling, mirror, polar) run before this pass, in work space.
#include "ncc/ir/ir.h"

namespace ncc::passes {

class WorkToMachinePass : public ir::BlockSink {
 public:
  WorkToMachinePass(ir::BlockSink& next, int axis_count) : next_(next), axis_count_(axis_count) {}
  void accept(ir::Block&& block) override;
  void finish() override { next_.finish(); }

 private:
  ir::BlockSink& next_;
  int axis_count_;
};

}  // namespace ncc::passes
