// Mazak figure rotation (§13-7: M98 P H I J K L): the evaluator says when a rotated call starts,
// repeats and ends (eval::EvaluatorOptions::FigureRotationHooks, through Lowering); run k of the
// subprogram is turned by k times the angle the first run swept about start + I J K, as the
// FigureRotation stage of the transform map (docs/transforms.md).
#include <cmath>
#include <numbers>

#include "affine.h"
#include "lowering_context.h"

namespace ncc::passes {

bool figureRotationBegin(LoweringCore& core, const std::array<std::optional<double>, 3>& ijk) {
  ControllerState& cs = core.cs();
  TransformState& t = cs.transforms.edit();
  if (!t.rotations.empty()) return false;  // 850: "COMMANDE G68 AVEC M98"
  TransformState::FigureCall call;
  call.plane = cs.modal.plane;
  call.start_position = cs.position;
  const AxisValues total = frameOf(cs, core.table->behaviour).total();
  const auto sl = planeSlots(call.plane);
  for (int s = 0; s < 3; ++s) {
    const int i = core.xyz[s];
    if (i >= 0) call.start[s] = cs.position[i] - total[i];
  }
  call.centre = call.start;
  // I J in G17, K I in G18, J K in G19: the centre's offset from the start in the plane.
  for (int s : {sl[0], sl[1]})
    if (ijk[s]) call.centre[s] += *ijk[s];
  t.figure_call = call;
  t.figure.reset();
  return true;
}

void figureRotationRun(LoweringCore& core, int64_t run) {
  ControllerState& cs = core.cs();
  if (!cs.transforms->figure_call) return;
  TransformState& t = cs.transforms.edit();
  TransformState::FigureCall& call = *t.figure_call;
  const auto sl = planeSlots(call.plane);
  if (run == 1) {
    // The angle start - centre - end of the first run, counterclockwise positive.
    const AxisValues total = frameOf(cs, core.table->behaviour).total();
    double end[3] = {};
    for (int s = 0; s < 3; ++s)
      if (core.xyz[s] >= 0) end[s] = cs.position[core.xyz[s]] - total[core.xyz[s]];
    const double a0 = call.start[sl[0]] - call.centre[sl[0]], b0 = call.start[sl[1]] - call.centre[sl[1]];
    const double a1 = end[sl[0]] - call.centre[sl[0]], b1 = end[sl[1]] - call.centre[sl[1]];
    call.angle = std::atan2(a0 * b1 - b0 * a1, a0 * a1 + b0 * b1) * 180.0 / std::numbers::pi;
  }
  // The tool stays where the last run left it; the next run is programmed from the start again
  // (absolute programs repeat as written, incremental ones from the same point).
  const AxisValues at = imageOf(core, cs, cs.position);
  cs.position = call.start_position;
  Vec3 axis{};
  axis[sl[2]] = 1.0;
  t.figure = rotation(core.xyz, call.centre, axis, call.angle * static_cast<double>(run));
  t.tool_at = at;
}

void figureRotationEnd(LoweringCore& core) {
  ControllerState& cs = core.cs();
  if (!cs.transforms->figure_call) return;
  TransformState& t = cs.transforms.edit();
  // The programmed point becomes where the tool is: the next call or move starts there.
  cs.position = imageOf(core, cs, cs.position);
  t.figure_call.reset();
  t.figure.reset();
  t.tool_at.reset();
}

}  // namespace ncc::passes
