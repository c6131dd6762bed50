// Error recovery: one root cause, one diagnostic. A rejected block did not run, but the real
// control would have run it (or stopped): the axes it names and the modal groups of its codes
// are then not known (UnknownState). A later block whose judgement needs one of them is
// lowered silently: its errors would be consequences of the first, not faults of its own.
// Its own words determine state again where they fully can (a modal code its group, F the
// feed, an absolute axis word the axis). After an error nothing is emitted anyway (the run
// has one verdict), so this only decides which diagnostics are shown.
#include <cmath>

#include "lowering_context.h"

namespace ncc::passes {

namespace {

using U = UnknownState;

// Groups whose code moves the work coordinate system: every axis's work position follows.
bool movesFrame(GGroup g) {
  switch (g) {
    case GGroup::WorkOffset:
    case GGroup::Rotation:
    case GGroup::Scaling:
    case GGroup::Mirror:
    case GGroup::Polar:
    case GGroup::PolarInterpolation:
      return true;
    default:
      return false;
  }
}

AxisMask allAxes() { return static_cast<AxisMask>((1u << kMaxAxes) - 1); }

// The axis carrying the tool length: the one in use, else Z.
AxisMask lengthAxis(const ControllerState& cs, const MachineConfig& machine) {
  int axis = cs.tool_length_axis >= 0 ? cs.tool_length_axis : machine.axisIndex("Z");
  return axis >= 0 && axis < kMaxAxes ? static_cast<AxisMask>(1u << axis) : AxisMask{0};
}

// Modal groups the block sets (after the same-group policy).
uint32_t carriedGroups(const DecodedBlock& words) {
  uint32_t groups = 0;
  for (size_t g = 0; g < words.modal.size(); ++g)
    if (words.modal[g]) groups |= 1u << g;
  return groups;
}

}  // namespace

void forgetRejected(ControllerState& cs, const ast::Block& block, const DialectTable& table,
                    const MachineConfig& machine) {
  U& u = cs.unknown;
  for (const ast::Word& w : block.words) {
    if (w.address == "G") {
      const GCodeEntry* e = nullptr;
      double v = w.value.number;
      if (w.value.isLiteral() && v >= 0 && v < 10000 &&
          std::fabs(v * 10.0 - std::round(v * 10.0)) < 1e-6)
        e = table.findG(static_cast<int>(std::lround(v * 10.0)));
      if (!e) {
        // A code the table does not know (or a computed one): which group it would have
        // changed, if any, is not known.
        u.groups = ~0u;
        u.axes = allAxes();
        continue;
      }
      if (e->group == GGroup::OneShot) continue;  // its axis words are what it changes
      u.groups |= U::groupBit(e->group);
      if (movesFrame(e->group)) u.axes = allAxes();
      if (e->group == GGroup::LengthComp) u.axes |= lengthAxis(cs, machine);
    } else if (w.address == "F") {
      u.feed = true;
    } else if (w.address == "H") {
      u.axes |= lengthAxis(cs, machine);
    } else if (w.address.size() == 1) {
      int axis = machine.axisIndex(w.address);
      if (axis >= 0 && axis < kMaxAxes) u.axes |= static_cast<AxisMask>(1u << axis);
    }
  }
}

void forgetEverything(ControllerState& cs) {
  cs.unknown.axes = allAxes();
  cs.unknown.groups = ~0u;
  cs.unknown.feed = true;
}

namespace {

// Whether the block's motion (or one-shot code) is judged against unknown state.
bool motionDepends(const BlockContext& ctx, const U& before, uint32_t groups) {
  auto unknown = [&](GGroup g) { return (groups & U::groupBit(g)) != 0; };
  const DecodedBlock& w = ctx.words;
  bool axes = w.anyAxis();
  if (w.one_shot) {
    if (isDwell(w.one_shot->entry->action)) return false;  // its X is a time
    // G28/G30/G92/G52/G53/G10 with axis words: relative to the position or a frame.
    return axes && (unknown(GGroup::Distance) || (before.axes & ctx.namedAxes()) != 0);
  }
  bool centre = w.i || w.j || w.k || w.r;
  if (!axes && !centre) return false;
  if (unknown(GGroup::Motion)) return true;
  if (axes && unknown(GGroup::Distance)) return true;
  GAction kind = ctx.next.motion;
  bool arc = kind == GAction::ArcCW || kind == GAction::ArcCCW;
  if (kind == GAction::Linear || arc) {
    if (unknown(GGroup::FeedMode)) return true;
    if (before.feed && !w.f) return true;
  }
  if (arc) {
    if (unknown(GGroup::Plane)) return true;
    // The arc's start point (and its end on an axis not named) in the plane.
    ir::Plane plane = ctx.next.modal.plane;
    int a = ctx.axisNamed(plane == ir::Plane::ZX ? "Z" : plane == ir::Plane::YZ ? "Y" : "X");
    int b = ctx.axisNamed(plane == ir::Plane::ZX ? "X" : plane == ir::Plane::YZ ? "Z" : "Y");
    for (int axis : {a, b})
      if (axis >= 0 && axis < kMaxAxes && (before.axes & (1u << axis))) return true;
  }
  return false;
}

}  // namespace

Dependence dependsOnUnknown(const BlockContext& ctx) {
  const U& before = ctx.core.cs().unknown;
  if (!before.any()) return {};
  const DecodedBlock& w = ctx.words;
  uint32_t groups = before.groups & ~carriedGroups(w);
  auto unknown = [&](GGroup g) { return (groups & U::groupBit(g)) != 0; };
  // Every value is read in the units in force (its format too); where a length-offset change
  // is allowed only in G00/G01 (Siemens) it is judged against the motion mode.
  bool values = w.anyAxis() || w.i || w.j || w.k || w.r || w.f;
  if ((unknown(GGroup::Units) && values) ||
      (unknown(GGroup::Motion) && ctx.behaviour.length_comp_in_arc_is_error &&
       (w.h || w.group(GGroup::LengthComp))))
    return {.words = true, .motion = true};
  return {.words = false, .motion = motionDepends(ctx, before, groups)};
}

void relearn(BlockContext& ctx) {
  U& u = ctx.next.unknown;
  if (!u.any()) return;
  const DecodedBlock& w = ctx.words;
  u.groups &= ~carriedGroups(w);
  if (w.f && !ctx.failed) u.feed = false;
  if (w.one_shot) {
    // A skipped G28/G92/G52 ... leaves its axes unknown; a lowered one named none unknown.
    if (ctx.silent && !isDwell(w.one_shot->entry->action)) u.axes |= ctx.namedAxes();
    return;
  }
  bool values_known = !u.group(GGroup::Units);
  bool modes_known = !u.group(GGroup::Distance);
  AxisValues target{};
  if (ctx.silent) {
    ir::Frame frame = frameOf(ctx.next, ctx.behaviour);
    target = ctx.toMachine(ctx.workTargets(ctx.baseWork()), frame);
  }
  for (int i = 0; i < ctx.axisCount(); ++i) {
    if (!w.axes[i]) continue;
    auto bit = static_cast<AxisMask>(1u << i);
    bool absolute = values_known && modes_known && w.axes[i]->mode == ir::DistanceMode::Absolute;
    if (!absolute) {
      // Incremental from an unknown point, or read in unknown units or mode.
      if (ctx.silent || !modes_known || !values_known) u.axes |= bit;
      continue;
    }
    // An absolute word fixes the axis. A lowered block has set the position already; a
    // silent one may have stopped before (an arc from an unknown start): the work target
    // under the frame in force. An unknown frame is unknown alike for start and end, so
    // work positions (what later blocks are judged by) come out right.
    if (ctx.silent) ctx.next.position[i] = target[i];
    u.axes &= static_cast<AxisMask>(~bit);
  }
}

}  // namespace ncc::passes
