#include "offset_geometry.h"

#include <cmath>
#include <numbers>

namespace ncc::passes::comp {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

Vec2 tangentAt(const Element& e, const Vec2& p) {
  if (!e.arc) {
    const Vec2 d = e.end - e.start;
    const double len = d.norm();
    return len > 0 ? Vec2(d / len) : Vec2(1, 0);
  }
  const Vec2 radial = (p - e.centre).normalized();
  const Vec2 ccw = leftNormal(radial);
  return e.clockwise ? Vec2(-ccw) : ccw;
}

// The lines a + t da and b + u db (unit directions): their common point, unless parallel.
std::optional<Vec2> lineLine(const Vec2& a, const Vec2& da, const Vec2& b, const Vec2& db) {
  const double den = cross(da, db);
  if (std::fabs(den) <= kAngleTolerance) return std::nullopt;
  return Vec2(a + da * (cross(b - a, db) / den));
}

std::optional<Vec2> nearest(const std::vector<Vec2>& candidates, const Vec2& near) {
  std::optional<Vec2> best;
  for (const Vec2& c : candidates)
    if (!best || (c - near).squaredNorm() < (*best - near).squaredNorm()) best = c;
  return best;
}

std::vector<Vec2> lineCircle(const Vec2& p, const Vec2& d, const Vec2& c, double r) {
  const Vec2 f = p - c;
  const double b = f.dot(d);
  double disc = b * b - (f.squaredNorm() - r * r);
  // Tangent within rounding: the touching point.
  if (disc < 0 && disc > -1e-12 * std::max(1.0, r * r)) disc = 0;
  if (disc < 0) return {};
  const double s = std::sqrt(disc);
  return {p + d * (-b + s), p + d * (-b - s)};
}

std::vector<Vec2> circleCircle(const Vec2& c1, double r1, const Vec2& c2, double r2) {
  const Vec2 between = c2 - c1;
  const double dist = between.norm();
  if (dist <= kLengthTolerance) return {};
  const double a = (r1 * r1 - r2 * r2 + dist * dist) / (2 * dist);
  double h2 = r1 * r1 - a * a;
  if (h2 < 0 && h2 > -1e-12 * std::max(1.0, r1 * r1)) h2 = 0;
  if (h2 < 0) return {};
  const Vec2 u = between / dist;
  const Vec2 mid = c1 + u * a;
  const Vec2 off = leftNormal(u) * std::sqrt(h2);
  return {mid + off, mid - off};
}

// Where the offset lines through pa (along da) and pb (along db) meet: for equal offsets the
// bisector form P + w (n1 + n2) / (1 + n1.n2), which stays exact as the corner straightens.
std::optional<Vec2> tangentLinesMeet(const Vec2& p, const Vec2& d1, double wa, const Vec2& d2,
                                     double wb) {
  const Vec2 n1 = leftNormal(d1), n2 = leftNormal(d2);
  if (std::fabs(wa - wb) <= kLengthTolerance) {
    const double den = 1 + n1.dot(n2);
    if (den <= kAngleTolerance) return std::nullopt;
    return Vec2(p + (n1 + n2) * (wa / den));
  }
  return lineLine(p + n1 * wa, d1, p + n2 * wb, d2);
}

void addLine(CornerPath& path, const Vec2& to) {
  const Vec2 from = path.b_start();
  if ((to - from).norm() > kLengthTolerance) path.connectors.push_back({false, to});
}

// The points of a linear outer corner: A's end, then straight lines through the rest.
CornerPath through(const std::vector<Vec2>& points) {
  CornerPath path{points.front(), {}};
  for (size_t i = 1; i < points.size(); ++i) addLine(path, points[i]);
  return path;
}

}  // namespace

Vec2 Element::startDirection() const { return tangentAt(*this, start); }
Vec2 Element::endDirection() const { return tangentAt(*this, end); }

double sweepBetween(const Vec2& centre, const Vec2& from, const Vec2& to, bool clockwise) {
  const Vec2 a = from - centre, b = to - centre;
  double angle = std::atan2(cross(a, b), a.dot(b));  // counterclockwise, (-pi, pi]
  if (clockwise) angle = -angle;
  if (angle < 0) angle += kTwoPi;
  return angle;
}

double Element::sweep() const {
  double s = (end - start).norm() <= kLengthTolerance
                 ? kTwoPi
                 : sweepBetween(centre, start, end, clockwise);
  return clockwise ? -s : s;
}

