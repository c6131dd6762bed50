// Property tests of cutter radius compensation on random contours (seeds fixed and printed):
//  (a) closed contours of lines and arcs that leave room for the tool (convex polygons whose
//      edges are lines or shallow arcs, every corner a left turn of 10..150 degrees, or convex
//      polygons whose corners are rounded by fillets larger than the tool; G41 puts the tool
//      inside, every sharp corner inner; G42 outside, every sharp corner outer): each compensated
//      move keeps the offset distance from the element it offsets (1e-9 mm), every point of
//      the path keeps at least that distance from the whole contour, and the corner moves
//      follow the stated rules (closed forms written here, not the pass's geometry);
//  (b) contours with a groove narrower than the tool: the alarm is reported at the groove's
//      block and is an error (the driver then writes no program); wider grooves pass.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <variant>

#include "compensation_harness.h"
#include "gtest/gtest.h"

namespace ncc::passes::testing {
namespace {

using Side = ir::CutterComp::Side;
constexpr double kPi = std::numbers::pi;
constexpr double kTol = 1e-9;

struct P2 {
  double x = 0, y = 0;
};
P2 operator+(P2 a, P2 b) { return {a.x + b.x, a.y + b.y}; }
P2 operator-(P2 a, P2 b) { return {a.x - b.x, a.y - b.y}; }
P2 operator*(P2 a, double k) { return {a.x * k, a.y * k}; }
double dot(P2 a, P2 b) { return a.x * b.x + a.y * b.y; }
double crs(P2 a, P2 b) { return a.x * b.y - a.y * b.x; }
double len(P2 a) { return std::hypot(a.x, a.y); }
P2 unit(P2 a) { return a * (1 / len(a)); }
P2 left(P2 d) { return {-d.y, d.x}; }
double dist(P2 a, P2 b) { return len(a - b); }

// A programmed element.
struct Elem {
  bool arc = false;
  P2 s, e, c;
  bool cw = false;
  double radius() const { return dist(s, c); }
  P2 tangent(P2 p) const {
    if (!arc) return unit(e - s);
    const P2 t = left(unit(p - c));
    return cw ? t * -1 : t;
  }
};

// The counterclockwise angle from a to b about c in the direction of travel, in [0, 2 pi).
double sweep(P2 c, P2 a, P2 b, bool cw) {
  double t = std::atan2(crs(a - c, b - c), dot(a - c, b - c));
  if (cw) t = -t;
  if (t < 0) t += 2 * kPi;
  return t;
}
P2 rotate(P2 c, P2 a, double angle) {
  const P2 v = a - c;
  return c + P2{v.x * std::cos(angle) - v.y * std::sin(angle),
                v.x * std::sin(angle) + v.y * std::cos(angle)};
}

// The distance from p to the element (the segment or the arc itself).
double distanceTo(const Elem& el, P2 p) {
  if (!el.arc) {
    const P2 d = el.e - el.s;
    double t = dot(p - el.s, d) / dot(d, d);
    t = std::clamp(t, 0.0, 1.0);
    return dist(p, el.s + d * t);
  }
  if (sweep(el.c, el.s, p, el.cw) <= sweep(el.c, el.s, el.e, el.cw))
    return std::fabs(dist(p, el.c) - el.radius());
  return std::min(dist(p, el.s), dist(p, el.e));
}
// The distance from p to the element's carrier (its whole line or circle).
double carrierDistance(const Elem& el, P2 p) {
  if (!el.arc) return std::fabs(crs(unit(el.e - el.s), p - el.s));
  return std::fabs(dist(p, el.c) - el.radius());
}

// One move out of the pass, in plane coordinates.
struct Move {
  uint32_t line = 0;
  bool arc = false, cw = false;
  P2 from, to, c;
};
std::vector<Move> movesOf(const std::vector<ir::Block>& blocks) {
  std::vector<Move> out;
  P2 at;
  for (const ir::Block& b : blocks)
    for (const ir::Operation& op : b.ops) {
      Move m;
      m.line = b.loc.line;
      m.from = at;
      if (const auto* r = std::get_if<ir::Rapid>(&op)) m.to = {r->to[0], r->to[1]};
      else if (const auto* l = std::get_if<ir::Linear>(&op)) m.to = {l->to[0], l->to[1]};
      else if (const auto* a = std::get_if<ir::Arc>(&op)) {
        m.arc = true;
        m.cw = a->clockwise;
        m.to = {a->to[0], a->to[1]};
        m.c = {a->center[0], a->center[1]};
      } else {
        continue;
      }
      at = m.to;
      out.push_back(m);
    }
  return out;
}
std::vector<P2> samples(const Move& m, int n = 16) {
  std::vector<P2> pts;
  const double sw = m.arc ? sweep(m.c, m.from, m.to, m.cw) : 0.0;
  for (int k = 0; k <= n; ++k) {
    const double t = static_cast<double>(k) / n;
    if (!m.arc) pts.push_back(m.from + (m.to - m.from) * t);
    else pts.push_back(rotate(m.c, m.from, (m.cw ? -1 : 1) * sw * t));
  }
  return pts;
}

// A random convex contour: n vertices on a circle, counterclockwise, each edge a line or a
// shallow arc bulging out or in; every corner a left turn of 10..150 degrees.
std::vector<Elem> randomContour(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (;;) {
    const int n = 3 + static_cast<int>(u(rng) * 6);
    const double radius = 30 + 30 * u(rng);
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) angles.push_back(2 * kPi * u(rng));
    std::sort(angles.begin(), angles.end());
    bool spaced = true;
    for (int i = 0; i < n; ++i) {
      const double gap = i + 1 < n ? angles[i + 1] - angles[i] : angles[0] + 2 * kPi - angles[i];
      if (gap < 20 * kPi / 180 || gap > 170 * kPi / 180) spaced = false;
    }
    if (!spaced) continue;
    std::vector<Elem> c;
    for (int i = 0; i < n; ++i) {
      Elem el;
      el.s = {radius * std::cos(angles[i]), radius * std::sin(angles[i])};
      const double a1 = angles[(i + 1) % n];
      el.e = {radius * std::cos(a1), radius * std::sin(a1)};
      if (u(rng) < 0.6) {
        // An arc through s and e with sagitta h = f L (f in 0.05..0.3) out (ccw) or in (cw).
        const double L = dist(el.s, el.e), h = (0.05 + 0.25 * u(rng)) * L;
        const double R = (L * L / 4 + h * h) / (2 * h);
        const bool out = u(rng) < 0.5;
        const P2 mid = (el.s + el.e) * 0.5, n_left = left(unit(el.e - el.s));
        el.arc = true;
        el.cw = !out;
        el.c = mid + n_left * ((out ? 1 : -1) * (R - h));
      }
      c.push_back(el);
    }
    bool turns = true;
    for (int i = 0; i < n; ++i) {
      const Elem& a = c[i];
      const Elem& b = c[(i + 1) % n];
      const P2 d1 = a.tangent(a.e), d2 = b.tangent(b.s);
      const double turn = std::atan2(crs(d1, d2), dot(d1, d2));
      if (turn < 10 * kPi / 180 || turn > 150 * kPi / 180) turns = false;
    }
    if (turns) return c;
  }
}

// A random convex polygon of lines whose corners are rounded by counterclockwise fillets of
// radius rho (tangent corners: line, arc, line); rho > `least` so a tool inside fits them.
std::vector<Elem> roundedContour(std::mt19937_64& rng, double least) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (;;) {
    const int n = 3 + static_cast<int>(u(rng) * 6);
    const double radius = 30 + 30 * u(rng);
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) angles.push_back(2 * kPi * u(rng));
    std::sort(angles.begin(), angles.end());
    std::vector<P2> v;
    for (double a : angles) v.push_back({radius * std::cos(a), radius * std::sin(a)});
    // Each corner's fillet: tangent length t = rho tan(phi / 2) along both edges.
    std::vector<double> rho(n), t(n);
    bool ok = true;
    for (int i = 0; i < n; ++i) {
      const P2 d1 = unit(v[i] - v[(i + n - 1) % n]), d2 = unit(v[(i + 1) % n] - v[i]);
      const double phi = std::atan2(crs(d1, d2), dot(d1, d2));
      if (phi < 10 * kPi / 180 || phi > 150 * kPi / 180) ok = false;
      rho[i] = least + 0.1 + u(rng) * 10;
      t[i] = rho[i] * std::tan(phi / 2);
    }
    for (int i = 0; i < n && ok; ++i)
      if (t[i] + t[(i + 1) % n] > dist(v[i], v[(i + 1) % n]) - 5) ok = false;
    if (!ok) continue;
    std::vector<Elem> c;
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      const P2 d = unit(v[j] - v[i]);
      Elem line;
      line.s = v[i] + d * t[i];
      line.e = v[j] - d * t[j];
      c.push_back(line);
      // The fillet at v[j], from line.e to the next edge's tangent point, about line.e + rho n.
      const P2 d2 = unit(v[(j + 1) % n] - v[j]);
      Elem fillet;
      fillet.arc = true;
      fillet.s = line.e;
      fillet.e = v[j] + d2 * t[j];
      fillet.c = line.e + left(d) * rho[j];
      c.push_back(fillet);
    }
    return c;
  }
}

