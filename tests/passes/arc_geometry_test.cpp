#include "arc_geometry.h"

#include "gtest/gtest.h"

namespace ncc::passes {
namespace {

TEST(ArcGeometry, ShortAndLongArcCentres) {
  auto c = centreFromRadius({0, 0}, {10, 10}, 10, true);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->a, 10, 1e-12);
  EXPECT_NEAR(c->b, 0, 1e-12);
  c = centreFromRadius({0, 0}, {10, 10}, -10, true);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->a, 0, 1e-12);
  EXPECT_NEAR(c->b, 10, 1e-12);
  c = centreFromRadius({0, 0}, {10, 10}, 10, false);  // CCW short arc: centre on the left
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->a, 0, 1e-12);
  EXPECT_NEAR(c->b, 10, 1e-12);
}

TEST(ArcGeometry, HalfCircleAndTooSmallRadius) {
  auto c = centreFromRadius({0, 0}, {20, 0}, 10, true);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->a, 10, 1e-12);
  EXPECT_NEAR(c->b, 0, 1e-12);
  EXPECT_FALSE(centreFromRadius({0, 0}, {100, 0}, 40, true));
}

}  // namespace
}  // namespace ncc::passes
