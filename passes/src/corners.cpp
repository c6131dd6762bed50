#include "corners.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <variant>

#include "absl/strings/str_cat.h"
#include "arc_geometry.h"
#include "ncc/ir/visit.h"

namespace ncc::passes {

namespace {

constexpr double kEps = 1e-9;  // mm: points closer than this are the same
// Siemens §4.8.2: moves that meet within +-1 degree get a zero-length insert (no corner).
const double kStraight = std::sin(std::numbers::pi / 180.0);

struct Vec {
  double a = 0.0, b = 0.0;
};
Vec operator-(Vec p, Vec q) { return {p.a - q.a, p.b - q.b}; }
Vec operator+(Vec p, Vec q) { return {p.a + q.a, p.b + q.b}; }
Vec operator*(double k, Vec p) { return {k * p.a, k * p.b}; }
double dot(Vec p, Vec q) { return p.a * q.a + p.b * q.b; }
double cross(Vec p, Vec q) { return p.a * q.b - p.b * q.a; }
double norm(Vec p) { return std::hypot(p.a, p.b); }
Vec unit(Vec p) { return (1.0 / norm(p)) * p; }
Vec left(Vec p) { return {-p.b, p.a}; }

// One move in the plane: a line from s to e, or an arc around c.
struct Element {
  bool arc = false;
  Vec s, e, c;
  bool cw = false;
  double sweep = 0.0;  // arc: radians from s to e in the direction of travel (2 pi: closed)

