// The tangential budget on curves (limits.h TangentialBudget): the split of each axis' jerk
// between the tangential jerk and the cross term 3 v k a_t that makes a ramp shortest, under
// the sum-form and norm-form bounds, and the constraints it must keep.
#include "ncc/vm/motion/limits.h"

#include <algorithm>
#include <cmath>

#include "gtest/gtest.h"

namespace ncc::vm::motion {
namespace {

double rampTime(double v, double a, double j) { return v / a + a / j; }

// Within its limit by at least one of the two bounds.
bool withinLimit(const TangentialBudget::Axis& x, double a, double j) {
  const double tol = 1e-12 * std::max(x.jerk_left, x.norm_jerk_left);
  const bool sum = j * x.tangent + x.cross * a <= x.jerk_left + tol;
  const bool norm = x.norm_cross > 0.0 &&
                    std::hypot(j, x.norm_cross * a) <= x.norm_jerk_left + tol;
  return sum || norm;
}

TEST(TangentialBudget, SumFormAloneReachesTheClosedFormOptimum) {
  // r 10 mm circle at 100 mm/s, the sum form only: c = 3 v k = 30 /s, J' = 35000 mm/s^3.
  TangentialBudget b;
  b.add({1.0, 30.0, 35000.0, 0.0, 0.0});
  double a = 1000.0, j = INFINITY;
  b.split(100.0, a, j);
  const double a_opt = 35000.0 / (30.0 + std::sqrt(35000.0 / 100.0));
  const double best = rampTime(100.0, a_opt, 35000.0 - 30.0 * a_opt);
  EXPECT_NEAR(rampTime(100.0, a, j), best, 1e-6 * best);
  EXPECT_NEAR(a, a_opt, 2e-3 * a_opt);
  EXPECT_TRUE(withinLimit({1.0, 30.0, 35000.0, 0.0, 0.0}, a, j));
}

TEST(TangentialBudget, NormFormOnTheCurvesPlaneIsFaster) {
  // The same axis with the norm form: sqrt(j^2 + (30 a)^2) <= 35000 allows more of both.
  const TangentialBudget::Axis axis{1.0, 30.0, 35000.0, 30.0, 35000.0};
  TangentialBudget b;
  b.add(axis);
  double a = 1700.0, j = INFINITY;
  b.split(100.0, a, j);
  EXPECT_TRUE(withinLimit(axis, a, j));
  const double a_sum = 35000.0 / (30.0 + std::sqrt(35000.0 / 100.0));
  EXPECT_LT(rampTime(100.0, a, j), 0.85 * rampTime(100.0, a_sum, 35000.0 - 30.0 * a_sum));
  // And it is the optimum of the norm form: no nearby a does better.
  for (double f : {0.9, 0.97, 1.03, 1.1}) {
    const double af = f * a;
    const double jf = std::sqrt(35000.0 * 35000.0 - 900.0 * af * af);
    EXPECT_LE(rampTime(100.0, a, j), rampTime(100.0, af, jf) * (1.0 + 1e-6)) << f;
  }
}

TEST(TangentialBudget, KeepsEveryAxisWithinItsJerkAndTheAccelerationBound) {
  const TangentialBudget::Axis axes[3] = {{1.0, 30.0, 35000.0, 30.0, 34000.0},
                                          {0.6, 45.0, 20000.0, 0.0, 0.0},
                                          {0.0, 12.0, 900.0, 20.0, 1200.0}};
  TangentialBudget b;
  for (const auto& x : axes) b.add(x);
  double a = 500.0, j = INFINITY;  // 500: what the axis accelerations leave
  b.split(80.0, a, j);
  EXPECT_GT(a, 0.0);
  EXPECT_LE(a, 500.0);
  EXPECT_GT(j, 0.0);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(withinLimit(axes[i], a, j)) << i;
}

TEST(TangentialBudget, OnALineTakesTheFullLimits) {
  TangentialBudget b;
  b.add({0.8, 0.0, 45000.0, 0.0, 0.0});
  double a = 2500.0, j = INFINITY;
  b.split(50.0, a, j);
  EXPECT_EQ(a, 2500.0);
  EXPECT_DOUBLE_EQ(j, 45000.0 / 0.8);
}

}  // namespace
}  // namespace ncc::vm::motion
