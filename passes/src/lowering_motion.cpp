// Motion: the group 01 modes G00 (rapid), G01 (linear), G02/G03 (arcs in the selected plane,
// by centre I/J/K or radius R) and the feed rate F they cut with (per minute, per revolution,
// inverse time, Siemens F1-digit presets). Kept together because a cutting move's feed check
// and IR feed depend on the feed mode and on the move's own length.
#include <cmath>
#include <numbers>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "arc_geometry.h"
#include "lowering_context.h"

namespace ncc::passes {

namespace {

const char* feedUnit(const ir::Modal& m) {
  bool inch = m.units == ir::Units::Inch;
  switch (m.feed_mode) {
    case ir::FeedMode::PerRevolution: return inch ? "in/rev" : "mm/rev";
    case ir::FeedMode::InverseTime: return "1/min";
    case ir::FeedMode::PerMinute: break;
  }
  return inch ? "in/min" : "mm/min";
}

// G94/G95 after G93: the inverse-time F means nothing per minute or per revolution; the
// block (or a later one) must give a new F (Mazak §7-10; FANUC and Siemens alike). Between
// G94 and G95 the F is kept (docs/semantics.md, Feed).
void leaveInverseTime(BlockContext& ctx) {
  ir::Modal& m = ctx.next.modal;
  if (ctx.core.cs().modal.feed_mode != ir::FeedMode::InverseTime ||
      m.feed_mode == ir::FeedMode::InverseTime)
    return;
  m.feed = 0.0;
  ctx.next.feed_programmed = false;
  ctx.next.feed_after_inverse_time = true;
}

}  // namespace

void applyFeed(BlockContext& ctx) {
  leaveInverseTime(ctx);
  if (!ctx.words.f || dwellTakesFeedAndSpindle(ctx.words)) return;
  const WordValue& f = *ctx.words.f;
  ir::Modal& m = ctx.next.modal;
  if (f.value < 0) {
    ctx.fail(Alarm::ValueOutOfRange, f.loc, "a feed rate cannot be negative");
    return;
  }
  // F1-digit feed (Siemens MD22920): F1-F9 select presets, F0 selects rapid traverse.
  if (ctx.settings.f1_digit && !f.point && f.value <= 9 && f.value == std::trunc(f.value)) {
    int n = static_cast<int>(f.value);
    if (n == 0) {
      ctx.next.motion = GAction::Rapid;
      return;
    }
    m.feed =
        n <= static_cast<int>(ctx.settings.f1_feeds.size()) ? ctx.settings.f1_feeds[n - 1] : 0.0;
    ctx.next.feed_programmed = m.feed > 0;
    ctx.next.feed_after_inverse_time = false;
    return;
  }
  const ValueRules& v = ctx.settings.values;
  double increment = v.lengthIncrement(m.units);
  double count = v.feedInput(f.value, f.point, m.units, m.feed_mode) / increment;
  if (!(count <= v.maxCount() + 0.5)) {
    int decimals = static_cast<int>(std::lround(-std::log10(increment)));
    ctx.fail(Alarm::TooManyDigits, f.loc,
             absl::StrCat("address F: the value exceeds the ", v.digits, "-digit format (at most ",
                          absl::StrFormat("%.*f", decimals, v.maxCount() * increment), " ",
                          feedUnit(m), ")"));
    return;
  }
  // A feed below half the least increment is F0: no feed.
  m.feed = count < 0.5 ? 0.0 : v.feed(f.value, f.point, m.units, m.feed_mode);
  ctx.next.feed_programmed = m.feed > 0;
  ctx.next.feed_after_inverse_time = false;
}

bool checkFeed(BlockContext& ctx, bool inverse_time_needs_f) {
  const ir::Modal& m = ctx.next.modal;
  if (m.feed_mode == ir::FeedMode::InverseTime) {
    if (inverse_time_needs_f && (!ctx.words.f || m.feed <= 0)) {
      ctx.fail(Alarm::FeedMissing, ctx.motionLoc(),
               "no feed rate: in inverse time feed (G93) every cutting block needs its own F");
      return false;
    }
    return true;
  }
  if (!ctx.next.feed_programmed && !ctx.words.f && !ctx.next.feed_after_inverse_time &&
      m.feed_mode == ir::FeedMode::PerMinute && ctx.settings.default_feed > 0) {
    // Sinumerik: "SD42110 DEFAULT_FEED is used if no feed has been programmed" (ISO notes
    // §4.2); the move runs at it, and so does every later one until an F.
    ctx.next.modal.feed = ctx.settings.default_feed;
    ctx.next.feed_programmed = true;
  }
  if (!ctx.next.feed_programmed) {
    const char* mode = m.feed_mode == ir::FeedMode::PerRevolution ? "G95" : "G94";
    if (ctx.words.f && ctx.words.f->value > 0)
      ctx.fail(Alarm::FeedMissing, ctx.words.f->loc,
               absl::StrCat("no feed rate: F is below half the least input increment and counts "
                            "as F0"));
    else if (ctx.next.feed_after_inverse_time)
      ctx.fail(Alarm::FeedMissing, ctx.motionLoc(),
               absl::StrCat("no feed rate: after inverse time feed (G93), ", mode,
                            " needs a new F word"));
    else
      ctx.fail(Alarm::FeedMissing, ctx.motionLoc(),
               "no feed rate: a cutting move needs an F word and none has been programmed");
    return false;
  }
  return true;
}

namespace {

// Feed of a cutting op in the IR unit: inverse time (1/min) becomes mm/min over `length`.
double opFeed(const BlockContext& ctx, double length) {
  const ir::Modal& m = ctx.next.modal;
  if (m.feed_mode == ir::FeedMode::InverseTime) return m.feed * length;
  return m.feed;
}

double pathLength(const BlockContext& ctx, const AxisValues& from, const AxisValues& to) {
  double s = 0.0;
  for (int i = 0; i < ctx.axisCount(); ++i) s += (to[i] - from[i]) * (to[i] - from[i]);
  return std::sqrt(s);
}

struct PlaneAxes {
  int a, b;                            // plane axes (first, second)
  const std::optional<WordValue>* wa;  // centre words on them
  const std::optional<WordValue>* wb;
  const std::optional<WordValue>* normal;  // the third centre word
  const char* names;                       // "XY", "ZX", "YZ"
  const char* code;                        // "G17"...
};

PlaneAxes planeAxes(const BlockContext& ctx) {
  const DecodedBlock& w = ctx.words;
  switch (ctx.next.modal.plane) {
    case ir::Plane::ZX:
      return {ctx.axisNamed("Z"), ctx.axisNamed("X"), &w.k, &w.i, &w.j, "ZX", "G18"};
    case ir::Plane::YZ:
      return {ctx.axisNamed("Y"), ctx.axisNamed("Z"), &w.j, &w.k, &w.i, "YZ", "G19"};
    case ir::Plane::XY: break;
  }
  return {ctx.axisNamed("X"), ctx.axisNamed("Y"), &w.i, &w.j, &w.k, "XY", "G17"};
}

// The plane's axes when the machine has both, else nullopt after AxisMissing at `loc`: `what`
// ("an arc", "a corner") needs them.
std::optional<PlaneAxes> bothPlaneAxes(BlockContext& ctx, SourceLocation loc,
                                       const char* what) {
  PlaneAxes pl = planeAxes(ctx);
  if (pl.a >= 0 && pl.b >= 0) return pl;
  ctx.fail(Alarm::AxisMissing, loc,
           absl::StrCat(what, " in the ", pl.names, " plane (", pl.code,
                        ") needs both plane axes, which the machine does not have"));
  return std::nullopt;
}

// Full turns beyond the arc's own sweep, from the dialect's turn count (0 when the block has
// none or after an error). Mazak §6-7: P = p in l = Z / ((2 pi p + theta) / 2 pi), theta in
// [0, 2 pi): an open arc runs theta + p turns (P omitted: p = 0), a closed one p turns (P
// omitted: one, "P may be omitted when the number of pitches is 1"). Siemens §2.1.3: L = the
// number of times a full circle `G02 I J Ln` is run (L omitted: once). R arcs take neither.
constexpr int64_t kMaxArcTurns = 9999;  // the pitch number's range on the Mitsubishi-based Mazak

uint32_t arcExtraTurns(BlockContext& ctx, bool closed) {
  using T = DialectBehaviour::ArcTurns;
  T kind = ctx.behaviour.arc_turns;
  const std::optional<WordValue>& word = kind == T::PitchesP ? ctx.words.p : ctx.words.l;
  if (kind == T::None || !word || (kind == T::FullCircleRepeatsL && !closed)) return 0;
  (kind == T::PitchesP ? ctx.used_p : ctx.used_l) = true;
  auto n = ctx.integer(*word);
  if (!n) return 0;
  bool pitches = kind == T::PitchesP;
  int64_t least = (!pitches || closed) ? 1 : 0;
  if (*n < least || *n > kMaxArcTurns) {
    ctx.fail(Alarm::ValueOutOfRange, word->loc,
             absl::StrCat(pitches ? "the number of helical pitches P"
                                  : "the number of full-circle repeats L",
                          " must be ", least, " to ", kMaxArcTurns,
                          pitches && closed ? " for an arc that ends at its start" : ""));
    return 0;
  }
  return static_cast<uint32_t>(closed || kind == T::FullCircleRepeatsL ? *n - 1 : *n);
}

bool arc(BlockContext& ctx, const AxisValues& start, const AxisValues& target,
         const ir::Frame& frame) {
  bool cw = ctx.next.motion == GAction::ArcCW;
  const std::optional<PlaneAxes> plane = bothPlaneAxes(ctx, ctx.motionLoc(), "an arc");
  if (!plane) return false;
  const PlaneAxes& pl = *plane;
  PlanePoint s{start[pl.a], start[pl.b]}, e{target[pl.a], target[pl.b]};
  bool end_given = ctx.words.axes[pl.a] || ctx.words.axes[pl.b];
  bool closed = distance(s, e) <= kSamePoint;
  bool has_centre = pl.wa->has_value() || pl.wb->has_value();
  ctx.used_ijk = true;  // centre words are read (or, next to R, ignored by rule) here
  PlanePoint c;
  bool by_radius = ctx.words.r && end_given && !closed;
  if (by_radius) {
    // R beats I/J/K when an end point is given (Mazak §6-6, FANUC).
    ctx.used_r = true;
    double r = positionOffsetLength(ctx, ctx.lengthValue(*ctx.words.r));
    if (r == 0.0) {
      ctx.fail(Alarm::ArcDegenerate, ctx.words.r->loc, "an arc radius R cannot be 0");
      return false;
    }
    auto centre = centreFromRadius(s, e, r, cw);
    if (!centre) {
      ctx.fail(
          Alarm::ArcRadiusTooSmall, ctx.words.r->loc,
          absl::StrCat("no arc of radius ", mm(std::fabs(r)), " joins the start and end points ",
                       mm(distance(s, e)), " apart (the radius must be at least half the chord)"));
      return false;
    }
    c = *centre;
  } else if (has_centre) {
    if (pl.normal->has_value()) {
      ctx.fail(Alarm::AddressWithoutMeaning, (*pl.normal)->loc,
               absl::StrCat("address ", std::string((*pl.normal)->address), " is not a centre word of the ",
                            pl.names, " plane (", pl.code, ")"));
      return false;
    }
    ctx.used_r = true;  // an I/J/K full circle ignores R (Mazak §6-6)
    c = {s.a + (pl.wa->has_value() ? positionOffsetLength(ctx, ctx.lengthValue(**pl.wa)) : 0.0),
         s.b + (pl.wb->has_value() ? positionOffsetLength(ctx, ctx.lengthValue(**pl.wb)) : 0.0)};
    double rs = distance(s, c), re = distance(e, c);
    if (rs <= kSamePoint) {
      ctx.fail(Alarm::ArcDegenerate, ctx.motionLoc(), "the arc centre is at the start point");
      return false;
    }
    if (std::fabs(rs - re) > ctx.settings.arc_tolerance) {
      ctx.fail(Alarm::ArcRadiusMismatch, ctx.motionLoc(),
               absl::StrCat("the end point is not on the arc: start radius ", mm(rs),
                            ", end radius ", mm(re), " (difference above arc_radius_tolerance ",
                            mm(ctx.settings.arc_tolerance), ")"));
      return false;
    }
  } else if (ctx.words.r) {
    // R with no end point or end = start: an R full circle does not move (Mazak §6-6).
    ctx.used_r = true;
    if (!ctx.samePosition(ctx.toMachine(target, frame), ctx.next.position))
      ctx.fail(Alarm::ArcDegenerate, ctx.words.r->loc,
               "an R arc needs an end point in the plane different from the start point");
    return !ctx.failed;
  } else {
    ctx.fail(Alarm::ArcCentreMissing, ctx.motionLoc(),
             absl::StrCat(cw ? "G02" : "G03", " needs the centre (I/J/K) or the radius (R)"));
    return false;
  }
  // R arcs were handled above; a turn count belongs to I/J/K arcs only.
  uint32_t extra_turns = by_radius ? 0 : arcExtraTurns(ctx, closed);
  if (ctx.failed) return false;
  if (!checkFeed(ctx, true)) return false;
  ir::Arc a;
  a.extra_turns = extra_turns;
  a.to = target;
  a.center = target;
  a.center[pl.a] = c.a;
  a.center[pl.b] = c.b;
  a.space = ir::Space::Work;
  a.plane = ctx.next.modal.plane;
  a.clockwise = cw;
  a.feed_per_rev = ctx.next.modal.feed_mode == ir::FeedMode::PerRevolution;
  // The arc's length in its plane and along the helix (the IR feed is the speed along it).
  double r = distance(s, c);
  double sweep = std::atan2(s.b - c.b, s.a - c.a) - std::atan2(e.b - c.b, e.a - c.a);
  if (!cw) sweep = -sweep;
  while (sweep <= 0) sweep += 2 * std::numbers::pi;
  if (closed) sweep = 2 * std::numbers::pi;  // not a rounding residue of the angles
  sweep += 2 * std::numbers::pi * extra_turns;
  double plane_len = r * sweep;
  double lin = 0.0;
  for (int i = 0; i < ctx.axisCount(); ++i)
    if (i != pl.a && i != pl.b) lin += (target[i] - start[i]) * (target[i] - start[i]);
  double helix_len = std::sqrt(plane_len * plane_len + lin);
  if (ctx.next.modal.feed_mode == ir::FeedMode::InverseTime) {
    a.feed = ctx.behaviour.inverse_time_arc_per_radius ? ctx.next.modal.feed * r
                                                       : ctx.next.modal.feed * helix_len;
  } else if (ctx.settings.helical_feed_along_arc && lin > 0 && plane_len > 0) {
    // FANUC: F is the speed along the arc; the helix is faster by its length / the arc's.
    a.feed = ctx.next.modal.feed * helix_len / plane_len;
  } else {
    a.feed = ctx.next.modal.feed;
  }
  if (!arcUnderTransforms(ctx, a)) return false;
  ctx.ops.push_back(a);
  return true;
}

// Mazak §13-12 line angle: `G01 Aa` with one end coordinate in the plane; the other is where
// the line from the start at angle a (from the plane's first axis, counter-clockwise positive)
// reaches it. With both coordinates the angle is ignored; with neither it is the geometric
// command (§13-13), not built.
bool lineAngle(BlockContext& ctx, const AxisValues& start, AxisValues& target) {
  const WordValue& w = *ctx.words.line_angle;
  ctx.used_angle = true;
  const std::optional<PlaneAxes> plane = bothPlaneAxes(ctx, w.loc, "a line angle");
  if (!plane) return false;
  const PlaneAxes& pl = *plane;
  bool has_a = ctx.words.axes[pl.a].has_value(), has_b = ctx.words.axes[pl.b].has_value();
  if (has_a && has_b) return true;
  if (!has_a && !has_b) {
    ctx.fail(Alarm::AddressNotSupported, w.loc,
             "the geometric command (an angle without an end point, §13-13) is not supported yet");
    return false;
  }
  double angle = ctx.settings.values.rotary(w.value, w.point) * std::numbers::pi / 180.0;
  double c = std::cos(angle), s = std::sin(angle);
  double along = has_a ? c : s;
  if (std::fabs(along) < 1e-9) {
    ctx.fail(Alarm::ValueOutOfRange, w.loc,
             absl::StrCat("a line at ", mm(ctx.settings.values.rotary(w.value, w.point)),
                          " degrees never changes ", std::string(1, pl.names[has_a ? 0 : 1]),
                          ": give the other coordinate"));
    return false;
  }
  if (has_a)
    target[pl.b] = start[pl.b] + (target[pl.a] - start[pl.a]) / c * s;
  else
    target[pl.a] = start[pl.a] + (target[pl.b] - start[pl.b]) / s * c;
  return true;
}

// ,C / ,R (DIN: CHR / RND, and CHF): the corner after this block's move, for the corners pass (docs/semantics.md,
// Corner chamfer and rounding). Only a G01-G03 block that moves has a corner.
void cornerRequest(BlockContext& ctx, GAction kind, bool moves, const AxisValues& start) {
  const WordValue& w = *ctx.words.corner;
  if (ctx.failed) return;
  if (kind != GAction::Linear && kind != GAction::ArcCW && kind != GAction::ArcCCW) {
    ctx.fail(Alarm::AddressWithoutMeaning, w.loc,
             absl::StrCat("address ", std::string(w.address), " (", w.address == ",R" ? "rounding" : "chamfer",
                          ") needs a G01, G02 or G03 move in its block"));
    return;
  }
  double amount = ctx.lengthValue(w);
  if (amount < 0) {
    ctx.fail(Alarm::ValueOutOfRange, w.loc,
             absl::StrCat("a ", w.address == ",R" ? "corner radius" : "chamfer",
                          " cannot be negative"));
    return;
  }
  ir::CornerRequest c;
  c.kind = w.address == ",C"   ? ir::CornerRequest::Kind::Chamfer
           : w.address == ",R" ? ir::CornerRequest::Kind::Round
                               : ir::CornerRequest::Kind::ChamferLength;  // Siemens CHF
  c.amount = amount;
  c.from = start;
  const std::optional<PlaneAxes> plane = bothPlaneAxes(ctx, w.loc, "a corner");
  if (!plane) return;
  const PlaneAxes& pl = *plane;
  c.plane_a = pl.a;
  c.plane_b = pl.b;
  c.loc = w.loc;
  ctx.corner = c;
  if (!moves || amount == 0.0) ctx.corner->amount = 0.0;  // nothing to insert, still checked
}

}  // namespace

void lowerMotion(BlockContext& ctx) {
  ir::Frame frame = frameOf(ctx.next, ctx.behaviour);
  AxisValues start = ctx.baseWork(frame);
  AxisValues target = ctx.workTargets(start);
  applyPositionOffset(ctx, start, target);  // G45-G48
  if (ctx.words.line_angle && ctx.next.motion == GAction::Linear && !lineAngle(ctx, start, target))
    return;
  AxisValues to_machine = ctx.toMachine(target, frame);
  const bool moves =
      movesUnderTransforms(ctx, target, !ctx.samePosition(to_machine, ctx.next.position));
  bool feed_per_rev = ctx.next.modal.feed_mode == ir::FeedMode::PerRevolution;
  GAction kind = ctx.next.motion;
  bool arc_mode = kind == GAction::ArcCW || kind == GAction::ArcCCW;
  // A block with no arc words in an arc mode (G43 H alone) can only move the length axis:
  // that move is a straight line.
  if (arc_mode && !ctx.words.anyAxis() && !ctx.words.i && !ctx.words.j && !ctx.words.k &&
      !ctx.words.r)
    kind = GAction::Linear;
  switch (kind) {
    case GAction::Rapid:
      if (moves) ctx.ops.push_back(ir::Rapid{target, ir::Space::Work, ctx.settings.rapid_type});
      break;
    case GAction::Linear:
      if (!moves) break;
      if (!checkFeed(ctx, true)) return;
      ctx.ops.push_back(ir::Linear{target, ir::Space::Work,
                                   opFeed(ctx, pathLength(ctx, ctx.next.position, to_machine)),
                                   feed_per_rev});
      break;
    case GAction::ArcCW:
    case GAction::ArcCCW:
      if (!arc(ctx, start, target, frame)) return;
      break;
    default: break;
  }
  if (ctx.words.corner) cornerRequest(ctx, kind, moves, start);
  ctx.next.position = to_machine;
  ctx.lengthChangeTraversed();
}

}  // namespace ncc::passes