  double radius() const { return norm(s - c); }
  // Radians from the start to p, turning in the direction of travel, in [0, 2 pi).
  double angleFromStart(Vec p) const {
    double d = std::atan2(p.b - c.b, p.a - c.a) - std::atan2(s.b - c.b, s.a - c.a);
    if (cw) d = -d;
    while (d < -1e-12) d += 2 * std::numbers::pi;
    while (d >= 2 * std::numbers::pi - 1e-12) d -= 2 * std::numbers::pi;
    return d;
  }
  // Where p (on the line or circle) lies along the move: 0 at the start, 1 at the end.
  double fraction(Vec p) const {
    if (!arc) return dot(p - s, e - s) / dot(e - s, e - s);
    return angleFromStart(p) / sweep;
  }
  double length() const { return arc ? radius() * sweep : norm(e - s); }
  // The direction of travel at p.
  Vec tangent(Vec p) const {
    if (!arc) return unit(e - s);
    Vec r = unit(p - c);
    return cw ? Vec{r.b, -r.a} : left(r);
  }
  // The point of the line or circle nearest to p.
  Vec foot(Vec p) const {
    if (!arc) return s + (dot(p - s, e - s) / dot(e - s, e - s)) * (e - s);
    return c + radius() * unit(p - c);
  }
};

// A line (point p, direction d) or a circle (centre c, radius r) the insert is built from.
struct Curve {
  bool circle = false;
  Vec p, d;
  Vec c;
  double r = 0.0;
};

Curve support(const Element& el) {
  if (el.arc) return {true, {}, {}, el.c, el.radius()};
  return {false, el.s, el.e - el.s, {}, 0.0};
}

// The element moved sideways by `r` to the left (side > 0) or right of its travel: a parallel
// line, or a concentric circle (nullopt when the circle would vanish).
std::optional<Curve> offset(const Element& el, double r, int side) {
  if (!el.arc) return Curve{false, el.s + (side * r) * unit(left(el.e - el.s)), el.e - el.s, {}, 0};
  // The centre is on the left of a counter-clockwise arc: a left offset shrinks it.
  double k = (el.cw ? 1.0 : -1.0) * side * r;
  double rr = el.radius() + k;
  if (rr <= kEps) return std::nullopt;
  return Curve{true, {}, {}, el.c, rr};
}

std::vector<Vec> intersect(const Curve& x, const Curve& y) {
  if (!x.circle && !y.circle) {
    double den = cross(x.d, y.d);
    if (std::fabs(den) < 1e-15) return {};
    double t = cross(y.p - x.p, y.d) / den;
    return {x.p + t * x.d};
  }
  if (x.circle && !y.circle) return intersect(y, x);
  if (!x.circle) {  // line x, circle y
    Vec u = unit(x.d);
    Vec f = x.p + dot(y.c - x.p, u) * u;  // foot of the centre on the line
    double h2 = y.r * y.r - dot(f - y.c, f - y.c);
    if (h2 < -kEps) return {};
    double h = std::sqrt(std::max(h2, 0.0));
    return {f - h * u, f + h * u};
  }
  double d = norm(y.c - x.c);
  if (d < kEps) return {};
  double a = (x.r * x.r - y.r * y.r + d * d) / (2 * d);
  double h2 = x.r * x.r - a * a;
  if (h2 < -kEps) return {};
  double h = std::sqrt(std::max(h2, 0.0));
  Vec u = unit(y.c - x.c);
  Vec m = x.c + a * u;
  return {m + h * left(u), m - h * left(u)};
}

std::vector<Vec> intersectCircle(const Element& el, Vec centre, double r) {
  return intersect(support(el), Curve{true, {}, {}, centre, r});
}

bool within(double f) { return f >= -1e-9 && f <= 1 + 1e-9; }

struct Planar {
  int a, b;
  Vec at(const AxisValues& v) const { return {v[a], v[b]}; }
  void set(AxisValues& v, Vec p) const {
    v[a] = p.a;
    v[b] = p.b;
  }
};

// The move of a block (its first motion operation), or null.
ir::Operation* motionOf(ir::Block& block) {
  for (ir::Operation& op : block.ops)
    if (ir::isMove(op)) return &op;
  return nullptr;
}

Element elementOf(const ir::Operation& op, Vec start, const Planar& pl) {
  Element el;
  el.s = start;
  if (const auto* arc = std::get_if<ir::Arc>(&op)) {
    el.arc = true;
    el.e = pl.at(arc->to);
    el.c = pl.at(arc->center);
    el.cw = arc->clockwise;
    el.sweep = norm(el.e - el.s) <= kEps ? 2 * std::numbers::pi : el.angleFromStart(el.e);
    el.sweep += 2 * std::numbers::pi * arc->extra_turns;
  } else {
    el.e = pl.at(std::get<ir::Linear>(op).to);
  }
  return el;
}

// Variable writes between the held block and the next move stay with the held block.
bool heldWithIt(const ir::Block& b) { return !b.corner && ir::onlyVariableWrites(b); }

const char* what(const ir::CornerRequest& c) {
  return c.kind == ir::CornerRequest::Kind::Round ? "corner rounding" : "chamfer";
}

}  // namespace

CornersPass::CornersPass(ir::BlockSink& next, Dialect dialect, DiagnosticEngine& diags)
    : next_(next), table_(dialectTable(dialect)), diags_(diags) {}

void CornersPass::fail(Alarm a, SourceLocation loc, std::string message) {
  diags_.error(std::string(table_->alarm(a)), loc, std::move(message));
}

void CornersPass::accept(ir::Block&& block) {
  if (!held_) return take(std::move(block));
  if (heldWithIt(block)) {
    writes_.push_back(std::move(block));
    return;
  }
  if (ir::hasPrepare(block)) {
    // The VM prepares the held block again, with the block after it (corners.h).
    held_.reset();
    writes_.clear();
    next_.accept(std::move(block));
    return;
  }
  ir::Block held = *std::exchange(held_, std::nullopt);
  // The next move now starts where the insert ends: its own corner starts from there.
  if (block.corner) insertCorner(held, block, block.corner->from);
  else {
    AxisValues unused{};
    insertCorner(held, block, unused);
  }
  held.corner.reset();
  next_.accept(std::move(held));
  for (ir::Block& w : writes_) next_.accept(std::move(w));
  writes_.clear();
  take(std::move(block));
}

void CornersPass::take(ir::Block&& block) {
  if (!block.corner || !table_ || block.corner->amount <= 0) {
    block.corner.reset();
    next_.accept(std::move(block));
    return;
  }
  ir::Operation* op = motionOf(block);
  if (op && std::holds_alternative<ir::Arc>(*op) && !table_->behaviour.corner_with_arcs) {
    fail(Alarm::CornerArcNotAllowed, block.corner->loc,
         absl::StrCat("a ", what(*block.corner), " joins two lines only; this block is an arc"));
    block.corner.reset();
    next_.accept(std::move(block));
    return;
  }
  held_ = std::move(block);
}

void CornersPass::finish() {
  if (held_) {
    fail(Alarm::CornerNoMoveAfter, held_->corner->loc,
         absl::StrCat("no block with a move follows the ", what(*held_->corner)));
    release();
  }
  next_.finish();
}

void CornersPass::release() {
  held_->corner.reset();
  next_.accept(std::move(*held_));
  held_.reset();
  for (ir::Block& w : writes_) next_.accept(std::move(w));
  writes_.clear();
}

bool CornersPass::insertCorner(ir::Block& held, ir::Block& next, AxisValues& next_start) {
  const ir::CornerRequest& req = *held.corner;
  const char* name = what(req);
  const Planar pl{req.plane_a, req.plane_b};
  if (next.modal.plane != held.modal.plane || !(next.frame == held.frame) ||
      !(next.transform == held.transform)) {
    fail(Alarm::CornerContextChange, next.loc,
         absl::StrCat("the block after a ", name, " changes the ",
                      next.modal.plane != held.modal.plane ? "plane" : "coordinate system"));
    return false;
  }
  const ir::Operation* nop = motionOf(next);
  if (!nop) {
    fail(Alarm::CornerNoMoveAfter, next.loc,
         absl::StrCat("the block after a ", name, " must be a G01, G02 or G03 move"));
    return false;
  }
  if (std::holds_alternative<ir::Rapid>(*nop) || std::holds_alternative<ir::Skip>(*nop)) {
    fail(Alarm::CornerNotCuttingAfter, next.loc,
         absl::StrCat("the block after a ", name, " must be a G01, G02 or G03 move, not ",
                      std::holds_alternative<ir::Rapid>(*nop) ? "G00" : "a skip move"));
    return false;
  }
  if (std::holds_alternative<ir::Arc>(*nop) && !table_->behaviour.corner_with_arcs) {
    fail(Alarm::CornerArcNotAllowed, next.loc,
         absl::StrCat("a ", name, " joins two lines only; the next block is an arc"));
    return false;
  }
  ir::Operation* hop = motionOf(held);
  const AxisValues corner_at =  // a copy: the move's end changes below
      std::holds_alternative<ir::Arc>(*hop) ? std::get<ir::Arc>(*hop).to : std::get<ir::Linear>(*hop).to;
  const Vec corner = pl.at(corner_at);
  Element first = elementOf(*hop, pl.at(req.from), pl);
  Element second = elementOf(*nop, corner, pl);
  if (first.length() <= kEps) {
    fail(Alarm::CornerTooLong, req.loc,
         absl::StrCat("the ", name, " block moves no axis of the plane"));
    return false;
  }
  if (second.length() <= kEps) {
    fail(Alarm::CornerNoMoveAfter, next.loc,
         absl::StrCat("the block after a ", name, " moves no axis of the plane"));
    return false;
  }
  const Vec t1 = first.tangent(corner), t2 = second.tangent(corner);
  const double turn = cross(t1, t2);
  if (std::fabs(turn) < kStraight) return true;  // (anti)parallel: nothing to insert
  double amount = req.amount;
  if (req.kind == ir::CornerRequest::Kind::ChamferLength) {
    // CHF gives the chamfer's own length: for legs of length d meeting at angle phi it is
    // 2 d sin(phi / 2) (measured on the tangents at the corner).
    const double cos_phi = std::clamp(-dot(t1, t2), -1.0, 1.0);
    amount /= 2.0 * std::sqrt((1.0 - cos_phi) / 2.0);
  }

  Vec p1, p2;  // where the insert starts (on the first move) and ends (on the second)
  std::optional<Vec> centre;
  if (req.kind != ir::CornerRequest::Kind::Round) {
    // Points at distance `amount` from the virtual corner: on a line measured along it, on an
    // arc along the chord.
    std::optional<double> best1, best2;
    for (Vec p : intersectCircle(first, corner, amount)) {
      double f = first.fraction(p);
      if (f < 1 - 1e-12 && f >= -1e-9 && (!best1 || f > *best1)) best1 = f, p1 = p;
    }
    if (!best1) {
      fail(Alarm::CornerTooLong, req.loc,
           absl::StrCat("the chamfer of ", amount, " mm is longer than the move of its block"));
      return false;
    }
    for (Vec p : intersectCircle(second, corner, amount)) {
      double f = second.fraction(p);
      if (f > 1e-12 && f <= 1 + 1e-9 && (!best2 || f < *best2)) best2 = f, p2 = p;
    }
    if (!best2) {
      fail(Alarm::CornerTooLongAfter, next.loc,
           absl::StrCat("the chamfer of ", amount, " mm is longer than the move of the next block"));
      return false;
    }
  } else {
    // The circle of radius `amount` tangent to both moves, on the inside of the turn: its
    // centre is where the two moves offset by the radius towards the inside meet (the nearest
    // such point to the corner).
    const int side = turn > 0 ? 1 : -1;
    std::optional<Curve> o1 = offset(first, amount, side), o2 = offset(second, amount, side);
    if (o1 && o2) {
      for (Vec q : intersect(*o1, *o2))
        if (!centre || norm(q - corner) < norm(*centre - corner)) centre = q;
    }
    if (!centre) {
      fail(Alarm::CornerTooLong, req.loc,
           absl::StrCat("no arc of radius ", amount, " mm is tangent to both moves"));
      return false;
    }
    p1 = first.foot(*centre);
    p2 = second.foot(*centre);
    if (!within(first.fraction(p1))) {
      fail(Alarm::CornerTooLong, req.loc,
           absl::StrCat("the corner radius ", amount, " mm does not fit in the move of its block"));
      return false;
    }
    if (!within(second.fraction(p2))) {
      fail(Alarm::CornerTooLongAfter, next.loc,
           absl::StrCat("the corner radius ", amount,
                        " mm does not fit in the move of the next block"));
      return false;
    }
  }

  // The block's move ends where the insert starts (its other axes reach their end there).
  AxisValues end = corner_at;
  pl.set(end, p1);
  double feed = 0.0;
  bool per_rev = false;
  ir::Plane plane = held.modal.plane;
  auto cut = [&](auto& op) {
    op.to = end;
    feed = op.feed;
    per_rev = op.feed_per_rev;
  };
  std::visit(ir::Overloaded{
                 [&](ir::Linear& op) { cut(op); },
                 [&](ir::Arc& op) { cut(op); },
                 // Lowering requests a corner on G01-G03 moves only: nothing to shorten here.
                 ir::Leave<ir::Rapid, ir::Skip, ir::HoleCycle, ir::ReferenceCheck>{},
                 ir::NoPoint{},
             },
             *hop);
  AxisValues to = corner_at;
  pl.set(to, p2);
  size_t at = static_cast<size_t>(hop - held.ops.data()) + 1;
  if (req.kind != ir::CornerRequest::Kind::Round) {
    held.ops.insert(held.ops.begin() + at, ir::Linear{to, ir::Space::Work, feed, per_rev});
  } else {
    ir::Arc arc;
    arc.to = to;
    arc.center = to;
    pl.set(arc.center, *centre);
    arc.space = ir::Space::Work;
    arc.plane = plane;
    arc.clockwise = turn < 0;
    arc.feed = feed;
    arc.feed_per_rev = per_rev;
    held.ops.insert(held.ops.begin() + at, arc);
  }
  next_start = to;
  return true;
}

}  // namespace ncc::passes
