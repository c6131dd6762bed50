// Cutter radius compensation as lowering sees it (docs/semantics.md, "Cutter compensation: what
// lowering records"): G40/G41/G42 with D, G38/G39 and the I J K vectors are checked against the
// compensation in force and recorded on the block as an ir::CutterComp, which the
// `compensation` pass turns into the tool centre's path. Nothing here moves the tool: the
// block's programmed moves are lowered as usual (a G39 block has none). What differs between
// the dialects is in their CompRules and the machine's parameters (LoweringSettings::comp_*).
#include <cmath>

#include "absl/strings/str_cat.h"
#include "lowering_context.h"

namespace ncc::passes {

namespace {

using Side = ir::CutterComp::Side;
using Special = ir::CutterComp::Special;

const char* sideCode(Side s) { return s == Side::Left ? "G41" : s == Side::Right ? "G42" : "G40"; }

bool arcMode(GAction a) { return a == GAction::ArcCW || a == GAction::ArcCCW; }

const char* planeCode(ir::Plane p) {
  return p == ir::Plane::XY ? "G17" : p == ir::Plane::ZX ? "G18" : "G19";
}

// The plane's two I J K addresses (G17 I J, G18 K I, G19 J K), as slots 0 1 2 = I J K.
std::array<bool, 3> planeSlots(ir::Plane p) {
  switch (p) {
    case ir::Plane::XY: return {true, true, false};
    case ir::Plane::ZX: return {true, false, true};
    case ir::Plane::YZ: return {false, true, true};
  }
  return {true, true, false};
}

// The radius register `d` (geometry + wear) with this block's G10 writes to it applied: the
// vector at the block's end uses the offset given in the block (FANUC §5.4, Mazak §12-4-6 2.).
double radiusOf(const LoweringCore& core, const std::vector<TableWrite>* writes, int d) {
  auto valueIn = [d](const std::map<int, double>& m) {
    auto it = m.find(d);
    return it == m.end() ? 0.0 : it->second;
  };
  double geometry = valueIn(core.tables.radius), wear = valueIn(core.tables.radius_wear);
  if (writes) {
    for (const TableWrite& w : *writes) {
      if (w.number != d) continue;
      if (w.target == TableWrite::Target::Radius)
        geometry = w.add ? geometry + w.values[0] : w.values[0];
      if (w.target == TableWrite::Target::RadiusWear)
        wear = w.add ? wear + w.values[0] : w.values[0];
    }
  }
  return geometry + wear;
}

// The record of the compensation in force in `cs` (side, D, radius, the 3-D offset, the rules).
ir::CutterComp recordOf(const LoweringCore& core, const ControllerState& cs,
                        const std::vector<TableWrite>* writes) {
  const LoweringSettings& s = core.settings;
  const CompRules& rules = *core.table->comp;
  ir::CutterComp c;
  c.side = cs.comp.side;
  c.d_number = cs.d_selected;
  c.radius = radiusOf(core, writes, cs.d_selected);
  if (cs.comp.direction_3d && c.side != Side::Off) {
    std::array<double, 3> v = *cs.comp.direction_3d;
    for (double& x : v) x = x * c.radius + 0.0;  // + 0.0: no -0 for a zero radius
    c.offset_3d = v;
  }
  c.startup = s.comp_startup;
  c.arc_corners = s.comp_arc_corners;
  c.lookahead = s.comp_lookahead;
  c.max_without_motion = s.comp_max_without_motion;
  c.interference_check = s.comp_interference_check;
  c.interference_avoidance = s.comp_interference_avoidance;
  c.corner_move_limit = s.comp_corner_move_limit;
  c.recommand_perpendicular = rules.same_side_recommand_counts;
  c.side_change_perpendicular = rules.side_change_perpendicular;
  // The plane's machine axes (first, second, normal), as an arc in it takes them; -1: none.
  static constexpr int kSlots[][3] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};  // XY, ZX, YZ of X Y Z
  const int* slots = kSlots[static_cast<int>(cs.modal.plane)];
  c.plane_a = core.xyz[slots[0]];
  c.plane_b = core.xyz[slots[1]];
  c.plane_normal = core.xyz[slots[2]];
  return c;
}

// I J K (slots 0 1 2) as a work-space vector on X Y Z (mm), from the slots `use`; claims the
// block's I J K. nullopt after reporting: a word outside `use` (the plane's third address) has
// no meaning, and a zero vector gives no direction.
std::optional<std::array<double, 3>> vectorOf(BlockContext& ctx, std::array<bool, 3> use,
                                              const char* what) {
  const std::optional<WordValue>* words[3] = {&ctx.words.i, &ctx.words.j, &ctx.words.k};
  std::array<double, 3> v{};
  std::optional<SourceLocation> loc;
  ctx.used_ijk = true;
  for (int n = 0; n < 3; ++n) {
    if (use[n] || !*words[n]) continue;
    const char* kPlaneWords[] = {"J K", "I K", "I J"};  // by the slot left out
    const int out = !use[0] ? 0 : !use[1] ? 1 : 2;
    ctx.fail(Alarm::AddressWithoutMeaning, (*words[n])->loc,
             absl::StrCat("address ", std::string((*words[n])->address), " has no meaning in ",
                          planeCode(ctx.next.modal.plane), ": the vector of ", what, " is ",
                          kPlaneWords[out]));
    return std::nullopt;
  }
  for (int n = 0; n < 3; ++n) {
    if (!use[n] || !*words[n]) continue;
    v[n] = ctx.lengthValue(**words[n]);
    if (!loc) loc = (*words[n])->loc;
  }
  if (std::hypot(v[0], v[1], v[2]) <= kSamePoint) {
    ctx.fail(Alarm::ValueOutOfRange, *loc,
             absl::StrCat("the I J K vector of ", what, " is zero: it gives no direction"));
    return std::nullopt;
  }
  return v;
}

// Whether the block has one of the I J K words of the slots `use`.
bool hasPlaneVector(const BlockContext& ctx, std::array<bool, 3> use) {
  const std::optional<WordValue>* words[3] = {&ctx.words.i, &ctx.words.j, &ctx.words.k};
  for (int n = 0; n < 3; ++n)
    if (use[n] && *words[n]) return true;
  return false;
}

// The checks of the block against the compensation in force (before it: `was`, after its
// G40/G41/G42 and D: `now`). Reports the first fault.
void checkBlock(BlockContext& ctx, const CompRules& rules, Side was, Side now,
                const std::optional<GWord>& code) {
  const ControllerState& before = ctx.core.cs();
  const bool startup = was == Side::Off && now != Side::Off;
  const bool cancel = was != Side::Off && now == Side::Off;
  const bool one_shot = ctx.words.one_shot.has_value();
  SourceLocation at = code ? code->loc : ctx.words.d ? ctx.words.d->loc : ctx.block.loc;
  // Start-up and cancel only in G00/G01 (FANUC PS0034, Mazak 835, Siemens §3.5.3).
  if ((startup || (cancel && rules.cancel_in_arc_is_error)) && arcMode(ctx.next.motion) &&
      !one_shot && !inCycle(ctx)) {
    const char* mode = ctx.next.motion == GAction::ArcCW ? "G02" : "G03";
    std::string what = code ? gCodeName(code->entry->code10) : std::string("D0");
    ctx.fail(Alarm::CompStartInArc, at,
             absl::StrCat(what, startup ? " starts" : " cancels",
                          " cutter compensation in ", mode,
                          " mode: the start-up and the cancel must be G00 or G01 blocks"));
    return;
  }
  // The plane while compensating (FANUC PS0037, Siemens §3.5.3); the start-up block may choose
  // it (Siemens: "in or before the G41 block").
  if (was != Side::Off && ctx.next.modal.plane != before.modal.plane) {
    const auto& g = ctx.words.group(GGroup::Plane);
    ctx.fail(Alarm::CompPlaneChange, g ? g->loc : ctx.block.loc,
             absl::StrCat(planeCode(ctx.next.modal.plane), " changes the plane from ",
                          planeCode(before.modal.plane), " while cutter compensation (",
                          sideCode(was),
                          ") is in force; cancel it with G40 first"));
    return;
  }
  // G41 <-> G42 in the start-up block's successor (FANUC §5.4, Mazak §12-4-3 3.).
  if (rules.side_change_early_is_error && was != Side::Off && now != Side::Off && was != now &&
      before.comp.blocks < 2) {
    ctx.fail(Alarm::CompSideChangeEarly, at,
             absl::StrCat(sideCode(now), " changes the compensation side in the block after the ",
                          sideCode(was),
                          " start-up: the side may change from the third compensated block on"));
    return;
  }
  if (now == Side::Off || !one_shot) return;
  const GWord& g = *ctx.words.one_shot;
  if (g.entry->action == GAction::Skip && rules.skip_is_error) {
    ctx.fail(Alarm::CompSkip, g.loc,
             absl::StrCat(gCodeName(g.entry->code10), " (skip) is not allowed while ",
                          sideCode(now), " cutter compensation is in force"));
    return;
  }
  if ((g.entry->action == GAction::ReferenceReturn ||
       g.entry->action == GAction::ReferenceReturnN) &&
      rules.reference_return_is_error) {
    ctx.fail(Alarm::CompReferenceReturn, g.loc,
             absl::StrCat(gCodeName(g.entry->code10), " (reference return) is not allowed while ",
                          sideCode(now), " cutter compensation is in force; cancel it with G40"));
  }
}

// G38 / G39: the one-shot special and, where the dialect reads one, its vector. In an arc
// block (`arc`: G38 X Y in G02/G03 mode) I J K stay the arc's centre.
void special(BlockContext& ctx, const CompRules& rules, bool arc, ir::CutterComp& c) {
  const GWord& g = *ctx.words.comp_special;
  const std::array<bool, 3> plane = planeSlots(ctx.next.modal.plane);
  if (g.entry->action == GAction::CompCornerArc) {
    c.special = Special::CornerArc;
    for (int i = 0; i < ctx.axisCount(); ++i) {
      if (!ctx.words.axes[i]) continue;
      ctx.fail(Alarm::CompCornerArcMove, ctx.words.axes[i]->loc,
               absl::StrCat("G39 (corner arc) cannot move: address ", std::string(ctx.words.axes[i]->address),
                            " is not allowed in its block"));
      return;
    }
    if (hasPlaneVector(ctx, plane)) c.vector = vectorOf(ctx, plane, "G39");
    return;
  }
  c.special = Special::VectorHold;
  if (rules.vector_with_hold && !arc && hasPlaneVector(ctx, plane))
    c.vector = vectorOf(ctx, plane, "G38");
}

}  // namespace

