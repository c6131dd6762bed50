// G15/G16, the polar coordinate command (Siemens ISO §4.5; FANUC 0i/30i-M alike): in G16 the
// word of the plane's first axis is a radius and that of its second axis an angle in degrees,
// counter-clockwise from the first axis. The words are turned into Cartesian ones before the
// block's move, hole cycle or G31 reads them, so that every motion kind gets them unchanged.
// Where the dialects differ is data (PolarRules in dialect_table.h); docs/semantics.md has the
// rules with the manual's example.
#include <cmath>
#include <numbers>

#include "absl/strings/str_cat.h"
#include "lowering_context.h"

namespace ncc::passes {

namespace {

struct Plane {
  int first = -1, second = -1;  // axis indices; -1 when the machine lacks the axis
  const char* first_name;
  const char* second_name;
  const char* description;  // "the XY plane (G17)"
};

Plane planeOf(const BlockContext& ctx) {
  auto axis = [&](const char* name) {
    const int i = ctx.axisNamed(name);
    return i >= 0 && i < ctx.axisCount() ? i : -1;
  };
  switch (ctx.next.modal.plane) {
    case ir::Plane::ZX: return {axis("Z"), axis("X"), "Z", "X", "the ZX plane (G18)"};
    case ir::Plane::YZ: return {axis("Y"), axis("Z"), "Y", "Z", "the YZ plane (G19)"};
    case ir::Plane::XY: break;
  }
  return {axis("X"), axis("Y"), "X", "Y", "the XY plane (G17)"};
}

// cos and sin of an angle in degrees, exact on the axes (90. gives 0, not 6e-17).
void cosSin(double degrees, double& c, double& s) {
  double a = std::fmod(degrees, 360.0);
  if (a < 0) a += 360.0;
  if (a == 0.0) { c = 1.0; s = 0.0; return; }
  if (a == 90.0) { c = 0.0; s = 1.0; return; }
  if (a == 180.0) { c = -1.0; s = 0.0; return; }
  if (a == 270.0) { c = 0.0; s = -1.0; return; }
  const double r = a * std::numbers::pi / 180.0;
  c = std::cos(r);
  s = std::sin(r);
}

struct PolarPoint {
  double first = 0.0, second = 0.0;  // work coordinates on the plane axes
};

// Whether the point rests on the current position: the pole there (an incremental radius), the
// radius or the angle taken from it (omitted), or an angle counted on from it.
bool fromPosition(const PolarWords& w) {
  return !w.radius || !w.angle || w.radius->mode == ir::DistanceMode::Incremental ||
         w.angle->mode == ir::DistanceMode::Incremental;
}

// The point the polar words name, the current position (work coordinates) being `from`.
PolarPoint polarPoint(const BlockContext& ctx, const PolarWords& w, const AxisValues& from) {
  const PolarRules& rules = *ctx.table.polar;
  const double c1 = from[w.first], c2 = from[w.second];
  // The pole: the work origin for an absolute radius, the current position for an incremental
  // one; without a radius the work origin, the radius the current position's distance from it
  // (Siemens §4.5 N20, FANUC likewise).
  double pole1 = 0.0, pole2 = 0.0, radius = std::hypot(c1, c2);
  bool pole_here = false;
  if (w.radius) {
    radius = ctx.axisValue(w.first, *w.radius);
    if (w.radius->mode == ir::DistanceMode::Incremental) {
      pole1 = c1;
      pole2 = c2;
      pole_here = true;
    }
  }
  // The angle an incremental or omitted angle starts from.
  double base = 0.0;
  if (!(pole_here && rules.angle_from_axis_at_current_pole) && std::hypot(c1, c2) > kSamePoint)
    base = std::atan2(c2, c1) * 180.0 / std::numbers::pi;
  double angle = base;
  if (w.angle) {
    const double v = ctx.settings.values.rotary(w.angle->value, w.angle->point);
    angle = w.angle->mode == ir::DistanceMode::Absolute ? v : base + v;
  }
  double c = 1.0, s = 0.0;
  cosSin(angle, c, s);
  PolarPoint p;
  p.first = pole1 + radius * c;
  p.second = pole2 + radius * s;
  return p;
}

// Codes whose axis words are no end point: FANUC lists G04, G10, G52, G92, G53 (and G22, G68,
// G51, not built) as not read in polar coordinates.
bool wordsAreNoPosition(GAction a) {
  switch (a) {
    case GAction::Dwell:
    case GAction::DwellFeedOrSpindle:
    case GAction::DataSet:
    case GAction::LocalShift:
    case GAction::MachineCoordinates:
    case GAction::SetShift:
    case GAction::ResetShift: return true;
    default: return false;
  }
}

// Arcs and corners in G16, by the dialect's rules. False after reporting.
bool checkArcAndCorner(BlockContext& ctx, const PolarRules& rules) {
  const DecodedBlock& w = ctx.words;
  const bool arc = !w.one_shot && !inCycle(ctx) &&
                   (ctx.next.motion == GAction::ArcCW || ctx.next.motion == GAction::ArcCCW);
  if (arc && (w.anyAxis() || w.i || w.j || w.k || w.r)) {
    if (rules.arcs == PolarRules::Arcs::NotSupported) {
      ctx.fail(Alarm::PolarNotAllowed, ctx.motionLoc(),
               "G02/G03 in the polar coordinate mode (G16) is not supported for this dialect "
               "(its manual does not say how the arc is read); cancel G16 with G15 first");
      return false;
    }
    for (const std::optional<WordValue>* c : {&w.i, &w.j, &w.k}) {
      if (!*c) continue;
      ctx.fail(Alarm::PolarNotAllowed, (*c)->loc,
               absl::StrCat("an arc in the polar coordinate mode (G16) takes its radius by R, "
                            "not by the centre (", std::string((*c)->address), ")"));
      return false;
    }
  }
  if (w.corner && !rules.corners_allowed) {
    ctx.fail(Alarm::PolarNotAllowed, w.corner->loc,
             absl::StrCat(std::string(w.corner->address),
                          " (chamfer / corner rounding) cannot be used in the polar coordinate "
                          "mode (G16)"));
    return false;
  }
  return true;
}

}  // namespace

void applyPolarCode(BlockContext& ctx) {
  const std::optional<GWord>& code = ctx.words.group(GGroup::Polar);
  if (code) ctx.next.polar = code->entry->action == GAction::PolarOn;
  const std::optional<GWord>& plane_code = ctx.words.group(GGroup::Plane);
  if (!ctx.next.polar || !ctx.table.polar || (!code && !plane_code)) return;
  const Plane p = planeOf(ctx);
  if (p.first >= 0 && p.second >= 0) return;
  ctx.fail(Alarm::AxisMissing, (code ? *code : *plane_code).loc,
           absl::StrCat("polar coordinates (G16) in ", p.description, " need the radius axis ",
                        p.first_name, " and the angle axis ", p.second_name,
                        "; the machine has no ", p.first < 0 ? p.first_name : p.second_name));
}

int polarAngleAxis(const BlockContext& ctx) {
  if (!ctx.table.polar || !ctx.next.polar) return -1;
  if (ctx.words.one_shot && wordsAreNoPosition(ctx.words.one_shot->entry->action)) return -1;
  return planeOf(ctx).second;
}

void convertPolarWords(BlockContext& ctx) {
  ctx.polar.reset();
  if (!ctx.table.polar || ctx.failed) return;
  // After a rejected block G16 may be unknown: the block's plane words are then neither known
  // polar nor Cartesian; it is lowered silently and its plane axes stay unknown.
  const bool unknown = ctx.core.cs().unknown.group(GGroup::Polar) && !ctx.words.group(GGroup::Polar);
  if (!ctx.next.polar && !unknown) return;
  const Plane p = planeOf(ctx);
  if (p.first < 0 || p.second < 0) return;  // reported at the G16 or plane code
  std::optional<WordValue>& radius = ctx.words.axes[p.first];
  std::optional<WordValue>& angle = ctx.words.axes[p.second];
  if (unknown) {
    if (!radius && !angle) return;
    ctx.silent = true;
    for (std::optional<WordValue>* w : {&radius, &angle})
      if (*w) (*w)->mode = ir::DistanceMode::Incremental;
    return;
  }
  if (ctx.words.one_shot) {
    const GWord& g = *ctx.words.one_shot;
    if (wordsAreNoPosition(g.entry->action)) return;
    if (g.entry->action != GAction::Skip && (radius || angle)) {
      ctx.fail(Alarm::PolarNotAllowed, g.loc,
               absl::StrCat(gCodeName(g.entry->code10), " with ", p.first_name, " or ",
                            p.second_name, " in the polar coordinate mode (G16) is not "
                            "supported; cancel G16 with G15 first"));
      return;
    }
  }
  if (!checkArcAndCorner(ctx, *ctx.table.polar)) return;
  if (!radius && !angle) return;

  PolarWords words{p.first, p.second, radius, angle};
  const WordValue like = radius ? *radius : *angle;  // where the new words are reported
  // Both plane words become Cartesian. Their mode first: baseWork() depends on it (a pending
  // length change on a plane axis), and the point is taken from that same start.
  const bool from_position = fromPosition(words);
  const ir::DistanceMode mode =
      from_position ? ir::DistanceMode::Incremental : ir::DistanceMode::Absolute;
  for (int axis : {p.first, p.second}) {
    WordValue w = like;
    w.address = ctx.core.machine->axes[axis].name;
    w.value = 0.0;
    w.point = true;
    w.mode = mode;
    ctx.words.axes[axis] = w;
  }
  const AxisValues start = ctx.baseWork();
  const PolarPoint point = polarPoint(ctx, words, start);
  // A value as the block's unit reads it back (axisValue: mm, or inches x 25.4).
  const double unit = ctx.settings.values.linear(1.0, true, ctx.next.modal.units);
  auto set = [&](int axis, double target) {
    ctx.words.axes[axis]->value = (from_position ? target - start[axis] : target) / unit;
  };
  set(p.first, point.first);
  set(p.second, point.second);
  ctx.polar = std::move(words);
}

void polarHole(const BlockContext& ctx, const AxisValues& from, AxisValues& hole) {
  if (!ctx.polar) return;
  const PolarPoint point = polarPoint(ctx, *ctx.polar, from);
  hole[ctx.polar->first] = point.first;
  hole[ctx.polar->second] = point.second;
}

}  // namespace ncc::passes
