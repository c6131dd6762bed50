// The ramp envelope (ramp_envelope.h): what it allows must keep every axis within its limits
// at every state a profile with those limits can reach, checked here by dense sampling
// independent of the envelope's interval bounds; it must never be slower than the
// top-speed budget it starts from; and through the planner a fast small circle gains from it
// while every sampled setpoint stays within the axis limits.
#include "ncc/vm/motion/ramp_envelope.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "gtest/gtest.h"
#include "motion_test_util.h"
#include "ncc/vm/motion/limits.h"

namespace ncc::vm::motion {
namespace {

using namespace motion_test;

// Every axis at (v, a_t, j_t) of a curve: the sum or the norm bound holds.
bool axisWithin(const RampEnvelope::Axis& x, double v, double kappa, double rate, double a,
                double j) {
  const double tol = 1e-9;
  const double centripetal = v * v * kappa, cross = 3.0 * v * kappa * a, rotation = v * v * v * rate;
  const bool on_plane = x.normal > 0.0;
  const bool acc = a * x.tangent + centripetal * x.normal <= x.acceleration * (1 + tol) ||
                   (on_plane && std::hypot(a, centripetal) <= x.acceleration * (1 + tol));
  const bool jerk = j * x.tangent + (cross + rotation) * x.normal <= x.jerk * (1 + tol) ||
                    (on_plane && std::hypot(j, cross) + rotation <= x.jerk * (1 + tol));
  return acc && jerk;
}

TEST(RampEnvelope, WidenedLimitsHoldAtEveryReachableState) {
  Random rng(7);
  int widened = 0;
  for (int trial = 0; trial < 200; ++trial) {
    double top = rng.uniform(5.0, 300.0);
    const double kappa = 1.0 / rng.uniform(0.5, 100.0), rate = kappa * kappa;
    std::vector<RampEnvelope::Axis> axes;
    const int n = 2 + rng.below(3);
    for (int i = 0; i < n; ++i) {
      const RampEnvelope::Axis x{rng.uniform(0.3, 1.0), rng.below(3) == 0 ? 0.0 : rng.uniform(0.3, 1.0),
                                 rng.uniform(800.0, 4000.0), rng.uniform(10000.0, 80000.0)};
      axes.push_back(x);
      // The top speed is capped as segmentLimits caps it: the centripetal part at most 3/4
      // of the axis acceleration, the rotation at most 1/3 of its jerk.
      if (x.normal > 0.0) {
        top = std::min(top, std::sqrt(kCentripetalShare * x.acceleration / (kappa * x.normal)));
        top = std::min(top, std::cbrt(x.jerk / 3.0 / (rate * x.normal)));
      }
    }
    RampEnvelope env(top, kappa, rate);
    TangentialBudget budget;
    for (const RampEnvelope::Axis& x : axes) {
      env.add(x);
      budget.add({x.tangent, 3.0 * top * kappa * x.normal, x.jerk - top * top * top * rate * x.normal,
                  x.normal > 0.0 ? 3.0 * top * kappa : 0.0,
                  x.normal > 0.0 ? x.jerk - top * top * top * rate : 0.0});
    }
    // The top-speed budget's choice, as segmentLimits makes it (acceleration from the axes).
    double a0 = 1e300;
    for (const auto& x : axes) {
      const double c = top * top * kappa;
      double ai = x.tangent > 0.0 ? (x.acceleration - c * x.normal) / x.tangent : 1e300;
      if (x.normal > 0.0 && x.acceleration >= c) ai = std::max(ai, std::sqrt(x.acceleration * x.acceleration - c * c));
      a0 = std::min(a0, ai);
    }
    if (!(a0 > 0.0)) continue;
    double j0 = INFINITY;
    budget.split(top, a0, j0);
    if (!(a0 > 0.0 && j0 > 0.0)) continue;
    // The closed-form largest jerk agrees with a fine bisection on holds(): exactly on the
    // coarse intervals; on the halved ones it stops halving where that gains less than
    // kHalvingGain, so it may lie up to that share below, never above.
    using Resolution = RampEnvelope::Resolution;
    for (double f : {1.0, 1.5, 2.5}) {
      const double a_try = f * a0;
      for (const Resolution resolution : {Resolution::Coarse, Resolution::Fine}) {
        double lo = 0.0, hi = 1e7;
        for (int k = 0; k < 80; ++k) {
          const double mid = 0.5 * (lo + hi);
          (env.holds(a_try, mid, resolution) ? lo : hi) = mid;
        }
        const double bound = std::min(env.jerkBound(a_try, resolution), 1e7);
        const double slack = resolution == Resolution::Coarse
                                 ? 0.0
                                 : RampEnvelope::kHalvingGain * lo;
        EXPECT_LE(bound, lo + 1e-9 * std::max(lo, 1.0)) << "trial " << trial << " a " << a_try;
        EXPECT_GE(bound, lo - slack - 1e-9 * std::max(lo, 1.0)) << "trial " << trial << " a " << a_try;
      }
    }
    double a = a0, j = j0;
    env.widen(a, j);
    EXPECT_LE(top / a + a / j, (top / a0 + a0 / j0) * (1.0 + 1e-12)) << trial;
    if (a != a0 || j != j0) ++widened;
    // Dense sampling of the envelope: every v, every |a_t| up to min(a, sqrt(2 j (top - v))),
    // the full jerk.
    for (int s = 0; s <= 400; ++s) {
      const double v = std::min(top, top * s / 400.0);
      const double alpha = std::min(a, std::sqrt(2.0 * j * (top - v)));
      for (double f : {0.0, 0.5, 1.0}) {
        for (const auto& x : axes)
          ASSERT_TRUE(axisWithin(x, v, kappa, rate, f * alpha, j))
              << "trial " << trial << " v " << v << " a_t " << f * alpha << " j " << j;
      }
    }
  }
  EXPECT_GT(widened, 50);  // the envelope usually finds a faster pair
}

TEST(RampEnvelope, CircleLimitsHoldAtEveryOrientation) {
  // A circle in a coordinate plane (tangent and normal bounds 1 on both plane axes, rotation
  // -v^3 k^2 T along the tangent): the budget and the envelope take the rotation with the
  // tangential jerk (rotation_along_tangent). Ground truth, independent of both forms: each
  // plane axis at every orientation phi of the circle, a_i = a_t cos(phi) - v^2 k sin(phi) and
  // j_i = (j_t - v^3 k^2) cos(phi) - 3 v k a_t sin(phi), for both signs of a_t and j_t.
  Random rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const double kappa = 1.0 / rng.uniform(0.5, 100.0), rate = kappa * kappa;
    const RampEnvelope::Axis axes[2] = {
        {1.0, 1.0, rng.uniform(800.0, 4000.0), rng.uniform(10000.0, 80000.0)},
        {1.0, 1.0, rng.uniform(800.0, 4000.0), rng.uniform(10000.0, 80000.0)}};
    double top = rng.uniform(5.0, 300.0);
    for (const auto& x : axes) {
      top = std::min(top, std::sqrt(kCentripetalShare * x.acceleration / kappa));
      top = std::min(top, std::cbrt(x.jerk / 3.0 / rate));
    }
    const double c = top * top * kappa, cross = 3.0 * top * kappa, rotation = top * top * top * rate;
    RampEnvelope env(top, kappa, rate, /*rotation_along_tangent=*/true);
    TangentialBudget budget;
    double a0 = 1e300;
    for (const auto& x : axes) {
      env.add(x);
      budget.add({1.0, cross, x.jerk - rotation, cross, x.jerk, rotation});
      a0 = std::min(a0, std::max(x.acceleration - c, std::sqrt(x.acceleration * x.acceleration - c * c)));
    }
    double j0 = INFINITY;
    budget.split(top, a0, j0);
    ASSERT_GT(a0, 0.0);
    ASSERT_GT(j0, 0.0);
    double a = a0, j = j0;
    env.widen(a, j);
    for (const double limit_a : {a0, a}) {
      const double limit_j = limit_a == a0 ? j0 : j;
      for (int s = 0; s <= 200; ++s) {
        const double v = std::min(top, top * s / 200.0);
        const double alpha = std::min(limit_a, std::sqrt(2.0 * limit_j * (top - v)));
        for (double at : {alpha, -alpha, 0.5 * alpha})
          for (double jt : {limit_j, -limit_j})
            for (int k = 0; k < 72; ++k) {
              const double phi = 2.0 * std::numbers::pi * k / 72.0;
              const double acc = at * std::cos(phi) - v * v * kappa * std::sin(phi);
              const double jerk =
                  (jt - v * v * v * rate) * std::cos(phi) - 3.0 * v * kappa * at * std::sin(phi);
              for (const auto& x : axes) {
                ASSERT_LE(std::abs(acc), x.acceleration * (1 + 1e-9)) << trial << " v " << v;
                ASSERT_LE(std::abs(jerk), x.jerk * (1 + 1e-9)) << trial << " v " << v;
              }
            }
      }
    }
  }
}

TEST(RampEnvelope, BindingSpeedIntervalsAreHalvedTowardsTheEnvelope) {
  // A circle of r 10 at F6000 on the default machine (A 2000, 90 % of J 50000): the shortest
  // ramp V/a + a/j over the envelope itself, found by sampling it at 4000 speeds, against the
  // ramp widen() finds. On 16 intervals alone it was 3.6 % longer: each interval's bound
  // takes alpha at its start and the rotation and cross terms at its end.
  const double top = 100.0, kappa = 0.1, rate = kappa * kappa, A = 2000.0, J = 45000.0;
  RampEnvelope env(top, kappa, rate, /*rotation_along_tangent=*/true);
  TangentialBudget budget;
  const double cross = 3.0 * top * kappa, rotation = top * top * top * rate, c = top * top * kappa;
  for (int i = 0; i < 2; ++i) {
    env.add({1.0, 1.0, A, J});
    budget.add({1.0, cross, J - rotation, cross, J, rotation});
  }
  double a = std::max(A - c, std::sqrt(A * A - c * c)), j = INFINITY;
  budget.split(top, a, j);
  env.widen(a, j);
  auto within = [&](double at, double jt) {  // the envelope of (at, jt), sampled
    for (int s = 0; s <= 4000; ++s) {
      const double v = top * s / 4000.0;
      const double alpha = std::min(at, std::sqrt(2.0 * jt * (top - v)));
      const double centripetal = v * v * kappa, turn = 3.0 * v * kappa * alpha;
      const double rot = v * v * v * rate;
      if (std::hypot(alpha, centripetal) > A || std::hypot(jt + rot, turn) > J) return false;
    }
    return true;
  };
  double best = INFINITY;
  for (double at = 1000.0; at <= A; at += 5.0) {
    double lo = 0.0, hi = J;
    for (int k = 0; k < 40; ++k) {
      const double mid = 0.5 * (lo + hi);
      (within(at, mid) ? lo : hi) = mid;
    }
    if (lo > 0.0) best = std::min(best, top / at + at / lo);
  }
  EXPECT_LE(top / a + a / j, 1.005 * best) << "a " << a << " j " << j;
  EXPECT_TRUE(within(a, j * (1.0 - 1e-9)));
}

TEST(RampEnvelope, SmallFastCircleGainsAndKeepsEveryLimit) {
  // G2 circles of r 3..25 mm at F3000..F9000 from rest: the planned time against the
  // rest-to-rest S-curve over the circle at full axis limits (a lower bound within 0.3 % on
  // circles, bench/circle_optimum.h), and every sampled setpoint within the axis limits.
  const MachineConfig m = defaultMachine();
  const double A = m.axes[0].max_acceleration, J = m.axes[0].max_jerk;
  for (double r : {3.0, 10.0, 25.0}) {
    for (double feed : {3000.0, 6000.0, 9000.0}) {
      const Trace t = run(m, {arc(xyz(r, 0, 0), xyz(r, 0, 0), 0, 1, 0.0, 0.0, false, feed)});
      const Worst w = check(m, t);
      EXPECT_LE(w.velocity, 1.0 + kTolerance) << r << " " << feed;
      EXPECT_LE(w.acceleration, 1.0 + kTolerance) << r << " " << feed;
      EXPECT_LE(w.jerk, 1.0 + kTolerance) << r << " " << feed;
      EXPECT_EQ(t.points.back(), xyz(r, 0, 0));
      if (r == 10.0 && feed == 6000.0) {
        // 0.781 s with the top-speed budget alone; the lower bound is 0.718 s.
        const double bound = restToRestTime(2.0 * std::numbers::pi * r, 100.0, A, J);
        EXPECT_LT(static_cast<double>(t.ticks() - 1) * m.ipo_cycle_seconds, 1.05 * bound);
      }
    }
  }
}

}  // namespace
}  // namespace ncc::vm::motion
