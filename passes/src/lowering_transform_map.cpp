// The transforms in force as one map, and the tool under it: transformOf composes the stages of
// TransformState in the dialect's order (TransformRules::order); the rest keeps the programmed
// point (ControllerState::position) and the point the tool is at (TransformState::tool_at)
// apart, so that a block moves when either changes, an arc is checked from where the tool
// really is, and a move given in machine coordinates is taken back to a programmed point.
#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "affine.h"
#include "lowering_context.h"

namespace ncc::passes {

using Stage = TransformRules::Stage;
ir::Transform transformOf(const BlockContext& ctx) { return transformOf(ctx.core, ctx.next); }

ir::Transform transformOf(const BlockContext& ctx, const ControllerState& cs) {
  return transformOf(ctx.core, cs);
}

ir::Transform transformOf(const LoweringCore& core, const ControllerState& cs) {
  ir::Transform out;  // one object for every return: `return {}` zeroed it first
  const TransformRules* rules = core.table->transforms;
  const TransformState& t = *cs.transforms;
  // Nothing in force (nearly every block of a program): nothing to compose.
  if (!rules || !t.inForce()) return out;
  const std::array<int8_t, 3>& xyz = core.xyz;
  if (t.work_rotation) out.machine = *t.work_rotation;
  if (!t.figure && !t.programmable && !t.mirrorsAny() && !t.scaling && t.rotations.empty())
    return out;
  ir::Affine map = t.programmable ? *t.programmable : identityAffine(xyz);
  for (Stage stage : rules->order) {
    switch (stage) {
      case Stage::FigureRotation:
        if (t.figure) map = compose(*t.figure, map);
        break;
      case Stage::Mirror:
        if (t.mirrorsAny()) {
          Vec3 f{1, 1, 1};
          for (int s = 0; s < 3; ++s)
            if (t.mirrored[s]) f[s] = -1.0;
          map = compose(scaling(xyz, t.mirror_centre, f), map);
        }
        break;
      case Stage::Scaling:
        if (t.scaling) {
          Vec3 f{1, 1, 1};
          for (int s = 0; s < 3; ++s)
            if (t.scaled[s]) f[s] = t.scale_factor[s];
          map = compose(scaling(xyz, t.scale_centre, f), map);
        }
        break;
      case Stage::Rotation: {
        // The first rotation acts last: the second is given in the first's coordinates.
        ir::Affine r = identityAffine(xyz);
        for (const ir::Affine& each : t.rotations) r = compose(r, each);
        map = compose(r, map);
        break;
      }
    }
  }
  if (!isIdentity(map)) out.work = map;
  return out;
}

// The machine point the tool goes to for the programmed point `position` (machine coordinates
// of the programmed point, ControllerState::position) under the state's transforms.
AxisValues imageOf(const LoweringCore& core, const ControllerState& cs, const AxisValues& position) {
  if (!cs.transforms->inForce()) return position;
  const ir::Transform t = transformOf(core, cs);
  if (!t.any()) return position;
  AxisValues image = position;
  applyPoint(machineSpaceMap(t, frameOf(cs, core.table->behaviour).total()), image);
  return image;
}

bool movesUnderTransforms(const BlockContext& ctx, const AxisValues& target, bool moves) {
  const std::optional<AxisValues>& tool_at = ctx.core.cs().transforms->tool_at;
  // A block without axis words moves nothing, whatever changed (G69 or G50 alone).
  if (!ctx.words.anyAxis() || (!tool_at && !transformOf(ctx).any())) return moves;
  const AxisValues total = frameOf(ctx.next, ctx.behaviour).total();
  AxisValues to = target;
  for (int i = 0; i < ctx.axisCount(); ++i) to[i] += total[i];
  return !ctx.samePosition(tool_at ? *tool_at : ctx.core.cs().position, imageOf(ctx.core, ctx.next, to));
}

bool arcUnderTransforms(BlockContext& ctx, const ir::Arc& arc) {
  const std::optional<AxisValues>& tool_at = ctx.core.cs().transforms->tool_at;
  const ir::Transform after = transformOf(ctx);
  if (!tool_at && !after.any()) return true;
  const AxisValues total = frameOf(ctx.next, ctx.behaviour).total();
  const ir::Affine map = workSpaceMap(after, total);
  const auto image = arcImage(map, arc.plane, arc.clockwise, /*helical=*/true);
  if (!image) {
    ctx.fail(Alarm::TransformArcNotCircle, ctx.motionLoc(),
             "the arc would leave the principal planes under the coordinate transform in force "
             "(a 3-D rotation tilts its plane)");
    return false;
  }
  AxisValues start = tool_at ? *tool_at : ctx.core.cs().position, end = arc.to, centre = arc.center;
  for (int i = 0; i < ctx.axisCount(); ++i) start[i] -= total[i];
  applyPoint(map, end);
  applyPoint(map, centre);
  const double r0 = planeDistance(map, image->plane, start, centre);
  const double r1 = planeDistance(map, image->plane, end, centre);
  if (std::fabs(r0 - r1) <= ctx.settings.arc_tolerance) return true;
  const bool similar = arcImage(map, arc.plane, arc.clockwise, false, /*similarity=*/true).has_value();
  if (!similar)
    ctx.fail(Alarm::TransformArcNotCircle, ctx.motionLoc(),
             absl::StrCat("under unequal scaling in its plane the arc is no circle: radius ",
                          mm(r0), " at the start, ", mm(r1), " at the end"));
  else
    ctx.fail(Alarm::ArcRadiusMismatch, ctx.motionLoc(),
             absl::StrCat("the arc starts off its circle (radius ", mm(r0), " at the start, ",
                          mm(r1), " at the end): a coordinate transform changed since the last "
                          "move; give an absolute G00/G01 move first"));
  return false;
}

void trackTool(BlockContext& ctx) {
  if (!ctx.table.transforms) return;
  bool moved = false;
  for (const ir::Operation& op : ctx.ops)
    moved = moved || ir::isMove(op) || std::holds_alternative<ir::HoleCycle>(op);
  if (!moved || (!ctx.next.transforms->inForce() && !ctx.next.transforms->tool_at)) return;
  const AxisValues at = imageOf(ctx.core, ctx.next, ctx.next.position);
  // Written only when it changes: the transform state is shared until written.
  if (!ctx.samePosition(at, ctx.next.position))
    ctx.next.transforms.edit().tool_at = at;
  else if (ctx.next.transforms->tool_at)
    ctx.next.transforms.edit().tool_at.reset();
}

AxisValues programmedAt(const BlockContext& ctx, const AxisValues& machine) {
  return programmedAt(ctx.core, ctx.next, machine);
}

AxisValues programmedAt(const LoweringCore& core, const ControllerState& cs, const AxisValues& machine) {
  const ir::Transform tr = transformOf(core, cs);
  if (!tr.any()) return machine;
  const auto inv = inverse(machineSpaceMap(tr, frameOf(cs, core.table->behaviour).total()));
  if (!inv) return machine;
  AxisValues programmed = machine;
  applyPoint(*inv, programmed);
  return programmed;
}

}  // namespace ncc::passes