struct Run {
  CompProgram program;
  std::vector<Move> moves;
};

// Lead-in from outside along the bisector at vertex 0, the contour twice round, back out: the
// start-up and the cancel at vertex 0 are not compensated corners (an inner one is cut into
// there by design), so the contour's distance is checked from the first element's end to the
// last element's start.
CompProgram programOf(const std::vector<Elem>& contour, Side side, double r, bool arc_corners) {
  CompProgram p;
  p.settings().arc_corners = arc_corners;
  const P2 v0 = contour[0].s;
  const P2 out = unit(v0) * 20;  // the contour is about the origin
  p.rapid(v0.x + out.x, v0.y + out.y).side(side, r).line(v0.x, v0.y);
  for (int lap = 0; lap < 2; ++lap)
    for (const Elem& el : contour) {
      if (el.arc) p.arc(el.e.x, el.e.y, el.c.x, el.c.y, el.cw);
      else p.line(el.e.x, el.e.y);
    }
  p.cancel().line(v0.x + out.x, v0.y + out.y);
  return p;
}

TEST(CompensationProperty, ContoursWithRoomForTheToolKeepTheOffsetDistanceAndTheCornerRules) {
  const uint64_t seed = 20261128;
  std::printf("CompensationProperty seed %llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked_moves = 0, inner = 0, outer_linear = 0, outer_arc = 0, tangent = 0;
  for (int trial = 0; trial < 300; ++trial) {
    // Every third contour has rounded (tangent) corners; the tool is smaller than the fillets.
    const bool rounded = trial % 3 == 2;
    double r = 0.0;
    std::vector<Elem> contour;
    if (rounded) {
      r = 0.3 + u(rng) * 4;
      contour = roundedContour(rng, r);
    } else {
      contour = randomContour(rng);
      double shortest = 1e9;
      for (const Elem& el : contour) shortest = std::min(shortest, dist(el.s, el.e));
      r = 0.3 + u(rng) * (shortest / 10 - 0.3);
    }
    const bool inside = trial % 2 == 0;
    const bool arc_corners = trial % 4 >= 2;
    const Side side = inside ? Side::Left : Side::Right;
    SCOPED_TRACE(::testing::Message() << "seed " << seed << " trial " << trial << " r " << r
                                      << (inside ? " G41" : " G42") << (rounded ? " rounded" : "")
                                      << (arc_corners ? " arc corners" : ""));
    CompProgram p = programOf(contour, side, r, arc_corners);
    const std::vector<ir::Block> out = p.runBlocks();
    if (std::getenv("NCC_DUMP") && trial == std::atoi(std::getenv("NCC_DUMP"))) {
      for (const Elem& el : contour)
        std::printf("%s %.4f %.4f -> %.4f %.4f c %.4f %.4f %s\n", el.arc ? "A" : "L", el.s.x,
                    el.s.y, el.e.x, el.e.y, el.c.x, el.c.y, el.cw ? "cw" : "ccw");
      std::printf("%s", movesText(out).c_str());
    }
    ASSERT_FALSE(p.diagnostics().hasErrors()) << p.diagnostics().diagnostics()[0].message;
    ASSERT_EQ(out.size(), 2 * contour.size() + 3);
    const std::vector<Move> moves = movesOf(out);
    const double w = inside ? r : -r;  // the tool at P + w left(d)
    const size_t n = 2 * contour.size();
    for (size_t i = 0; i < n; ++i) {
      const Elem& el = contour[i % contour.size()];
      const uint32_t line = static_cast<uint32_t>(i + 3);  // 1 rapid, 2 lead-in
      // This element's moves: the compensated element, then its corner moves.
      std::vector<Move> mine;
      for (const Move& m : moves)
        if (m.line == line) mine.push_back(m);
      ASSERT_FALSE(mine.empty());
      const Move& main = mine.front();
      ASSERT_EQ(main.arc, el.arc) << "element " << i;
      if (el.arc) {
        EXPECT_LT(dist(main.c, el.c), kTol);
        EXPECT_EQ(main.cw, el.cw);
      }
      for (const P2& q : samples(main)) {
        EXPECT_NEAR(carrierDistance(el, q), r, kTol) << "element " << i;
        // ... on the tool's side: left of a line for G41; for an arc, towards its centre for
        // G41 on a counterclockwise arc (and G42 on a clockwise one).
        if (!el.arc) EXPECT_GT(crs(el.e - el.s, q - el.s) * w, 0) << "element " << i;
        else EXPECT_EQ(dist(q, el.c) < el.radius(), (w > 0) != el.cw) << "element " << i;
      }
      ++checked_moves;
      // Every point of every move of the offset mode keeps r from the whole contour.
      for (const Move& m : mine)
        for (const P2& q : samples(m)) {
          if ((i == 0 && dist(q, main.to) > kTol) || (i + 1 == n && dist(q, main.from) > kTol))
            continue;  // the start-up's and the cancel's
          double nearest = 1e9;
          for (const Elem& other : contour) nearest = std::min(nearest, distanceTo(other, q));
          EXPECT_GE(nearest, r - kTol) << "element " << i << " at " << q.x << " " << q.y;
        }
      if (i + 1 == n) break;  // the last corner is the cancel's
      // The corner at the element's end, by the stated rule.
      const Elem& next = contour[(i + 1) % contour.size()];
      const P2 P = el.e, d1 = el.tangent(el.e), d2 = next.tangent(next.s);
      const P2 m1 = left(d1) * w, m2 = left(d2) * w;  // the offset vectors
      const std::vector<Move> corner(mine.begin() + 1, mine.end());
      if (std::fabs(crs(d1, d2)) < 1e-12 && dot(d1, d2) > 0) {
        // Tangent: the moves meet at P + m1 = P + m2, no corner move.
        ++tangent;
        EXPECT_TRUE(corner.empty()) << "element " << i;
        EXPECT_LT(dist(main.to, P + m1), kTol) << "element " << i;
        continue;
      }
      if (inside) {
        // Inner: the offset curves meet; no corner move.
        ++inner;
        EXPECT_TRUE(corner.empty()) << "element " << i;
        EXPECT_NEAR(carrierDistance(next, main.to), r, kTol);
        continue;
      }
      if (arc_corners) {
        // Outer, arc connection: from P + m1 an arc of radius r about P to P + m2.
        ++outer_arc;
        EXPECT_LT(dist(main.to, P + m1), kTol) << "element " << i;
        ASSERT_EQ(corner.size(), 1u) << "element " << i;
        EXPECT_TRUE(corner[0].arc);
        EXPECT_LT(dist(corner[0].c, P), kTol);
        EXPECT_LT(dist(corner[0].to, P + m2), kTol);
        EXPECT_FALSE(corner[0].cw);  // G42: the tool on the right of a left turn
        continue;
      }
      // Outer, linear: [P + m1 if A is an arc], the tangent lines' meeting point (obtuse) or
      // P + m1 + r d1, P + m2 - r d2 (acute), [P + m2 if B is an arc].
      ++outer_linear;
      std::vector<P2> expected;
      if (el.arc) expected.push_back(P + m1);
      if (dot(d1, d2) >= 0) {
        // The lines P + m1 + s d1 and P + m2 + t d2 meet where s = cross(m2 - m1, d2) / cross(d1, d2).
        const double s = crs(m2 - m1, d2) / crs(d1, d2);
        expected.push_back(P + m1 + d1 * s);
      } else {
        expected.push_back(P + m1 + d1 * r);
        expected.push_back(P + m2 - d2 * r);
      }
      if (next.arc) expected.push_back(P + m2);
      std::vector<P2> got{main.to};
      for (const Move& m : corner) {
        EXPECT_FALSE(m.arc);
        got.push_back(m.to);
      }
      ASSERT_EQ(got.size(), expected.size()) << "element " << i;
      for (size_t k = 0; k < got.size(); ++k)
        EXPECT_LT(dist(got[k], expected[k]), 1e-9) << "element " << i << " point " << k;
    }
  }
  EXPECT_GT(inner, 100);
  EXPECT_GT(outer_linear, 100);
  EXPECT_GT(outer_arc, 100);
  EXPECT_GT(tangent, 500);
  EXPECT_GT(checked_moves, 1000);
}

// A rectangle, counterclockwise, G42 (the tool outside), with a groove down into its top edge
// between x1 and x2 (a slot of depth d, or a round notch of radius (x2 - x1) / 2).
CompProgram grooved(double W, double H, double x1, double x2, double d, bool round, double r) {
  CompProgram p;
  p.rapid(-20, -20).side(Side::Right, r).line(0, 0).line(W, 0).line(W, H).line(x2, H);
  if (round) {
    p.arc(x1, H, (x1 + x2) / 2, H, true);  // line 6
  } else {
    p.line(x2, H - d).line(x1, H - d).line(x1, H);  // lines 6, 7 (the bottom), 8
  }
  p.line(0, H).line(0, 0).cancel().line(-20, -20);
  return p;
}

TEST(CompensationProperty, GroovesNarrowerThanTheToolAreAlarmsNeverCuts) {
  const uint64_t seed = 4242;
  std::printf("CompensationProperty grooves seed %llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int narrow = 0, wide = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const double W = 60 + 40 * u(rng), H = 30 + 30 * u(rng), r = 1 + 4 * u(rng);
    const bool round = trial % 3 == 0;
    const bool too_narrow = trial % 2 == 0;
    // Slots: narrower than 2r, or wider by 0.1 at least. Notches (radius rho): at most r (the
    // offset arc has no radius: PS0041) or between r and 2r (the top edge's offset misses the
    // notch's: no intersection, PS0033); or 2r and more (they meet: no alarm).
    const double width = too_narrow ? (0.2 + u(rng) * (2 * r - 0.4))
                                    : (round ? 4 * r + 0.2 + u(rng) * 5 : 2 * r + 0.1 + u(rng) * 10);
    const double x1 = 10 + u(rng) * (W - 20 - width), x2 = x1 + width;
    const double d = 1 + u(rng) * (H - 10);
    SCOPED_TRACE(::testing::Message() << "seed " << seed << " trial " << trial << " r " << r
                                      << " width " << width << (round ? " notch" : " slot"));
    CompProgram p = grooved(W, H, x1, x2, d, round, r);
    const std::vector<ir::Block> out = p.runBlocks();
    const auto& diags = p.diagnostics().diagnostics();
    if (!too_narrow) {
      ++wide;
      EXPECT_TRUE(diags.empty()) << diags[0].message;
      continue;
    }
    ++narrow;
    ASSERT_EQ(diags.size(), 1u);
    EXPECT_EQ(diags[0].severity, Severity::Error);
    EXPECT_TRUE(p.diagnostics().hasErrors());  // the driver writes no program
    const bool no_radius = round && width / 2 <= r;
    EXPECT_EQ(diags[0].code, round && !no_radius ? "PS0033" : "PS0041");
    EXPECT_EQ(diags[0].location.line, round ? 6u : 7u);  // the notch, the slot's bottom
    // From the groove's block on nothing is compensated: the moves are the programmed ones.
    const std::vector<Move> moves = movesOf(out);
    for (const Move& m : moves)
      if (m.line >= (round ? 6u : 7u) && !m.arc) {
        const ir::Block& in = p.input()[m.line - 1];
        const auto& to = std::visit(
            [](const auto& o) -> AxisValues {
              if constexpr (requires { o.to; }) return o.to;
              else return AxisValues{};
            },
            in.ops[0]);
        EXPECT_NEAR(m.to.x, to[0], kTol);
        EXPECT_NEAR(m.to.y, to[1], kTol);
      }
  }
  EXPECT_GT(narrow, 100);
  EXPECT_GT(wide, 100);
}

}  // namespace
}  // namespace ncc::passes::testing
