#include "compensation_pass.h"

#include <cmath>
#include <numbers>
#include <utility>
#include <variant>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "ncc/ir/printer.h"
#include "ncc/ir/visit.h"

namespace ncc::passes {

using comp::Connector;
using comp::CornerPath;
using comp::Element;
using comp::Vec2;
using comp::kLengthTolerance;

namespace {

using Side = ir::CutterComp::Side;
using Startup = ir::CutterComp::Startup;

// The target of a move (G00, G01, G02/G03, G31), its space; null for other operations.
AxisValues* target(ir::Operation& op, ir::Space& space) {
  AxisValues* to = nullptr;
  auto move = [&](AxisValues& t, ir::Space s) {
    to = &t;
    space = s;
  };
  std::visit(ir::Overloaded{
                 [&](ir::Rapid& o) { move(o.to, o.space); },
                 [&](ir::Linear& o) { move(o.to, o.space); },
                 [&](ir::Arc& o) { move(o.to, o.space); },
                 [&](ir::Skip& o) { move(o.to, o.space); },
                 // Expanded into moves by the cycles pass, which runs first; a reference
                 // check is no move: the tool stays where it is.
                 ir::Leave<ir::HoleCycle, ir::ReferenceCheck>{},
                 ir::NoPoint{},
             },
             op);
  return to;
}

// The pass's frame: work + work offset + shift, or a machine position less the tool length.
AxisValues common(const ir::Block& b, const AxisValues& v, ir::Space space) {
  AxisValues c = v;
  for (int i = 0; i < kMaxAxes; ++i)
    c[i] += space == ir::Space::Work ? b.frame.work_offset[i] + b.frame.shift[i]
                                     : -b.frame.tool_length[i];
  return c;
}
AxisValues fromCommon(const ir::Block& b, const AxisValues& c, ir::Space space) {
  AxisValues v = c;
  for (int i = 0; i < kMaxAxes; ++i)
    v[i] -= space == ir::Space::Work ? b.frame.work_offset[i] + b.frame.shift[i]
                                     : -b.frame.tool_length[i];
  return v;
}

Vec2 planeOf(const AxisValues& v, const ir::CutterComp& c) { return {v[c.plane_a], v[c.plane_b]}; }
AxisValues withPlane(AxisValues v, const ir::CutterComp& c, const Vec2& p) {
  v[c.plane_a] = p.x();
  v[c.plane_b] = p.y();
  return v;
}

// The signed offset: positive puts the tool on the left (G41 with a positive radius).
double offsetOf(const ir::CutterComp& c) {
  switch (c.side) {
    case Side::Left: return c.radius;
    case Side::Right: return -c.radius;
    case Side::Off: break;
  }
  return 0.0;
}


const char* planeName(const ir::Block& b) {
  switch (b.modal.plane) {
    case ir::Plane::ZX: return "ZX";
    case ir::Plane::YZ: return "YZ";
    case ir::Plane::XY: break;
  }
  return "XY";
}

double distance(const AxisValues& a, const AxisValues& b) {
  double sq = 0;
  for (int k = 0; k < kMaxAxes; ++k) sq += (b[k] - a[k]) * (b[k] - a[k]);
  return std::sqrt(sq);
}

std::string mm(double v) { return absl::StrFormat("%.3f", v); }

// The machine axes of X, Y, Z from the plane's (G17: a = X, b = Y, normal = Z).
std::array<int, 3> xyzAxes(const ir::CutterComp& c, ir::Plane plane) {
  switch (plane) {
    case ir::Plane::ZX: return {c.plane_b, c.plane_normal, c.plane_a};
    case ir::Plane::YZ: return {c.plane_normal, c.plane_a, c.plane_b};
    case ir::Plane::XY: break;
  }
  return {c.plane_a, c.plane_b, c.plane_normal};
}

// The plane's components of an I J K vector (X Y Z slots), as the arc words map to the plane.
Vec2 planeVector(const std::array<double, 3>& v, ir::Plane plane) {
  switch (plane) {
    case ir::Plane::ZX: return {v[2], v[0]};
    case ir::Plane::YZ: return {v[1], v[2]};
    case ir::Plane::XY: break;
  }
  return {v[0], v[1]};
}

// FANUC No.5010: a straight corner move whose change on each plane axis is within `limit` is
// left out (the tool goes on from where it is), but not the one onto an arc, which must start
// on its circle.
void dropSmallCornerMoves(CornerPath& path, double limit, bool arc_follows) {
  if (limit <= 0) return;
  Vec2 from = path.a_end;
  std::vector<Connector> kept;
  for (size_t k = 0; k < path.connectors.size(); ++k) {
    const Connector& c = path.connectors[k];
    const bool last = k + 1 == path.connectors.size();
    const Vec2 d = c.to - from;
    if (!c.arc && !(last && arc_follows) && std::fabs(d.x()) <= limit && std::fabs(d.y()) <= limit)
      continue;
    kept.push_back(c);
    from = c.to;
  }
  path.connectors = std::move(kept);
}

}  // namespace

CompensationPass::CompensationPass(ir::BlockSink& next, Dialect dialect, DiagnosticEngine& diags,
                                   bool compensate)
    : next_(next), table_(dialectTable(dialect)), diags_(diags), compensate_(compensate) {}

void CompensationPass::fail(Alarm alarm, SourceLocation loc, std::string message) {
  diags_.error(std::string(table_ ? table_->alarm(alarm) : "NCC2127"), loc, std::move(message));
  failed_ = true;
}

void CompensationPass::reset() {
  state_ = State::Off;
  open_.reset();
  spendCorner();
  shift_block_.reset();
  closed_.reset();
  stopped_.reset();
}

void CompensationPass::accept(ir::Block&& block) {
  if (ir::hasPrepare(block)) {
    // The VM prepares the held blocks again, with the ones after them (as the corners pass).
    window_.clear();
    reset();
    first_ = ++count_;
    next_.accept(std::move(block));
    return;
  }
  if (failed_ || !compensate_ || (!block.comp && state_ == State::Off && window_.empty())) {
    // Nothing of compensation: only the programmed position is followed.
    for (ir::Operation& op : block.ops) {
      ir::Space space{};
      if (const AxisValues* to = target(op, space)) last_ = common(block, *to, space);
    }
    block.comp.reset();
    release(count_);
    first_ = ++count_;
    next_.accept(std::move(block));
    return;
  }
  window_.push_back(Pending{std::move(block), {}, {}, {}});
  Pending& p = window_.back();
  p.before.resize(p.block.ops.size());
  p.after.resize(p.block.ops.size());
  const uint64_t n = count_++;
  process(n);
  if (failed_) {
    release(count_);
    return;
  }
  // Everything before the held move (or the start-up block that waits for its direction).
  uint64_t hold = count_;
  if (open_) hold = open_->ref.block;
  if (closed_) hold = std::min(hold, closed_->a.ref.block);
  if (shift_block_) hold = std::min(hold, *shift_block_);
  release(hold);
}

void CompensationPass::process(uint64_t n) {
  ir::Block& block = at(n).block;
  const ir::CutterComp* c = block.comp ? &*block.comp : nullptr;
  // A plane the machine lacks an axis of: the lowering has refused its moves already.
  if (c && (c->plane_a < 0 || c->plane_b < 0)) c = nullptr;
  const bool comp_after = c && c->side != Side::Off;
  if (c && c->offset_3d) {
    // Mazak 3-D compensation: every target moves by the vector (§12-4-10).
    for (ir::Operation& op : block.ops) {
      ir::Space space{};
      AxisValues* to = target(op, space);
      if (!to) continue;
      last_ = common(block, *to, space);
      const auto& v = *c->offset_3d;
      const std::array<int, 3> slot = xyzAxes(*c, block.modal.plane);
      for (int k = 0; k < 3; ++k)
        if (slot[k] >= 0) (*to)[slot[k]] += v[k];
      if (auto* arc = std::get_if<ir::Arc>(&op))
        for (int k = 0; k < 3; ++k)
          if (slot[k] >= 0) arc->center[slot[k]] += v[k];
    }
    return;
  }
  if (c) {
    last_comp_ = *c;
  } else {  // no request: compensation ends here, with nothing of the last block's specials
    last_comp_.side = Side::Off;
    last_comp_.vector.reset();
    last_comp_.special = ir::CutterComp::Special::None;
  }
  if (state_ == State::Off && comp_after) state_ = State::Starting;
  const bool cancelling = state_ != State::Off && !comp_after;
  // G41 again in G41 mode (FANUC): the corner before this block's move is perpendicular.
  if (state_ == State::On && open_ && c && c->side_commanded && c->recommand_perpendicular &&
      c->side == open_->comp.side)
    recommanded_ = true;
  // G28/G30, G53, a hole cycle: the block runs on its programmed points (temporary cancel).
  bool temporary = c && c->suspended;
  for (ir::Operation& op : block.ops) {
    ir::Space space{};
    if (target(op, space) && (space == ir::Space::Machine || std::holds_alternative<ir::Skip>(op)))
      temporary = true;
  }
  bool plane_motion = false;
  for (size_t i = 0; i < block.ops.size(); ++i) {
    ir::Space space{};
    AxisValues* to = target(block.ops[i], space);
    if (!to) continue;
    const AxisValues start = last_;
    const AxisValues end = common(block, *to, space);
    last_ = end;
    if (state_ == State::Off) continue;
    const ir::CutterComp& cc = last_comp_;  // a block without a request ends compensation
    const bool arc = std::holds_alternative<ir::Arc>(block.ops[i]);
    const bool in_plane = arc || (planeOf(end, cc) - planeOf(start, cc)).norm() > kLengthTolerance;
    if (temporary) {
      // Temporary cancel: the move runs on its programmed point; the next one takes the
      // vector up again from there.
      if (open_) {
        const Open& a = *open_;
        close(CornerPath{a.e.end + comp::leftNormal(a.e.endDirection()) * a.w, {}}, a.ref.block);
        open_.reset();
        closed_.reset();
      }
      stopped_.reset();
      plane_motion = true;
      continue;
    }
    if (!in_plane) {
      if (open_) between_.push_back({n, i});
      else if (stopped_) placeAt({n, i}, stopped_->point, cc);
      continue;
    }
    plane_motion = true;
    if (cancelling) {
      cancel(n, i, start, end);
      if (failed_) return;
      state_ = State::Off;
      stopped_.reset();
      continue;
    }
    admit(n, i, start, end);
    if (failed_) return;
  }
  if (failed_) return;
  if (cancelling && state_ != State::Off) {
    cancelWithoutMotion(n);
    state_ = State::Off;
    stopped_.reset();  // the tool stays where it stopped until the next move, as programmed
    return;
  }
  if (state_ == State::Off || plane_motion) return;
  // A block without motion in the plane while compensating.
  if (c && c->special == ir::CutterComp::Special::CornerArc) {
    corner_arc_ = n;
    if (c->vector) corner_arc_vector_ = planeVector(*c->vector, block.modal.plane);
    return;
  }
  if (c && c->vector && c->special == ir::CutterComp::Special::None && open_) {
    const Vec2 d = planeVector(*c->vector, block.modal.plane);
    if (d.norm() > kLengthTolerance) given_vector_ = comp::leftNormal(d.normalized()) * offsetOf(*c);
  }
  if (state_ == State::Starting && !open_ && c && c->startup == Startup::C && !shift_block_)
    shift_block_ = n;
  if (open_ && !ir::onlyVariableWrites(at(n).block)) ++without_motion_;
  // The window stays within the look-ahead: past it the corner is known without the next move.
  if (open_ && without_motion_ > open_->comp.max_without_motion && !corner_arc_)
    stopPerpendicular();
}

void CompensationPass::stopPerpendicular() {
  const Open& a = *open_;
  const Vec2 point = given_vector_ ? Vec2(a.e.end + *given_vector_)
                                   : Vec2(a.e.end + comp::leftNormal(a.e.endDirection()) * a.w);
  stopped_ = Stopped{point, a.e.endDirection(), a.w, without_motion_, a.comp.max_without_motion,
                     !given_vector_.has_value()};
  close(CornerPath{point, {}}, a.ref.block);
  open_.reset();
  closed_.reset();
}

// The controller stops perpendicular to the move before and goes on from there: where that
// cuts into an inner corner it is an error, where it leaves an outer one uncut a warning;
// nothing where the corner is straight or there is no offset. False after the error.
bool CompensationPass::judgePerpendicular(const Vec2& d1, double w, const Vec2& d2, double wb,
                                          const ir::Block& at, const std::string& what) {
  const comp::CornerKind kind = comp::classify(d1, d2, w);
  if (kind == comp::CornerKind::Straight || (w == 0 && wb == 0)) return true;
  if (kind == comp::CornerKind::Inner) {
    fail(Alarm::CompWithoutMotion, at.loc,
         absl::StrCat(what, ", and this inner corner would be cut into"));
    return false;
  }
  diags_.warning(std::string(table_->alarm(Alarm::CompWithoutMotion)), at.loc,
                 absl::StrCat(what, ": this corner is left uncut"));
  return true;
}

void CompensationPass::placeAt(const Ref& r, const Vec2& p, const ir::CutterComp& c) {
  Pending& pb = at(r.block);
  ir::Space space{};
  AxisValues* to = target(pb.block.ops[r.op], space);
  *to = fromCommon(pb.block, withPlane(common(pb.block, *to, space), c, p), space);
}

// A move in the plane while compensating: the corner before it ends the held move.
void CompensationPass::admit(uint64_t n, size_t i, const AxisValues& start, const AxisValues& end) {
  ir::Block& block = at(n).block;
  const ir::CutterComp& c = *block.comp;
  Open b;
  b.ref = {n, i};
  b.start = start;
  b.end = end;
  b.comp = c;
  b.w = offsetOf(c);
  b.e.start = planeOf(start, c);
  b.e.end = planeOf(end, c);
  if (const auto* arc = std::get_if<ir::Arc>(&block.ops[i])) {
    b.e.arc = true;
    b.e.centre = planeOf(common(block, arc->center, arc->space), c);
    b.e.clockwise = arc->clockwise;
    const double r = comp::offsetRadius(b.e, b.w);
    if (r <= kLengthTolerance) {
      fail(Alarm::CompInterference, block.loc,
           absl::StrCat("the arc's radius ", mm(b.e.radius()), " mm is not larger than the tool "
                        "radius D", c.d_number, " = ", mm(std::fabs(c.radius)),
                        " mm on its inside: the compensated arc has no radius (the tool would "
                        "cut into the contour)"));
      return;
    }
  }
  if (state_ == State::Starting) {
    state_ = State::On;
    b.comp_start = b.e.start;
    if (shift_block_) {
      // Type C from a block without motion: the tool moves perpendicular to this move there.
      const Vec2 to = b.e.start + comp::leftNormal(b.e.startDirection()) * b.w;
      Pending& s = at(*shift_block_);
      if (std::holds_alternative<ir::Rapid>(block.ops[i]) || block.modal.feed <= 0) {
        ir::Rapid r;
        r.to = fromCommon(s.block, withPlane(start, c, to), ir::Space::Work);
        s.tail.push_back(r);
      } else {
        ir::Linear line;
        line.to = fromCommon(s.block, withPlane(start, c, to), ir::Space::Work);
        line.feed = block.modal.feed;
        line.feed_per_rev = block.modal.feed_mode == ir::FeedMode::PerRevolution;
        s.tail.push_back(line);
      }
      b.comp_start = to;
      shift_block_.reset();
    } else {
      b.startup = true;
    }
  } else if (open_) {
    join(b);
    if (failed_) return;
  } else if (stopped_) {
    const Stopped s = *std::exchange(stopped_, std::nullopt);
    const std::string what = absl::StrCat(
        s.blocks, " blocks without motion in the ", planeName(block), " plane before this move "
        "(at most ", s.limit, " keep the corner): the controller stops perpendicular to the move "
        "before them");
    if (s.judge && !judgePerpendicular(s.direction, s.w, b.e.startDirection(), b.w, block, what))
      return;
    b.comp_start = s.point;
  } else {
    b.comp_start = b.e.start;  // after a temporary cancel: from where the tool is
  }
  // The end of this move is given now: G38 holds the vector, I J (FANUC IJ type) sets it.
  if (c.special == ir::CutterComp::Special::VectorHold) {
    const Vec2 hold = c.vector ? Vec2(planeVector(*c.vector, block.modal.plane).normalized() *
                                      std::fabs(b.w))
                               : Vec2(b.comp_start - b.e.start);
    b.fixed_end = b.e.end + hold;
  } else if (c.vector && c.special == ir::CutterComp::Special::None) {
    const Vec2 d = planeVector(*c.vector, block.modal.plane);
    if (d.norm() > kLengthTolerance)
      b.fixed_end = b.e.end + comp::leftNormal(d.normalized()) * b.w;
  }
  // An arc starts on its offset circle: a line there from a vector that is not (an inner
  // corner's intersection is on it already, and stays where it is).
  if (b.e.arc) {
    const Vec2 on = b.e.start + comp::leftNormal(b.e.startDirection()) * b.w;
    const double off_circle =
        std::fabs((b.comp_start - b.e.centre).norm() - comp::offsetRadius(b.e, b.w));
    if (off_circle > 1e-7) {
      ir::Linear line;
      const auto& arc = std::get<ir::Arc>(block.ops[i]);
      line.feed = arc.feed;
      line.feed_per_rev = arc.feed_per_rev;
      line.space = arc.space;
      line.to = fromCommon(block, withPlane(start, c, on), arc.space);
      at(n).before[i].push_back(line);
      b.comp_start = on;
    }
  }
  open_ = std::move(b);
}

// The corner between the held move and `b`: where the held move ends, the corner moves, and
// where `b` starts.
void CompensationPass::join(Open& b) {
  Open& a = *open_;
  const ir::Block& bb = at(b.ref.block).block;
  const bool side_change = (a.comp.side != b.comp.side) && a.w != 0 && b.w != 0;
  // A new D acts at the end of its block (FANUC §5.4, Mazak §12-4): a line starts at the old one.
  const double wb = (b.e.arc || side_change) ? b.w : a.w;
  const Vec2 p = a.e.end;
  CornerPath path;
  uint64_t connector_block = a.ref.block;
  if (a.fixed_end) {
    path.a_end = *a.fixed_end;
  } else if (given_vector_) {
    path.a_end = p + *given_vector_;
  } else if (b.comp.special == ir::CutterComp::Special::VectorHold) {
    // G38: the block before ends perpendicular to itself, and G38 keeps that vector (FANUC §5.5).
    path.a_end = p + comp::leftNormal(a.e.endDirection()) * a.w;
  } else if (corner_arc_) {
    // G39: an arc of the offset radius about the corner, to perpendicular to the next move
    // (or to I J), in the G39 block.
    const Vec2 n1 = comp::leftNormal(a.e.endDirection());
    const Vec2 d2 = corner_arc_vector_ && corner_arc_vector_->norm() > kLengthTolerance
                        ? Vec2(corner_arc_vector_->normalized())
                        : b.e.startDirection();
    path.a_end = p + n1 * a.w;
    const ir::Block& g39 = at(*corner_arc_).block;
    if (std::holds_alternative<ir::Rapid>(at(a.ref.block).block.ops[a.ref.op]) &&
        g39.modal.feed <= 0) {
      fail(Alarm::FeedMissing, g39.loc,
           "no feed rate: G39's corner arc after G00 runs at the modal F, and none has been "
           "programmed");
      return;
    }
    const Vec2 to = p + comp::leftNormal(d2) * a.w;
    if ((to - path.a_end).norm() > kLengthTolerance)
      path.connectors.push_back({true, to, p, a.w > 0});
    connector_block = *corner_arc_;
  } else if (side_change && b.comp.side_change_perpendicular) {
    path = CornerPath{p + comp::leftNormal(a.e.endDirection()) * a.w, {}};  // b: from there
  } else if (recommanded_) {
    // FANUC §5.4: the move before ends perpendicular to itself, the next goes on from there.
    if (!judgePerpendicular(a.e.endDirection(), a.w, b.e.startDirection(), wb, bb,
                            absl::StrCat(b.comp.side == Side::Left ? "G41" : "G42",
                                         " again while it is in force: the controller ends the "
                                         "move before perpendicular to itself")))
      return;
    path = CornerPath{p + comp::leftNormal(a.e.endDirection()) * a.w, {}};
  } else {
    comp::CornerRules rules;
    rules.arc_connection = a.comp.arc_corners &&
                           !std::holds_alternative<ir::Rapid>(at(a.ref.block).block.ops[a.ref.op]);
    rules.a_ends_perpendicular = a.e.arc;
    rules.b_starts_perpendicular = b.e.arc;
    rules.always_intersect = side_change;
    const comp::CornerKind kind = comp::classify(a.e.endDirection(), b.e.startDirection(), a.w);
    std::optional<CornerPath> found;
    if (a.startup && kind != comp::CornerKind::Inner && a.comp.startup != Startup::B) {
      // Type A (and C with motion): straight to perpendicular to the next move.
      found = CornerPath{p + comp::leftNormal(b.e.startDirection()) * wb, {}};
    } else {
      if (a.startup) rules.a_ends_perpendicular = true;
      found = comp::cornerPath(a.e, a.w, b.e, wb, rules);
    }
    if (!found) {
      fail(Alarm::CompNoIntersection, bb.loc,
           absl::StrCat("the offset paths of this move and the one before do not meet at their "
                        "inner corner (tool radius D", a.comp.d_number, " = ",
                        mm(std::fabs(a.w)), " mm is too large for them)"));
      return;
    }
    path = *found;
  }
  dropSmallCornerMoves(path, a.comp.corner_move_limit, b.e.arc);
  if (a.comp.interference_avoidance && closed_ && interferes(a, path.a_end) && avoid(b)) return;
  close(path, connector_block);
  if (failed_) return;
  b.comp_start = path.b_start();
}

// Interference avoidance (FANUC §5.4.6 CAV = 1, Mazak F92 bit 5 = 1): the held move would run
// backwards, so the move before it and `c` are joined where their offset paths meet, and the
// held move runs no way in the plane. False when there is no such point or the move before
// would then run backwards itself (FANUC PS5447: the caller's alarm).
bool CompensationPass::avoid(Open& c) {
  Closed& k = *closed_;
  const Open& mid = *open_;
  if (mid.fixed_end || c.startup) return false;
  const auto ca = comp::offsetCurve(k.a.e, k.a.w), cc = comp::offsetCurve(c.e, c.w);
  if (!ca || !cc) return false;
  const auto x = comp::intersect(*ca, *cc, (mid.e.start + mid.e.end) / 2);
  if (!x || interferes(k.a, *x)) return false;
  // The move before ends at the new point, without the corner moves it had.
  Pending& pa = at(k.a.ref.block);
  pa.block.ops[k.a.ref.op] = k.op;
  pa.after[k.a.ref.op] = k.after;
  finishMove(k.a, *x);
  // The held move and the moves off the plane on both sides of it stay at that point.
  Pending& pm = at(mid.ref.block);
  ir::Operation& op = pm.block.ops[mid.ref.op];
  ir::Space space{};
  const AxisValues to = fromCommon(
      pm.block, withPlane(common(pm.block, *target(op, space), space), mid.comp, *x), space);
  if (const auto* arc = std::get_if<ir::Arc>(&op)) {
    ir::Linear line;
    line.to = to;
    line.space = space;
    line.feed = arc->feed;
    line.feed_per_rev = arc->feed_per_rev;
    op = line;
  } else {
    *target(op, space) = to;
  }
  std::vector<Ref> refs = k.between;
  refs.insert(refs.end(), between_.begin(), between_.end());
  for (const Ref& r : refs) {
    Pending& pb = at(r.block);
    AxisValues* t = target(pb.block.ops[r.op], space);
    *t = fromCommon(pb.block, withPlane(common(pb.block, *t, space), mid.comp, *x), space);
  }
  diags_.warning(std::string(table_->alarm(Alarm::CompInterference)), pm.block.loc,
                 absl::StrCat("interference avoided: this ", mid.e.arc ? "arc" : "move",
                              " would run against the programmed one; the moves before and "
                              "after it are joined where their offset paths meet and it runs "
                              "no way in the plane (interference_avoidance)"));
  spendCorner();
  closed_.reset();
  c.comp_start = *x;
  return true;
}

// Ends the held move at the path's first point, puts the corner moves after it and the moves
// off the plane at the corner; the state of the corner is spent.
void CompensationPass::close(const CornerPath& path, uint64_t connector_block) {
  const Open& a = *open_;
  if (!checkInterference(a, path.a_end)) return;
  closed_.reset();
  if (a.comp.interference_avoidance && connector_block == a.ref.block && !a.startup &&
      !a.fixed_end) {
    const Pending& pa = at(a.ref.block);
    closed_ = Closed{a, pa.block.ops[a.ref.op], pa.after[a.ref.op], between_};
  }
  finishMove(a, path.a_end);
  Pending& holder = at(connector_block);
  for (const Connector& c : path.connectors) {
    ir::Operation op = connector(a, c, holder.block);
    if (connector_block == a.ref.block) holder.after[a.ref.op].push_back(std::move(op));
    else holder.tail.push_back(std::move(op));
  }
  placeBetween(path, connector_block);
  spendCorner();
}

// What the blocks since the held move said about its corner has been used.
void CompensationPass::spendCorner() {
  between_.clear();
  without_motion_ = 0;
  given_vector_.reset();
  corner_arc_.reset();
  corner_arc_vector_.reset();
  recommanded_ = false;
}

void CompensationPass::placeBetween(const CornerPath& path, uint64_t connector_block) {
  const ir::CutterComp& c = open_->comp;
  for (const Ref& r : between_) {
    // Before a G39 block the tool is still at the held move's end; after its arc, past it.
    const Vec2 p = r.block < connector_block ? path.a_end : path.b_start();
    Pending& pb = at(r.block);
    ir::Space space{};
    AxisValues* to = target(pb.block.ops[r.op], space);
    *to = fromCommon(pb.block, withPlane(common(pb.block, *to, space), c, p), space);
  }
}

void CompensationPass::finishMove(const Open& a, Vec2 end) {
  Pending& pb = at(a.ref.block);
  ir::Operation& op = pb.block.ops[a.ref.op];
  ir::Space space{};
  AxisValues* to = target(op, space);
  const double programmed = distance(a.start, a.end);
  double length = 0.0;
  if (auto* arc = std::get_if<ir::Arc>(&op)) {
    // The arc ends on its offset circle; a given vector off it is reached by a line after.
    const double r = comp::offsetRadius(a.e, a.w);
    const Vec2 on = a.e.end + comp::leftNormal(a.e.endDirection()) * a.w;
    Vec2 arc_end = end;
    if (std::fabs((end - a.e.centre).norm() - r) > 1e-7) {
      arc_end = on;
      ir::Linear line;
      line.space = space;
      line.feed = arc->feed;
      line.feed_per_rev = arc->feed_per_rev;
      line.to = fromCommon(pb.block, withPlane(a.end, a.comp, end), space);
      pb.after[a.ref.op].insert(pb.after[a.ref.op].begin(), line);
    }
    // A closed arc stays closed.
    if (a.e.sweep() == 2 * std::numbers::pi || a.e.sweep() == -2 * std::numbers::pi)
      if ((arc_end - a.comp_start).norm() <= 1e-7) arc_end = a.comp_start;
    *to = fromCommon(pb.block, withPlane(a.end, a.comp, arc_end), space);
    const double sweep = (arc_end - a.comp_start).norm() <= 1e-12 && std::fabs(a.e.sweep()) > 6
                             ? 2 * std::numbers::pi
                             : comp::sweepBetween(a.e.centre, a.comp_start, arc_end, a.e.clockwise);
    length = sweep * r;
  } else {
    *to = fromCommon(pb.block, withPlane(a.end, a.comp, end), space);
    length = distance(withPlane(a.start, a.comp, a.comp_start), withPlane(a.end, a.comp, end));
  }
  // Inverse time feed: the block keeps its time, so the feed follows the length.
  if (pb.block.modal.feed_mode == ir::FeedMode::InverseTime && programmed > kLengthTolerance &&
      length > kLengthTolerance) {
    const double arc_programmed =
        a.e.arc ? std::fabs(a.e.sweep()) * a.e.radius() : programmed;
    const double scale = length / arc_programmed;
    std::visit(ir::Overloaded{
                   [&](ir::Linear& o) { o.feed *= scale; },
                   [&](ir::Arc& o) { o.feed *= scale; },
                   // G93 applies to the cutting moves only (`op` is the compensated move).
                   ir::Leave<ir::Rapid, ir::Skip, ir::HoleCycle, ir::ReferenceCheck>{},
                   ir::NoPoint{},
               },
               op);
  }
}

// The interference check (FANUC §5.4.6, Mazak §12-4 837): the compensated move must not run
// against the programmed one (lines: more than 90 degrees; arcs: a sweep 180 degrees or more
// apart), or the tool cuts into the contour.
bool CompensationPass::interferes(const Open& a, const Vec2& end, std::string* by) const {
  // A move that starts without a vector (start-up, after a temporary cancel) turns by design.
  if (a.startup || (a.comp_start - a.e.start).norm() <= kLengthTolerance) return false;
  if (!a.e.arc) {
    const Vec2 programmed = a.e.end - a.e.start, compensated = end - a.comp_start;
    if (by)
      *by = absl::StrCat(", backwards by ", mm(-compensated.dot(programmed.normalized())), " mm");
    return compensated.norm() > kLengthTolerance && compensated.dot(programmed) < 0;
  }
  const double r = comp::offsetRadius(a.e, a.w);
  if (std::fabs((end - a.e.centre).norm() - r) > 1e-7) return false;  // a given vector
  const double programmed = std::fabs(a.e.sweep());
  const bool closed = programmed > 6.28 && (end - a.comp_start).norm() <= 1e-7;
  const double compensated =
      closed ? programmed : comp::sweepBetween(a.e.centre, a.comp_start, end, a.e.clockwise);
  return std::fabs(programmed - compensated) >= std::numbers::pi - 1e-9;
}

bool CompensationPass::checkInterference(const Open& a, const Vec2& end) {
  std::string by;
  const bool against = interferes(a, end, &by);
  if (!against) return true;
  const ir::Block& b = at(a.ref.block).block;
  const std::string message = absl::StrCat(
      "interference: the compensated path of this ", a.e.arc ? "arc" : "move",
      " runs against the programmed one", by, " (tool radius D", a.comp.d_number, " = ",
      mm(std::fabs(a.w)), " mm is larger than the contour here allows): the tool would cut "
      "into the work");
  if (!a.comp.interference_check) {
    diags_.warning(std::string(table_->alarm(Alarm::CompInterference)), b.loc,
                   absl::StrCat(message, " (the interference check is off)"));
    return true;
  }
  fail(Alarm::CompInterference, b.loc, message);
  return false;
}

// A corner move after `a`, as `a` moves: a rapid after G00, else at its feed.
ir::Operation CompensationPass::connector(const Open& a, const Connector& c,
                                          const ir::Block& in) {
  const ir::Operation& op = at(a.ref.block).block.ops[a.ref.op];
  const AxisValues to = withPlane(a.end, a.comp, c.to);
  if (const auto* r = std::get_if<ir::Rapid>(&op); r && !c.arc) {
    ir::Rapid out = *r;
    out.to = fromCommon(in, to, ir::Space::Work);
    out.space = ir::Space::Work;
    return out;
  }
  double feed = 0.0;
  bool per_rev = false;
  if (const auto* l = std::get_if<ir::Linear>(&op)) feed = l->feed, per_rev = l->feed_per_rev;
  if (const auto* arc = std::get_if<ir::Arc>(&op)) feed = arc->feed, per_rev = arc->feed_per_rev;
  if (std::holds_alternative<ir::Rapid>(op)) {
    // G39's arc after G00 runs at the modal F (FANUC §5.6: "the previous F, even in G00").
    feed = in.modal.feed;
    per_rev = in.modal.feed_mode == ir::FeedMode::PerRevolution;
  }
  if (!c.arc) {
    ir::Linear out;
    out.to = fromCommon(in, to, ir::Space::Work);
    out.feed = feed;
    out.feed_per_rev = per_rev;
    return out;
  }
  ir::Arc out;
  out.to = fromCommon(in, to, ir::Space::Work);
  out.center = fromCommon(in, withPlane(a.end, a.comp, c.centre), ir::Space::Work);
  out.plane = in.modal.plane;
  out.clockwise = c.clockwise;
  out.feed = feed;
  out.feed_per_rev = per_rev;
  return out;
}

// The move that cancels compensation (G40, Mazak D00) after the held one: it ends on its
// programmed point; the corner before it follows the cancel type.
void CompensationPass::cancel(uint64_t n, size_t i, const AxisValues& start,
                              const AxisValues& end) {
  if (!open_) return;  // after a temporary cancel: nothing is held
  Open& a = *open_;
  const ir::Block& block = at(n).block;
  const ir::CutterComp& c = last_comp_;
  Open b;
  b.ref = {n, i};
  b.start = start;
  b.end = end;
  b.comp = a.comp;
  b.w = a.w;
  b.e.start = planeOf(start, a.comp);
  b.e.end = planeOf(end, a.comp);
  const Vec2 p = a.e.end;
  const Vec2 p1 = p + comp::leftNormal(a.e.endDirection()) * a.w;
  CornerPath path{p1, {}};
  if (a.fixed_end) {
    path.a_end = *a.fixed_end;
  } else if (given_vector_) {
    path.a_end = p + *given_vector_;
  } else if (without_motion_ > a.comp.max_without_motion) {
    path.a_end = p1;  // the vector perpendicular to the held move stays
  } else if (c.vector) {
    // G40 with I J K: the corner with a virtual move along (I, J), on the same side, by
    // intersection whatever the corner is; none: perpendicular to the held move.
    const Vec2 d = planeVector(*c.vector, block.modal.plane);
    if (d.norm() > kLengthTolerance) {
      Element virt;
      virt.start = p;
      virt.end = p + d.normalized();
      comp::CornerRules rules;
      rules.always_intersect = true;
      const auto found = comp::cornerPath(a.e, a.w, virt, a.w, rules);
      if (found && found->connectors.empty()) path.a_end = found->a_end;
    }
  } else {
    const comp::CornerKind kind = comp::classify(a.e.endDirection(), b.e.startDirection(), a.w);
    if (kind == comp::CornerKind::Inner || a.comp.startup == Startup::B) {
      comp::CornerRules rules;
      rules.arc_connection = a.comp.arc_corners &&
                             !std::holds_alternative<ir::Rapid>(at(a.ref.block).block.ops[a.ref.op]);
      rules.a_ends_perpendicular = a.e.arc || a.startup;
      rules.b_starts_perpendicular = true;
      const auto found = comp::cornerPath(a.e, a.w, b.e, a.w, rules);
      if (!found) {
        fail(Alarm::CompNoIntersection, block.loc,
             absl::StrCat("the offset path of the move before this cancel and of this move do "
                          "not meet at their inner corner (tool radius D", a.comp.d_number,
                          " = ", mm(std::fabs(a.w)), " mm is too large for them)"));
        return;
      }
      path = *found;
    }
  }
  close(path, a.ref.block);
  if (failed_) return;
  // Inverse time feed: the G40 move starts off its programmed start and keeps its time too.
  const double programmed = distance(start, end);
  const double length = distance(withPlane(start, a.comp, path.b_start()), end);
  if (block.modal.feed_mode == ir::FeedMode::InverseTime && programmed > kLengthTolerance)
    if (auto* line = std::get_if<ir::Linear>(&at(n).block.ops[i])) line->feed *= length / programmed;
  open_.reset();
}

// G40 (or D00) in a block without motion in the plane: the vector perpendicular to the held
// move stays until the next move takes it away (types A and B); type C moves back to the
// programmed point in this block.
void CompensationPass::cancelWithoutMotion(uint64_t n) {
  if (!open_) return;
  Open& a = *open_;
  const Vec2 p = a.e.end;
  CornerPath path{p + comp::leftNormal(a.e.endDirection()) * a.w, {}};
  if (a.fixed_end) path.a_end = *a.fixed_end;
  else if (given_vector_) path.a_end = p + *given_vector_;
  const bool back = a.comp.startup == Startup::C;
  if (back) {
    // The moves off the plane of this block run on the programmed point, after a line there.
    std::vector<Ref> mine;
    std::erase_if(between_, [&](const Ref& r) {
      if (r.block != n) return false;
      mine.push_back(r);
      return true;
    });
    Pending& pn = at(n);
    ir::Operation line = connector(a, {false, p}, pn.block);
    if (!mine.empty()) pn.before[mine.front().op].push_back(std::move(line));
    else pn.tail.push_back(std::move(line));
  }
  close(path, a.ref.block);
  open_.reset();
  closed_.reset();
}

// Sends on the blocks numbered below `before`, with their corner moves in place.
void CompensationPass::release(uint64_t before) {
  while (!window_.empty() && first_ < before) {
    Pending p = std::move(window_.front());
    window_.pop_front();
    ++first_;
    ir::Operations ops;
    for (size_t i = 0; i < p.block.ops.size(); ++i) {
      for (ir::Operation& o : p.before[i]) ops.push_back(std::move(o));
      ops.push_back(std::move(p.block.ops[i]));
      for (ir::Operation& o : p.after[i]) ops.push_back(std::move(o));
    }
    for (ir::Operation& o : p.tail) ops.push_back(std::move(o));
    p.block.ops = std::move(ops);
    p.block.comp.reset();
    next_.accept(std::move(p.block));
  }
  if (window_.empty()) first_ = count_;
}

void CompensationPass::finish() {
  if (!failed_ && open_) {
    // The program ends compensating: the last move ends perpendicular to itself (FANUC: "a
    // program must end in cancel mode, else it stops off by the vector").
    const Open& a = *open_;
    close(CornerPath{a.e.end + comp::leftNormal(a.e.endDirection()) * a.w, {}}, a.ref.block);
    open_.reset();
  }
  release(count_);
  next_.finish();
}

}  // namespace ncc::passes
