#include "transform_pass.h"

#include <type_traits>
#include <variant>

#include "absl/strings/str_cat.h"
#include "affine.h"

namespace ncc::passes {

namespace {

const char* planeCode(ir::Plane p) {
  return p == ir::Plane::XY ? "G17" : p == ir::Plane::ZX ? "G18" : "G19";
}

}  // namespace

TransformPass::TransformPass(ir::BlockSink& next, Dialect dialect, DiagnosticEngine& diags)
    : next_(next), table_(dialectTable(dialect)), diags_(diags) {}

void TransformPass::accept(ir::Block block) {
  if (!block.transform.any()) return next_.accept(std::move(block));
  const ir::Affine map = workSpaceMap(block.transform, block.frame.total());
  block.transform = {};
  for (ir::Operation& op : block.ops) {
    bool ok = true;
    std::visit(
        [&](auto& o) {
          using T = std::decay_t<decltype(o)>;
          if constexpr (std::is_same_v<T, ir::Rapid> || std::is_same_v<T, ir::Linear> ||
                        std::is_same_v<T, ir::Skip>) {
            if (o.space == ir::Space::Work) applyPoint(map, o.to);
          } else if constexpr (std::is_same_v<T, ir::Arc>) {
            if (o.space != ir::Space::Work) return;
            const auto image = arcImage(map, o.plane, o.clockwise, /*helical=*/true);
            if (!image) {
              ok = false;
              diags_.error(std::string(table_->alarm(Alarm::TransformArcNotCircle)), block.loc,
                           absl::StrCat("the ", planeCode(o.plane),
                                        " arc is no circle in a principal plane under the "
                                        "coordinate transform in force (unequal scaling in its "
                                        "plane, or a 3-D rotation that tilts it)"));
              return;
            }
            applyPoint(map, o.to);
            applyPoint(map, o.center);
            o.plane = image->plane;
            o.clockwise = image->clockwise;
          }
          // Machine-space moves (G53, reference returns) and non-motion operations stay.
        },
        op);
    if (!ok) return;  // the block is refused: nothing of it goes on
  }
  next_.accept(std::move(block));
}

}  // namespace ncc::passes
