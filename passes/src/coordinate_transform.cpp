#include "ncc/passes/coordinate_transform.h"

#include <algorithm>
#include <type_traits>
#include <variant>

namespace ncc::passes {

void WorkToMachinePass::accept(ir::Block&& block) {
  const AxisValues total = block.frame.total();
  const int n = std::clamp(axis_count_, 0, kMaxAxes);
  auto shift = [&](AxisValues& v) {
    for (int i = 0; i < n; ++i) v[i] += total[i];
  };
  for (ir::Operation& op : block.ops) {
    std::visit(
        [&](auto& o) {
          using T = std::decay_t<decltype(o)>;
          if constexpr (std::is_same_v<T, ir::Rapid> || std::is_same_v<T, ir::Linear> ||
                        std::is_same_v<T, ir::Skip>) {
            if (o.space == ir::Space::Work) shift(o.to);
            o.space = ir::Space::Machine;
          } else if constexpr (std::is_same_v<T, ir::Arc>) {
            if (o.space == ir::Space::Work) {
              shift(o.to);
              shift(o.center);
            }
            o.space = ir::Space::Machine;
          }
          // ir::HoleCycle: the cycles pass (registered before this one) replaced it; one left
          // here stays in work space and the verifier / backend report it.
        },
        op);
  }
  next_.accept(std::move(block));
}

}  // namespace ncc::passes