bool cornerArcBlock(const BlockContext& ctx) {
  return ctx.words.comp_special && ctx.words.comp_special->entry->action == GAction::CompCornerArc;
}

void applyCutterComp(BlockContext& ctx) {
  const CompRules* rules = ctx.table.comp;
  if (!rules || ctx.failed) return;
  CompState& state = ctx.next.comp;
  const Side was = ctx.core.cs().comp.side;
  const auto& code = ctx.words.group(GGroup::CutterComp);
  Side now = was;
  if (code)
    now = code->entry->action == GAction::CompLeft    ? Side::Left
          : code->entry->action == GAction::CompRight ? Side::Right
                                                      : Side::Off;
  // Mazak: D00 cancels (and G41 with D0 in force starts nothing: "0 < D" is a start-up condition).
  if (rules->d_zero_cancels && ctx.next.d_selected == 0) now = Side::Off;
  checkBlock(ctx, *rules, was, now, code);
  if (ctx.failed) return;

  const bool cycle = inCycle(ctx);
  const bool arc = arcMode(ctx.next.motion) && !ctx.words.one_shot && !cycle;
  const std::array<bool, 3> plane = planeSlots(ctx.next.modal.plane);
  const bool all3 = ctx.words.i && ctx.words.j && ctx.words.k;
  // Mazak 835: 3-D compensation starts or changes only in G00/G01 (I J K of an arc are its).
  if (rules->has_3d && all3 && arc && code && now != Side::Off) {
    ctx.fail(Alarm::CompStartInArc, code->loc,
             absl::StrCat(sideCode(now), " with I J K (3-D compensation) in ",
                          ctx.next.motion == GAction::ArcCW ? "G02" : "G03",
                          " mode: 3-D compensation starts and changes in G00 or G01 blocks"));
    return;
  }
  // G40 in cancel mode: its I J K are ignored (FANUC §5.2 "in cancel mode I/K with G40 are
  // ignored"), and nothing is recorded.
  if (was == Side::Off && now == Side::Off) {
    if (code && rules->vector_with_cancel && !arc && !cycle && hasPlaneVector(ctx, plane))
      ctx.used_ijk = true;
    if (ctx.words.comp_special && !ctx.silent)
      ctx.core.diags.warning(
          std::string(ctx.table.alarm(Alarm::AddressWithoutMeaning)), ctx.words.comp_special->loc,
          absl::StrCat(gCodeName(ctx.words.comp_special->entry->code10),
                       " has no effect outside cutter compensation (G41/G42)"));
    state = CompState{};
    return;
  }

  ir::CutterComp c;
  if (now != Side::Off && code && code->entry->action != GAction::CompCancel)
    c.side_commanded = was != now || rules->same_side_recommand_counts;
  // Mazak 3-D compensation: G41/G42 with all of I J K (§12-4, "otherwise 2-D").
  if (now == Side::Off) {
    state.direction_3d.reset();
  } else if (rules->has_3d && c.side_commanded && all3 && !arc && !cycle) {
    auto v = vectorOf(ctx, {true, true, true}, sideCode(now));
    if (!v) return;
    const double length = ctx.settings.comp3d_normal_length > 0.0
                              ? ctx.settings.comp3d_normal_length
                              : std::hypot((*v)[0], (*v)[1], (*v)[2]);
    const double sign = now == Side::Left ? 1.0 : -1.0;
    for (double& x : *v) x *= sign / length;
    state.direction_3d = v;
  } else if (was != now && was != Side::Off && state.direction_3d) {
    for (double& x : *state.direction_3d) x = -x;  // a side change in 3-D: the other way
  }
  if (ctx.words.comp_special) {
    special(ctx, *rules, arc, c);
    if (ctx.failed) return;
  } else if (!arc && !cycle && !ctx.used_ijk && hasPlaneVector(ctx, plane)) {
    const bool vector = now == Side::Off ? rules->vector_with_cancel
                                         : rules->vector_with_motion && !ctx.words.one_shot;
    if (vector) {
      c.vector = vectorOf(ctx, plane, now == Side::Off ? "G40" : sideCode(now));
      if (ctx.failed) return;
    }
  }
  if (was == Side::Off) state.blocks = 0;
  state.side = now;
  if (now == Side::Off) state = CompState{};
  c.loc = code                                          ? code->loc
          : ctx.words.comp_special                      ? ctx.words.comp_special->loc
          : (now == Side::Off && ctx.words.d)           ? ctx.words.d->loc
                                                        : ctx.block.loc;
  ctx.comp = c;
}

