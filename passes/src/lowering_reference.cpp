// Reference points: G28 (return to reference point 1) and G30 P2-P4 (return to reference point
// 2-4), each via the programmed intermediate point, and the G27 reference position check.
// They move in machine coordinates and read the reference points from [machine.params], so
// they sit apart from ordinary motion; in some dialects a return also cancels the tool length.
#include <cmath>

#include "absl/strings/str_cat.h"
#include "affine.h"
#include "lowering_context.h"

namespace ncc::passes {

int referenceNumber(BlockContext& ctx, const GWord& g, int fallback) {
  if (!ctx.words.p) return fallback;
  ctx.used_p = true;
  auto n = ctx.integer(*ctx.words.p);
  if (!n) return fallback;
  if (*n >= 2 && *n <= 4) return static_cast<int>(*n);
  if (g.entry->action == GAction::ReferenceCheck && *n == 1) return 1;
  if (ctx.behaviour.g30_p == DialectBehaviour::G30P::OtherMeansSecond) return 2;
  ctx.fail(Alarm::ReferencePointNumber, ctx.words.p->loc,
           absl::StrCat("P", *n, ": ", gCodeName(g.entry->code10), " takes P2, P3 or P4"));
  return fallback;
}

// G28 / G30: rapid to the intermediate point, then the named axes to the reference point;
// both legs in machine coordinates (the frame would be wrong for the second).
void referenceReturn(BlockContext& ctx, const GWord&, int n) {
  if (ctx.failed) return;
  ir::Frame frame = frameOf(ctx.next, ctx.behaviour);
  // Mazak §13-10 5.5: the return ends scaling (the block's transforms are those after it).
  cancelScalingAfterReference(ctx);
  const AxisValues via_work = ctx.workTargets(ctx.baseWork());
  AxisValues via = ctx.toMachine(via_work, frame);
  const ir::Transform transform = transformOf(ctx);
  if (transform.any()) {
    // The intermediate point is a programmed point like any other (turned, mirrored): the
    // transform pass maps it; the way on to the reference point is in machine coordinates.
    const ir::Affine map = workSpaceMap(transform, frame.total());
    AxisValues image = via_work, here = ctx.baseWork();
    applyPoint(map, image);
    applyPoint(map, here);
    via = ctx.toMachine(image, frame);
    if (!ctx.samePosition(image, here))
      ctx.ops.push_back(ir::Rapid{via_work, ir::Space::Work, ctx.settings.rapid_type});
  } else if (!ctx.samePosition(via, ctx.next.position)) {
    ctx.ops.push_back(ir::Rapid{via, ir::Space::Machine, ctx.settings.rapid_type});
  }
  AxisValues home = via;
  for (int i = 0; i < ctx.axisCount(); ++i)
    if (ctx.words.axes[i]) home[i] = ctx.settings.reference[n - 1][i];
  if (!ctx.samePosition(home, via))
    ctx.ops.push_back(ir::Rapid{home, ir::Space::Machine, ir::RapidType::PerAxis});
  ctx.next.position = programmedAt(ctx, home);
  ctx.lengthChangeTraversed();
  // The length offset is cancelled in the axis returned (Mazak §14: "length offset cancelled
  // in that axis"): only when the length axis is among the named axes.
  int axis = ctx.next.tool_length_axis;
  if (ctx.behaviour.reference_return_cancels_length && axis >= 0 && axis < ctx.axisCount() &&
      ctx.words.axes[axis] && ctx.next.modal.length_offset_sign != 0) {
    ctx.next.modal.length_offset_sign = 0;
    ctx.next.modal.length_offset_h = 0;
    ctx.next.tool_length_axis = -1;
    ctx.next.tool_length = 0.0;
  }
}

void referenceCheck(BlockContext& ctx, const GWord& g) {
  int n = referenceNumber(ctx, g, 1);
  if (ctx.failed) return;
  ir::Frame frame = frameOf(ctx.next, ctx.behaviour);
  AxisValues target = ctx.workTargets(ctx.baseWork());
  AxisValues image = target;  // where the tool goes: the programmed point under the transforms
  if (const ir::Transform t = transformOf(ctx); t.any())
    applyPoint(workSpaceMap(t, frame.total()), image);
  AxisValues reached = ctx.toMachine(image, frame);
  for (int i = 0; i < ctx.axisCount(); ++i) {
    if (!ctx.words.axes[i]) continue;
    double ref = ctx.settings.reference[n - 1][i];
    if (std::fabs(reached[i] - ref) > kPositionCheck) {
      ctx.fail(Alarm::ReferenceCheckFailed, ctx.words.axes[i]->loc,
               absl::StrCat("G27: ", ctx.core.machine->axes[i].name, " reaches machine position ",
                            mm(reached[i]), ", not reference point ", n, " (", mm(ref), ")"));
      return;
    }
  }
  if (!ctx.samePosition(reached, ctx.next.position))
    ctx.ops.push_back(ir::Rapid{target, ir::Space::Work, ctx.settings.rapid_type});
  ctx.ops.push_back(ir::ReferenceCheck{reached, ctx.namedAxes(), n});
  ctx.next.position = ctx.toMachine(target, frame);
  ctx.lengthChangeTraversed();
}

}  // namespace ncc::passes
