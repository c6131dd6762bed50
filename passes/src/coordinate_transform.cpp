#include "ncc/passes/coordinate_transform.h"

#include <algorithm>
#include <variant>

#include "ncc/ir/visit.h"

namespace ncc::passes {

void WorkToMachinePass::accept(ir::Block&& block) {
  const AxisValues total = block.frame.total();
  const int n = std::clamp(axis_count_, 0, kMaxAxes);
  auto shift = [&](AxisValues& v) {
    for (int i = 0; i < n; ++i) v[i] += total[i];
  };
  auto toMachine = [&](AxisValues& to, ir::Space& space) {
    if (space == ir::Space::Work) shift(to);
    space = ir::Space::Machine;
  };
  for (ir::Operation& op : block.ops) {
    std::visit(ir::Overloaded{
                   [&](ir::Rapid& o) { toMachine(o.to, o.space); },
                   [&](ir::Linear& o) { toMachine(o.to, o.space); },
                   [&](ir::Skip& o) { toMachine(o.to, o.space); },
                   [&](ir::Arc& o) {
                     if (o.space == ir::Space::Work) shift(o.center);
                     toMachine(o.to, o.space);
                   },
                   // The cycles pass (registered before this one) replaced a hole cycle; one
                   // left here stays in work space and the verifier / backend report it. A
                   // reference check is in machine coordinates already.
                   ir::Leave<ir::HoleCycle, ir::ReferenceCheck>{},
                   ir::NoPoint{},
               },
               op);
  }
  next_.accept(std::move(block));
}

}  // namespace ncc::passes
