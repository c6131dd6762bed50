// Canned hole cycles (G73-G89), their cancel G80 and the return level G98/G99: the cycle words
// of a block into the modal cycle data (ControllerState::cycle), and one ir::HoleCycle per hole
// for the `cycles` pass (cycle_expansion.cpp) to expand. What differs between the dialects
// (which codes, the repeat address, P's unit, alarms, the positioning move) is the dialect's
// CycleRules; docs/cycles.md documents the rules below with their manual sections.
//
// The rules common to the three manuals (Mazak §13-1-3, Siemens ISO §4.1, FANUC-family):
//  - the initial level is the drilling-axis position at the first cycle block (after G80);
//  - R in G90 is a level, in G91 the distance from the initial level; Z in G90 is the bottom,
//    in G91 the distance from R;
//  - the data stay modal until G80 or a group-01 code, which clear them;
//  - a block with a positioning word (an axis, Z or R) drills; others only store data;
//  - K (L) repeats the hole: in G91 each repeat moves by the increments again; 0 stores only;
//  - the drilling axis is the normal of the plane (G17 Z, G18 Y, G19 X).
#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "lowering_context.h"

namespace ncc::passes {

namespace {

constexpr int64_t kMaxRepeats = 9999;
// The pecks one block may make, all repeats together: a Q tiny against the depth would expand
// one block into millions of moves (or, below the resolution of a double, never end).
constexpr double kMaxPecksPerBlock = 100000;

// The drilling axis of the plane (its normal), or -1 when the machine lacks it.
int drillingAxis(const BlockContext& ctx) {
  switch (ctx.next.modal.plane) {
    case ir::Plane::ZX: return ctx.axisNamed("Y");
    case ir::Plane::YZ: return ctx.axisNamed("X");
    case ir::Plane::XY: break;
  }
  return ctx.axisNamed("Z");
}

// The two plane axes (first, second) of the plane: G17 X Y, G18 Z X, G19 Y Z.
std::pair<int, int> planeAxesOf(const BlockContext& ctx) {
  switch (ctx.next.modal.plane) {
    case ir::Plane::ZX: return {ctx.axisNamed("Z"), ctx.axisNamed("X")};
    case ir::Plane::YZ: return {ctx.axisNamed("Y"), ctx.axisNamed("Z")};
    case ir::Plane::XY: break;
  }
  return {ctx.axisNamed("X"), ctx.axisNamed("Y")};
}

SourceLocation cycleLoc(const BlockContext& ctx) {
  if (const auto& g = ctx.words.group(GGroup::Cycle)) return g->loc;
  return ctx.motionLoc();
}

// G98/G99, G80, a group-01 code and the cycle code into the cycle state; M03/M04/M05.
void applyCodes(BlockContext& ctx) {
  // M03/M04/M05 of the block: the direction a cycle restores and Siemens checks (61102).
  for (const WordValue& m : ctx.words.m) {
    if (m.value == 3) ctx.next.spindle_direction = 1;
    if (m.value == 4) ctx.next.spindle_direction = -1;
    if (m.value == 5) ctx.next.spindle_direction = 0;
  }
  CycleState& c = ctx.next.cycle;
  // M29 (FANUC rigid tapping): the next G84/G74 are rigid, until the cycle is cancelled.
  const CycleRules* rules = ctx.table.cycles;
  for (const WordValue& m : ctx.words.m)
    if (rules && rules->rigid_tap_m_code != 0 && m.value == rules->rigid_tap_m_code) c.rigid = true;
  if (const auto& g = ctx.words.group(GGroup::ReturnLevel))
    c.return_to_r = g->entry->action == GAction::ReturnR;
  const auto& cycle = ctx.words.group(GGroup::Cycle);
  const auto& motion = ctx.words.group(GGroup::Motion);
  // A group-01 code ends the cycle (and clears its data); written after a cycle code in the
  // same block it wins, written before it loses.
  bool motion_wins = motion && (!cycle || motion->order > cycle->order);
  if (motion_wins || (cycle && cycle->entry->action == GAction::CycleCancel)) {
    bool keep = c.return_to_r;
    c = CycleState{};
    c.return_to_r = keep;
    return;
  }
  if (!cycle || cycle->entry->action != GAction::HoleCycle) return;
  if (c.code10 == 0) {
    // The first cycle block: the initial level is where the drilling axis is now.
    int axis = drillingAxis(ctx);
    if (axis >= 0) c.initial = ctx.baseWork()[axis];
  }
  c.code10 = cycle->entry->code10;
}

// Mazak G73/G83: D is the cycle's d; G82: D is where the feed starts below R. Taken out of the
// block before the radius offset number reads D (CycleRules::d_is_peck_distance). Modal like
// the other cycle data.
void takePeckDistance(BlockContext& ctx) {
  const CycleRules* rules = ctx.table.cycles;
  if (!ctx.words.d || !rules || !rules->d_is_peck_distance || !inCycle(ctx)) return;
  const CycleEntry* e = rules->find(ctx.next.cycle.code10);
  const double d = ctx.lengthValue(*ctx.words.d);
  if (e->feed_start_address == 'D') {
    ctx.next.cycle.feed_start = std::fabs(d);
  } else if (e->kind == ir::HoleCycle::Kind::Peck || e->kind == ir::HoleCycle::Kind::HighSpeedPeck) {
    ctx.next.cycle.d = d;
    ctx.next.cycle.has_d = d > 0;
  } else {
    return;
  }
  ctx.words.d.reset();
}

}  // namespace

void applyCycleCodes(BlockContext& ctx) {
  applyCodes(ctx);
  takePeckDistance(ctx);
}

bool inCycle(const BlockContext& ctx) {
  return ctx.next.cycle.code10 != 0 && !ctx.words.one_shot && ctx.table.cycles &&
         ctx.table.cycles->find(ctx.next.cycle.code10);
}

bool repeatCountIsK(const BlockContext& ctx) {
  return inCycle(ctx) && ctx.table.cycles->repeat_address == 'K';
}

void lowerCycle(BlockContext& ctx) {
  const CycleRules& rules = *ctx.table.cycles;
  CycleState& c = ctx.next.cycle;
  const CycleEntry& entry = *rules.find(c.code10);
  const std::string name = gCodeName(c.code10);
  const int axis = drillingAxis(ctx);
  if (axis < 0 || axis >= ctx.axisCount()) {
    ctx.fail(Alarm::AxisMissing, cycleLoc(ctx),
             absl::StrCat(name, " drills along the plane's normal axis, which the machine lacks"));
    return;
  }
  // ---- the cycle words into the modal data ----
  const std::optional<WordValue>& zw = ctx.words.axes[axis];
  if (ctx.words.r) {
    ctx.used_r = true;
    double v = ctx.lengthValue(*ctx.words.r);
    c.r = ctx.words.r->mode == ir::DistanceMode::Incremental ? c.initial + v : v;
    c.has_r = true;
    if (!zw && c.z_from_r) c.z = c.r + c.z_increment;
  }
  if (zw) {
    double v = ctx.axisValue(axis, *zw);
    c.z_from_r = zw->mode == ir::DistanceMode::Incremental;
    c.z_increment = v;
    // Without an R the distance counts from the initial level (R = the initial level).
    c.z = c.z_from_r ? (c.has_r ? c.r : c.initial) + v : v;
    c.has_z = true;
  }
  if (ctx.words.q) {
    ctx.used_q = true;
    c.q = ctx.lengthValue(*ctx.words.q);
    c.has_q = true;
  }
  if (ctx.words.p) {
    ctx.used_p = true;
    // A cycle without a dwell stores P for a later one without reading it (CAM output such
    // as `G81 ... P0.5` is accepted); a dwell cycle reads it in its unit.
    if (entry.dwell && !entry.p_in_seconds) {
      auto n = ctx.integer(*ctx.words.p);
      if (!n) return;
      c.p = static_cast<double>(*n);
    } else {
      c.p = ctx.words.p->value;
    }
    c.has_p = true;
  }
  // Mazak §13-1: K from R to the feed start (G73/G83), I J the slow zone above the bottom.
  if (entry.feed_start_address == 'K' && ctx.words.k) {
    ctx.used_k = true;
    c.feed_start = std::fabs(ctx.lengthValue(*ctx.words.k));
  }
  if (entry.slow_zone && (ctx.words.i || ctx.words.j)) {
    ctx.used_ijk = true;
    if (ctx.words.i) c.slow_zone = std::fabs(ctx.lengthValue(*ctx.words.i));
    if (ctx.words.j) c.slow_percent = ctx.words.j->value;  // a percentage, as written
    if (ctx.words.j && !(c.slow_percent > 0 && c.slow_percent <= 1000)) {
      ctx.fail(Alarm::ValueOutOfRange, ctx.words.j->loc,
               absl::StrCat(name, " J", ctx.words.j->value,
                            ": the slowed feed must be a percentage above 0"));
      return;
    }
  }
  int64_t repeats = 1;
  const std::optional<WordValue>& kw = rules.repeat_address == 'L' ? ctx.words.l : ctx.words.k;
  if (kw) {
    (rules.repeat_address == 'L' ? ctx.used_l : ctx.used_k) = true;
    auto n = ctx.integer(*kw);
    if (!n) return;
    if (*n < 0 || *n > kMaxRepeats) {
      ctx.fail(Alarm::ValueOutOfRange, kw->loc,
               absl::StrCat("the repeat count ", std::string(kw->address), " must be 0 to ", kMaxRepeats));
      return;
    }
    repeats = *n;
  }
  // Deep-hole tapping: G84/G74 with Q where the dialect pecks (CycleRules::peck_tapping).
  const bool tap_pecks =
      entry.kind == ir::HoleCycle::Kind::Tap && c.has_q && c.q != 0.0 &&
      ((rules.peck_tapping == CycleRules::PeckTapping::RigidMode && c.rigid) ||
       (rules.peck_tapping == CycleRules::PeckTapping::TappingType && ctx.settings.tapping_pecks));
  const bool peck = entry.kind == ir::HoleCycle::Kind::Peck ||
                    entry.kind == ir::HoleCycle::Kind::HighSpeedPeck || tap_pecks;
  if (ctx.words.q && peck) {
    double q = rules.q_sign_ignored ? std::fabs(c.q) : c.q;
    if (!(q > 0)) {
      ctx.fail(Alarm::CyclePeckInvalid, ctx.words.q->loc,
               absl::StrCat(name, ": the peck depth Q must be greater than 0 (Q", ctx.words.q->value,
                            ")"));
      return;
    }
  }
  // A block with a positioning word drills; one without only stores the data (and L0/K0).
  const bool drills = (ctx.words.anyAxis() || ctx.words.r) && repeats > 0;
  if (!drills) return;

  // ---- the checks of a hole ----
  if (!c.has_z) {
    ctx.fail(Alarm::CycleDepthMissing, cycleLoc(ctx),
             absl::StrCat(name, " needs the hole bottom (", ctx.core.machine->axes[axis].name,
                          "): none has been given since the cycle began"));
    return;
  }
  if (peck && !c.has_q) {  // (peck tapping needs Q by its definition)
    ctx.fail(Alarm::CyclePeckMissing, cycleLoc(ctx),
             absl::StrCat(name, " needs the peck depth Q: none has been given"));
    return;
  }
  if (!ctx.next.feed_programmed || ctx.next.modal.feed <= 0) {
    ctx.fail(Alarm::CycleFeedMissing, cycleLoc(ctx),
             absl::StrCat("no feed rate: ", name, " needs an F word and none has been programmed"));
    return;
  }
  if (rules.spindle_direction_required && ctx.next.spindle_direction == 0) {
    ctx.fail(Alarm::CycleSpindleDirection, cycleLoc(ctx),
             absl::StrCat(name, " needs the spindle turning: no M03 or M04 is in force"));
    return;
  }
  const double r_level = c.has_r ? c.r : c.initial;
  // G87 bores upwards: R (where it starts, below the part) lies below Z.
  const bool back = entry.kind == ir::HoleCycle::Kind::BackBore;
  if (rules.r_beyond_bottom_is_error && (back ? r_level >= c.z : r_level <= c.z)) {
    ctx.fail(Alarm::CycleReferencePlane, ctx.words.r ? ctx.words.r->loc : cycleLoc(ctx),
             absl::StrCat(name, ": the R level ", mm(r_level), back ? " is not below Z " : " is not above the bottom ",
                          mm(c.z)));
    return;
  }

  // ---- the holes ----
  ir::HoleCycle h;
  h.kind = entry.kind;
  h.code10 = c.code10;
  h.axis = axis;
  h.initial = c.initial;
  h.r_level = r_level;
  h.bottom = c.z;
  h.return_to_r = c.return_to_r && !back;  // G87 always returns to the initial level
  h.feed = ctx.next.modal.feed;
  // Mazak G84.2/G84.3: F is the pitch, the tap advancing it per spindle revolution.
  h.feed_per_rev = entry.pitch_feed || ctx.next.modal.feed_mode == ir::FeedMode::PerRevolution;
  h.positioning_by_feed = rules.positioning_in_motion_mode && ctx.next.motion != GAction::Rapid;
  h.rapid_type = ctx.settings.rapid_type;
  if (peck) {
    h.peck = rules.q_sign_ignored ? std::fabs(c.q) : c.q;
    const bool to_r = entry.kind == ir::HoleCycle::Kind::Peck ||
                      (tap_pecks && ctx.settings.tapping_peck_to_r);
    h.peck_distance = c.has_d ? c.d : to_r ? ctx.settings.peck_clearance : ctx.settings.peck_return;
    h.peck_tap_to_r = tap_pecks && to_r;
    if (entry.kind == ir::HoleCycle::Kind::HighSpeedPeck) h.peck_retract_feed = rules.peck_retract_feed;
    const double pecks = std::ceil(std::fabs(r_level - c.z) / h.peck) * static_cast<double>(repeats);
    if (!(pecks <= kMaxPecksPerBlock) || !(h.peck >= 1e-6)) {
      ctx.fail(Alarm::ValueOutOfRange, ctx.words.q ? ctx.words.q->loc : cycleLoc(ctx),
               absl::StrCat(name, ": the peck depth Q", h.peck, " makes more than ",
                            kMaxPecksPerBlock, " pecks in this block (", mm(std::fabs(r_level - c.z)),
                            " deep, ", repeats, " times)"));
      return;
    }
  }
  if (entry.dwell && c.has_p) h.dwell = entry.p_in_seconds ? c.p : c.p / 1000.0;
  h.spindle_direction = ctx.next.spindle_direction < 0 ? -1 : 1;
  if (entry.kind == ir::HoleCycle::Kind::Tap) {
    h.spindle_direction = entry.tap_direction;
    h.feed_out = true;
    h.retract_feed = h.feed * ctx.settings.tap_retract_percent / 100.0;
    h.dwell_at_r = entry.dwell_at_r;
    if (tap_pecks) h.peck_approach_feed = rules.peck_tap_approach_at_feed ? h.feed : h.retract_feed;
  }
  if (entry.feed_out) {
    h.feed_out = true;
    h.retract_feed = h.feed;
  }
  h.feed_start = std::min(c.feed_start, std::fabs(r_level - c.z));
  // "When I or J is omitted, the feed is not changed" (§13-1-6).
  if (c.slow_zone > 0 && c.slow_percent > 0) {
    h.slow_zone = c.slow_zone;
    h.slow_feed = h.feed * c.slow_percent / 100.0;
  }
  h.stop_spindle_at_bottom = entry.spindle_stop;
  h.program_stop_at_bottom = entry.manual_stop;
  if (entry.q_shift && c.has_q) {
    // The shift off the wall (boring_shift_direction): 1 + first plane axis, 0/2 - first,
    // 3 + second, 4 - second (Siemens _ZSFI[5] table; FANUC RD1/RD2, Mazak I14 likewise).
    auto [first, second] = planeAxesOf(ctx);
    int d = ctx.settings.boring_shift_direction;
    int on = d == 3 || d == 4 ? second : first;
    double sign = d == 1 || d == 3 ? 1.0 : -1.0;
    if (on >= 0 && on < kMaxAxes) h.shift[on] = sign * std::fabs(c.q);
  }
  AxisValues at = ctx.baseWork();
  const double level = h.return_to_r ? r_level : c.initial;
  for (int64_t n = 0; n < repeats; ++n) {
    h.from = at;
    AxisValues hole = at;
    for (int i = 0; i < ctx.axisCount(); ++i) {
      const auto& w = ctx.words.axes[i];
      if (i == axis || !w) continue;
      double v = ctx.axisValue(i, *w);
      hole[i] = w->mode == ir::DistanceMode::Absolute ? v : hole[i] + v;
    }
    polarHole(ctx, at, hole);  // G16: each repeat from the previous hole
    h.hole = hole;
    ctx.ops.push_back(h);
    at = hole;
    at[axis] = level;
  }
  ctx.next.position = ctx.toMachine(at, frameOf(ctx.next, ctx.behaviour));
}

}  // namespace ncc::passes