double offsetRadius(const Element& e, double w) {
  const double r = e.radius();
  const Vec2 radial = (e.start - e.centre) / r;
  // The left normal points to the centre on a counterclockwise arc, away from it clockwise.
  const double k = leftNormal(e.startDirection()).dot(radial);
  return r + k * w;
}

std::optional<OffsetCurve> offsetCurve(const Element& e, double w) {
  OffsetCurve c;
  if (!e.arc) {
    c.direction = e.startDirection();
    c.point = e.start + leftNormal(c.direction) * w;
    return c;
  }
  c.circle = true;
  c.centre = e.centre;
  c.radius = offsetRadius(e, w);
  if (c.radius <= kLengthTolerance) return std::nullopt;
  return c;
}

std::optional<Vec2> intersect(const OffsetCurve& a, const OffsetCurve& b, const Vec2& near) {
  if (!a.circle && !b.circle) return lineLine(a.point, a.direction, b.point, b.direction);
  if (a.circle && b.circle) return nearest(circleCircle(a.centre, a.radius, b.centre, b.radius), near);
  const OffsetCurve& line = a.circle ? b : a;
  const OffsetCurve& circle = a.circle ? a : b;
  return nearest(lineCircle(line.point, line.direction, circle.centre, circle.radius), near);
}

CornerKind classify(const Vec2& d1, const Vec2& d2, double w) {
  const double turn = cross(d1, d2), along = d1.dot(d2);
  if (std::fabs(turn) <= kAngleTolerance && along > 0) return CornerKind::Straight;
  // Turning towards the tool's side puts the tool inside the corner.
  if (turn * w > 0) return CornerKind::Inner;
  return along >= 0 ? CornerKind::OuterObtuse : CornerKind::OuterAcute;
}

CornerPath perpendicularPath(const Element& a, double wa, const Element& b, double wb) {
  const Vec2 p = a.end;
  CornerPath path{p + leftNormal(a.endDirection()) * wa, {}};
  addLine(path, p + leftNormal(b.startDirection()) * wb);
  return path;
}

std::optional<CornerPath> cornerPath(const Element& a, double wa, const Element& b, double wb,
                                     const CornerRules& rules) {
  const Vec2 p = a.end;
  const Vec2 d1 = a.endDirection(), d2 = b.startDirection();
  const Vec2 p1 = p + leftNormal(d1) * wa, p2 = p + leftNormal(d2) * wb;
  const CornerKind kind = classify(d1, d2, wa);

  if (rules.always_intersect) {
    const auto ca = offsetCurve(a, wa), cb = offsetCurve(b, wb);
    if (ca && cb)
      if (const auto x = intersect(*ca, *cb, p)) return CornerPath{*x, {}};
    return perpendicularPath(a, wa, b, wb);
  }
  if (kind == CornerKind::Straight) return through({p1, p2});
  if (kind == CornerKind::Inner) {
    if (!a.arc && !b.arc) {
      const auto x = tangentLinesMeet(p, d1, wa, d2, wb);
      if (!x) return std::nullopt;
      return CornerPath{*x, {}};
    }
    const auto ca = offsetCurve(a, wa), cb = offsetCurve(b, wb);
    if (!ca || !cb) return std::nullopt;
    const auto x = intersect(*ca, *cb, p);
    if (!x) return std::nullopt;
    return CornerPath{*x, {}};
  }
  // Outer corners.
  if (rules.arc_connection && std::fabs(wa - wb) <= kLengthTolerance) {
    CornerPath path{p1, {}};
    if ((p2 - p1).norm() > kLengthTolerance)
      path.connectors.push_back({true, p2, p, /*clockwise=*/wa > 0});
    return path;
  }
  std::vector<Vec2> points;
  if (rules.a_ends_perpendicular) points.push_back(p1);
  if (kind == CornerKind::OuterObtuse) {
    const auto x = tangentLinesMeet(p, d1, wa, d2, wb);
    points.push_back(x ? *x : p1);
    if (!x) points.push_back(p2);
  } else {
    points.push_back(p1 + d1 * std::fabs(wa));
    points.push_back(p2 - d2 * std::fabs(wb));
  }
  if (rules.b_starts_perpendicular) points.push_back(p2);
  return through(points);
}

}  // namespace ncc::passes::comp
