// Path geometry: lengths, exact end points, circles and helices.
#include "ncc/vm/motion/path.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "gtest/gtest.h"
#include "motion_test_util.h"

namespace ncc::vm::motion {
namespace {

using motion_test::xyz;

TEST(Path, LineEndsExactly) {
  const AxisValues a = xyz(0.1, 0.2, 0.3), b = xyz(0.7, -1.1, 2.9);
  const PathSegment p = PathSegment::line(a, b, 3);
  EXPECT_NEAR(p.length(), std::sqrt(0.36 + 1.69 + 6.76), 1e-15);
  AxisValues out;
  p.position(0.0, out);
  EXPECT_EQ(out, a);
  p.position(p.length(), out);
  EXPECT_EQ(out, b);
  p.position(0.5 * p.length(), out);
  EXPECT_NEAR(out[1], -0.45, 1e-15);
}

TEST(Path, FullCircleAndHelix) {
  // Full counter-clockwise circle r = 5 around (10, 0) starting at (15, 0).
  const AxisValues s = xyz(15.0, 0.0, 0.0);
  const PathSegment circle = PathSegment::arc(s, s, 3, 0, 1, 10.0, 0.0, false, 0);
  EXPECT_NEAR(circle.length(), 10.0 * std::numbers::pi, 1e-12);
  AxisValues out;
  circle.position(0.25 * circle.length(), out);
  EXPECT_NEAR(out[0], 10.0, 1e-12);
  EXPECT_NEAR(out[1], 5.0, 1e-12);  // ccw: up first
  // Helix: quarter turn clockwise plus 2 turns, Z rises 3 mm. Length = sqrt((r*sweep)^2+dz^2).
  const AxisValues e = xyz(10.0, -5.0, 3.0);
  const PathSegment helix = PathSegment::arc(s, e, 3, 0, 1, 10.0, 0.0, true, 2);
  const double plane = 5.0 * (4.0 * std::numbers::pi + 0.5 * std::numbers::pi);
  EXPECT_NEAR(helix.length(), std::hypot(plane, 3.0), 1e-12);
  for (int i = 0; i <= 100; ++i) {
    helix.position(helix.length() * i / 100.0, out);
    EXPECT_NEAR(std::hypot(out[0] - 10.0, out[1]), 5.0, 1e-12);
    EXPECT_NEAR(out[2], 3.0 * i / 100.0, 1e-12);  // Z linear in the angle
  }
  helix.position(helix.length(), out);
  EXPECT_EQ(out, e);
  AxisValues t;
  helix.tangent(0.0, t);
  EXPECT_NEAR(t[1], -plane / helix.length(), 1e-12);  // clockwise from angle 0: -Y
  EXPECT_NEAR(t[2], 3.0 / helix.length(), 1e-12);
}

TEST(Path, PartIsTheSamePathBetweenItsEnds) {
  // A helix piece and a line piece follow the whole segment at the same path length.
  const PathSegment helix =
      PathSegment::arc(xyz(5, 0, 0), xyz(0, 5, 2), 3, 0, 1, 0, 0, false, 1);
  const PathSegment line = PathSegment::line(xyz(0, 0, 0), xyz(3, 4, 12), 3);
  for (const PathSegment* whole : {&helix, &line}) {
    const double s0 = 0.3 * whole->length(), s1 = 0.8 * whole->length();
    const PathSegment piece = whole->part(s0, s1);
    EXPECT_NEAR(piece.length(), s1 - s0, 1e-12);
    for (int k = 0; k <= 10; ++k) {
      const double s = (s1 - s0) * k / 10.0;
      AxisValues a, b, ta, tb;
      piece.position(s, a);
      whole->position(s0 + s, b);
      piece.tangent(s, ta);
      whole->tangent(s0 + s, tb);
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(a[i], b[i], 1e-12) << k;
        EXPECT_NEAR(ta[i], tb[i], 1e-12) << k;
      }
    }
  }
  // The whole segment is itself, bit for bit.
  AxisValues a, b;
  helix.part(0.0, helix.length()).position(1.234, a);
  helix.position(1.234, b);
  EXPECT_EQ(a, b);
  // A piece of a plane circle is a plane circle.
  const PathSegment circle = PathSegment::arc(xyz(5, 0, 0), xyz(-5, 0, 0), 3, 0, 1, 0, 0, false, 0);
  EXPECT_TRUE(circle.part(1.0, 2.0).isPlaneCircle());
}

TEST(Path, DistanceToLinesAndCircleArcs) {
  const PathSegment line = PathSegment::line(xyz(0, 0, 0), xyz(10, 0, 0), 3);
  EXPECT_DOUBLE_EQ(line.distanceTo(xyz(4, 3, 0)), 3.0);
  EXPECT_DOUBLE_EQ(line.distanceTo(xyz(13, 4, 0)), 5.0);  // beyond the end: to the end
  EXPECT_DOUBLE_EQ(line.distanceTo(xyz(-3, 0, 4)), 5.0);
  // Quarter circle R5 from (5, 0) to (0, 5), counter-clockwise, and the same clockwise back.
  const PathSegment ccw = PathSegment::arc(xyz(5, 0, 0), xyz(0, 5, 0), 3, 0, 1, 0, 0, false, 0);
  const PathSegment cw = PathSegment::arc(xyz(0, 5, 0), xyz(5, 0, 0), 3, 0, 1, 0, 0, true, 0);
  const double d = 5.0 / std::sqrt(2.0);
  for (const PathSegment* arc : {&ccw, &cw}) {
    EXPECT_NEAR(arc->distanceTo(xyz(2 * d, 2 * d, 0)), 5.0, 1e-12);  // outside, in the wedge
    EXPECT_NEAR(arc->distanceTo(xyz(0.2 * d, 0.2 * d, 0)), 4.0, 1e-12);
    EXPECT_NEAR(arc->distanceTo(xyz(d, d, 3)), 3.0, 1e-12);  // off the plane
    // Outside the wedge: to the nearer end, not to the circle.
    EXPECT_NEAR(arc->distanceTo(xyz(5, -1, 0)), 1.0, 1e-12);
    EXPECT_NEAR(arc->distanceTo(xyz(-5, 0, 0)), std::hypot(5.0, 5.0), 1e-12);
  }
  // Not an arc of less than half a turn: no distance.
  const PathSegment three_quarters = PathSegment::arc(xyz(5, 0, 0), xyz(0, -5, 0), 3, 0, 1, 0, 0, false, 0);
  EXPECT_TRUE(std::isinf(three_quarters.distanceTo(xyz(0, 0, 0))));
}

// A helix piece's distance is that of its nearest point: against the tests' own search
// (toPrimitive: the nearest of 128 points along the helix, refined by golden sections), never
// less, and within 1e-9 mm (points all around it, and beyond its ends).
TEST(Path, DistanceToAHelix) {
  // R 5 around (1, 2), a third of a turn clockwise while Z falls 1.5 mm.
  const AxisValues from = xyz(6, 2, 0), to = xyz(1 + 5 * std::cos(-2.0), 2 + 5 * std::sin(-2.0), -1.5);
  const PathSegment helix = PathSegment::arc(from, to, 3, 0, 1, 1, 2, true, 0);
  ASSERT_LT(helix.maxPlaneSpeed(), 1.0);
  const MotionPrimitive programmed = motion_test::arc(from, to, 0, 1, 1, 2, true, 600.0);
  auto brute = [&](const AxisValues& q) { return motion_test::toPrimitive(q, programmed); };
  // All the way around: a point behind the helix (more than a quarter turn from both ends)
  // has a distance with two minima, a point in front of it one.
  for (int i = 0; i < 80; ++i) {
    const double a = -0.5 + 2.0 * std::numbers::pi * i / 80.0, z = -2.0 + 0.05 * i;
    for (double r : {0.5, 4.9, 5.0, 7.0}) {
      const AxisValues q = xyz(1 + r * std::cos(-a), 2 + r * std::sin(-a), z);
      const double expected = brute(q);
      const double d = helix.distanceTo(q);
      EXPECT_GE(d, expected - 1e-12) << i << " " << r;
      EXPECT_NEAR(d, expected, 1e-9) << i << " " << r;
    }
  }
}

TEST(Path, DistanceToAHelixClimbingByAHair) {
  // 0.68 um of Z over 78 mm of arc: the plane share rounds to 1, and the plane's distance
  // (found by review) read 0 for a point at the end's XY but the start's Z, 0.68 um away.
  const double r = 36.113, sweep = 2.158, dz = -6.8e-7;
  const AxisValues to = xyz(r * std::cos(sweep), r * std::sin(sweep), dz);
  const PathSegment helix = PathSegment::arc(xyz(r, 0, 0), to, 3, 0, 1, 0.0, 0.0, false, 0);
  ASSERT_EQ(helix.maxPlaneSpeed(), 1.0);
  const AxisValues q = xyz(to[0], to[1], 0.0);
  EXPECT_GE(helix.distanceTo(q), 0.99 * std::abs(dz));
  EXPECT_LE(helix.distanceTo(q), 1.01 * std::abs(dz));
}

// The curvature vector is d2x/ds2 of the path as position(s) runs it, which is what the axes'
// accelerations follow (v^2 d2x/ds2 at constant speed): against central differences of
// position(), and within maxCurvature() and maxCurvatureRate(). On a spiral (end radius
// differing from the start, as rounded end points or a centre from R make it) the radius
// changes along s too: d2x/ds2 gains a term across the radius (2 r' w with r' and w the radius
// and angle per unit of s; left out, it was 20 % of the centripetal term on this short R 1 arc
// whose radius grows 0.01 mm) and one along the tangent (path_spiral.cpp).
TEST(Path, CurvatureIsTheSecondDerivativeOfPosition) {
  const PathSegment circle = PathSegment::arc(xyz(1, 0, 0), xyz(std::cos(0.1), std::sin(0.1), 0),
                                              3, 0, 1, 0, 0, false, 0);
  const PathSegment spiral =
      PathSegment::arc(xyz(1, 0, 0), xyz(1.01 * std::cos(0.1), 1.01 * std::sin(0.1), 0.02), 3, 0,
                       1, 0, 0, false, 0);
  const PathSegment helix = PathSegment::arc(xyz(2, 0, 0), xyz(-2, 0, -3), 3, 0, 1, 0, 0, true, 0);
  for (const PathSegment* seg : {&circle, &spiral, &helix}) {
    const double L = seg->length(), h = 1e-4 * L;
    double top = 0.0, top_rate = 0.0;
    AxisValues previous{};
    for (int k = 1; k < 100; ++k) {
      const double s = L * k / 100.0;
      AxisValues before, at, after, k_vec;
      seg->position(s - h, before);
      seg->position(s, at);
      seg->position(s + h, after);
      seg->curvature(s, k_vec);
      double kn = 0.0, dk = 0.0;
      for (int i = 0; i < 3; ++i) {
        const double fd = (before[i] - 2.0 * at[i] + after[i]) / (h * h);
        EXPECT_NEAR(k_vec[i], fd, 1e-5 * seg->maxCurvature() + 1e-6) << k << " axis " << i;
        kn += k_vec[i] * k_vec[i];
        dk += (k_vec[i] - previous[i]) * (k_vec[i] - previous[i]);
      }
      top = std::max(top, std::sqrt(kn));
      if (k > 1) top_rate = std::max(top_rate, std::sqrt(dk) / (L / 100.0));
      previous = k_vec;
    }
    EXPECT_LE(top, seg->maxCurvature() * (1.0 + 1e-12));  // exact on a circle
    EXPECT_LE(top_rate, seg->maxCurvatureRate() * (1.0 + 1e-12));
  }
}

}  // namespace
}  // namespace ncc::vm::motion
