// Path geometry: lengths, exact end points, circles and helices.
#include "ncc/vm/motion/path.h"

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

}  // namespace
}  // namespace ncc::vm::motion
