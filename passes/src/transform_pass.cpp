#include "transform_pass.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "absl/strings/str_cat.h"
#include "affine.h"
#include "ncc/ir/printer.h"
#include "ncc/ir/visit.h"

namespace ncc::passes {

TransformPass::TransformPass(ir::BlockSink& next, Dialect dialect, DiagnosticEngine& diags)
    : next_(next), table_(dialectTable(dialect)), diags_(diags) {}

void TransformPass::accept(ir::Block&& block) {
  const AxisValues total = block.frame.total();
  // Where the tool ends (machine coordinates): an arc's start, for the check below.
  auto track = [&](const AxisValues& to, ir::Space space) {
    last_ = to;
    if (space == ir::Space::Work)
      for (int i = 0; i < kMaxAxes; ++i) (*last_)[i] += total[i];
  };
  const bool any = block.transform.any();
  const ir::Affine map = any ? workSpaceMap(block.transform, total) : ir::Affine{};
  block.transform = {};
  for (ir::Operation& op : block.ops) {
    bool ok = true;
    auto point = [&](AxisValues& to, ir::Space space) {
      if (any && space == ir::Space::Work) applyPoint(map, to);
      track(to, space);
    };
    std::visit(ir::Overloaded{
                   [&](ir::Rapid& o) { point(o.to, o.space); },
                   [&](ir::Linear& o) { point(o.to, o.space); },
                   [&](ir::Skip& o) { point(o.to, o.space); },
                   [&](ir::Arc& o) {
                     if (any && o.space == ir::Space::Work) ok = mapArc(block, map, o);
                     track(o.to, o.space);
                   },
                   // Expanded into moves by the cycles pass, which runs first; a machine
                   // position, checked as reached: no transform applies.
                   ir::Leave<ir::HoleCycle, ir::ReferenceCheck>{},
                   ir::NoPoint{},
               },
               op);
    if (!ok) return;  // the block is refused: nothing of it goes on
  }
  next_.accept(std::move(block));
}

// The lowering checked the arcs it made (arcUnderTransforms); an arc the corners pass inserted
// is checked here: it must stay a circle from where the tool is.
bool TransformPass::mapArc(const ir::Block& block, const ir::Affine& map, ir::Arc& arc) {
  const auto image = arcImage(map, arc.plane, arc.clockwise, /*helical=*/true);
  const bool similar = arcImage(map, arc.plane, arc.clockwise, true, true).has_value();
  AxisValues end = arc.to, centre = arc.center;
  applyPoint(map, end);
  applyPoint(map, centre);
  bool circle = image.has_value();
  if (circle && !similar && last_) {
    AxisValues start = *last_;  // machine coordinates: into work space, as `end` and `centre`
    const AxisValues total = block.frame.total();
    for (int i = 0; i < kMaxAxes; ++i) start[i] -= total[i];
    const double r0 = planeDistance(map, image->plane, start, centre);
    const double r1 = planeDistance(map, image->plane, end, centre);
    circle = std::fabs(r0 - r1) <= 1e-6 * std::max(1.0, r1);
  }
  if (!circle) {
    diags_.error(std::string(table_->alarm(Alarm::TransformArcNotCircle)), block.loc,
                 absl::StrCat("the ", ir::planeCode(arc.plane),
                              " arc is no circle in a principal plane under the coordinate "
                              "transform in force (unequal scaling in its plane, or a 3-D "
                              "rotation that tilts it)"));
    return false;
  }
  arc.to = end;
  arc.center = centre;
  arc.plane = image->plane;
  arc.clockwise = image->clockwise;
  return true;
}

}  // namespace ncc::passes
