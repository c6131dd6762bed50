// The tangential budget on curves (limits.h TangentialBudget): the split of each axis' jerk
// between the tangential jerk and the cross term 3 v a_t k_i that makes a ramp shortest, and
// the constraints it must keep.
#include "ncc/vm/motion/limits.h"

#include <cmath>

#include "gtest/gtest.h"

namespace ncc::vm::motion {
namespace {

double rampTime(double v, double a, double j) { return v / a + a / j; }

TEST(TangentialBudget, OneAxisTakesTheClosedFormOptimum) {
  // r 10 mm circle at 100 mm/s: c = 3 v k = 30 /s, J' = 35000 mm/s^3, A left 1000 mm/s^2.
  TangentialBudget b;
  b.add(1.0, 30.0, 35000.0);
  double a = 1000.0, j = INFINITY;
  b.split(100.0, a, j);
  const double expected = 35000.0 / (30.0 + std::sqrt(35000.0 / 100.0));
  EXPECT_NEAR(a, expected, 1e-9 * expected);
  EXPECT_NEAR(j, 35000.0 - 30.0 * a, 1e-9 * j);
  // It beats the old half-and-half split and any nearby a.
  EXPECT_LT(rampTime(100.0, a, j), rampTime(100.0, 35000.0 / 60.0, 17500.0));
  for (double f : {0.9, 0.95, 1.05, 1.1})
    EXPECT_LT(rampTime(100.0, a, j), rampTime(100.0, f * a, 35000.0 - 30.0 * f * a));
}

TEST(TangentialBudget, KeepsEveryAxisWithinItsJerkAndTheAccelerationBound) {
  TangentialBudget b;
  const double t[3] = {1.0, 0.6, 0.0}, c[3] = {30.0, 45.0, 12.0}, left[3] = {35000.0, 20000.0, 900.0};
  for (int i = 0; i < 3; ++i) b.add(t[i], c[i], left[i]);
  double a = 500.0, j = INFINITY;  // 500: what the axis accelerations leave
  b.split(80.0, a, j);
  EXPECT_GT(a, 0.0);
  EXPECT_LE(a, 500.0);
  EXPECT_GT(j, 0.0);
  for (int i = 0; i < 3; ++i) EXPECT_LE(j * t[i] + c[i] * a, left[i] * (1.0 + 1e-12)) << i;
}

TEST(TangentialBudget, OnALineTakesTheFullLimits) {
  TangentialBudget b;
  b.add(0.8, 0.0, 45000.0);
  double a = 2500.0, j = INFINITY;
  b.split(50.0, a, j);
  EXPECT_EQ(a, 2500.0);
  EXPECT_DOUBLE_EQ(j, 45000.0 / 0.8);
}

}  // namespace
}  // namespace ncc::vm::motion