void finishCutterComp(BlockContext& ctx, bool program_end) {
  if (!ctx.comp || ctx.failed) return;
  const CompRules& rules = *ctx.table.comp;
  // The record in force after the block (side, D, its radius with this block's G10 writes,
  // the 3-D offset, the rules), with what the block's own words said.
  ir::CutterComp c = recordOf(ctx.core, ctx.next, &ctx.table_writes);
  c.side_commanded = ctx.comp->side_commanded;
  c.special = ctx.comp->special;
  c.vector = ctx.comp->vector;
  c.loc = ctx.comp->loc;
  for (const ir::Operation& op : ctx.ops) {
    if (!std::holds_alternative<ir::HoleCycle>(op)) continue;
    // A hole cycle runs on the programmed points (FANUC, Siemens "compensation is ignored in
    // canned-cycle mode"); Mazak 901 in 3-D compensation.
    if (rules.cycle_in_3d_is_error && ctx.next.comp.direction_3d) {
      const auto& g = ctx.words.group(GGroup::Cycle);
      ctx.fail(Alarm::CompInCycle, g ? g->loc : ctx.motionLoc(),
               "a hole cycle is not allowed in 3-D cutter compensation; cancel it with G40");
      return;
    }
    c.suspended = true;
  }
  ctx.comp = c;
  if (c.side != Side::Off) ++ctx.next.comp.blocks;
  // M02/M30 reset the control: G40 (the vector is cleared after the block).
  if (program_end) ctx.next.comp = CompState{};
}

std::optional<ir::CutterComp> compensationInForce(const LoweringCore& core,
                                                  const ControllerState& cs, SourceLocation loc) {
  if (!core.table || !core.table->comp || !cs.comp.active()) return std::nullopt;
  ir::CutterComp c = recordOf(core, cs, nullptr);
  c.loc = loc;
  return c;
}

}  // namespace ncc::passes
