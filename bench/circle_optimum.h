#pragma once
// The offline time-optimal run once around a circle under per-axis limits: the reference
// optimum_bench compares the planner with on circles.
//
// The circle has radius r in the XY plane, starts and ends at rest at (r, 0) and runs
// counter-clockwise. Each of the two axes may use |acceleration| <= A and |jerk| <= J (the
// machine's limits, all of them: no share kept for junctions); the path speed is capped at F.
// With phi = s / r the axis quantities are
//   acceleration: x = -a sin(phi) - v^2/r cos(phi),            y = a cos(phi) - v^2/r sin(phi)
//   jerk:         x = -j sin(phi) - 3va/r cos(phi) + v^3/r^2 sin(phi),
//                 y =  j cos(phi) - 3va/r sin(phi) - v^3/r^2 cos(phi)
// so at each state (s, v, a) the path jerk j lies in an interval and the path acceleration
// under a ceiling. The run-up is integrated in steps of h with the most jerk allowed, riding
// the acceleration ceiling when it reaches it, until braking the acceleration with the least
// jerk allowed lands at a = 0 exactly at the top speed (checked every step by simulating that
// landing): for a jerk-limited run-up this bang-bang order is the optimum, and it uses the
// limits as they are at each point of the circle, not their worst case over the turn.
// The slow-down at the end is the run-up mirrored (y -> -y and time reversed map the last
// part of the circle onto the first and leave every |limit| unchanged), so the time is
// 2 T_up + (2 pi r - 2 s_up) / v_top. Accurate to about h (1e-5 s).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace ncc::bench {

class CircleOptimum {
 public:
  CircleOptimum(double r, double feed_mm_s, double A, double J) : r_(r), A_(A), J_(J) {
    // Cruise: the centripetal acceleration v^2/r and jerk v^3/r^2 fall on one axis at
    // phi = 0, pi/2, ...: each must be within that axis' limit.
    top_ = std::min({feed_mm_s, std::sqrt(A * r), std::cbrt(J * r * r)});
  }

  double topSpeed() const { return top_; }

  // Seconds from rest to rest once around; NaN if the run-up and slow-down do not fit (the
  // contours benchmarked here always reach top speed) or the limits leave no way to land.
  double seconds() const {
    double s = 0.0, v = 0.0, a = 0.0, t = 0.0;
    bool landing = false;
    for (int step = 0;; ++step) {
      if (step > kMaxSteps) return std::numeric_limits<double>::quiet_NaN();
      double lo, hi;
      jerkRange(s, v, a, lo, hi);
      if (!landing && landingSpeed(s, v, a) >= top_) landing = true;
      double j = lo;
      if (!landing) {
        j = hi;
        const double ceiling = accelerationCeiling(s + v * kStep, v + a * kStep);
        if (a + j * kStep > ceiling) j = std::max(lo, (ceiling - a) / kStep);
      }
      const double a_next = a + j * kStep;
      if (landing && a_next <= 0.0) {  // a = 0 within this step: end the run-up there
        const double f = a / (a - a_next);
        t += kStep * f;
        s += v * kStep * f;
        break;
      }
      s += v * kStep + 0.5 * a * kStep * kStep + j * kStep * kStep * kStep / 6.0;
      v += a * kStep + 0.5 * j * kStep * kStep;
      a = a_next;
      t += kStep;
    }
    const double length = 2.0 * std::numbers::pi * r_;
    if (2.0 * s > length) return std::numeric_limits<double>::quiet_NaN();
    return 2.0 * t + (length - 2.0 * s) / top_;
  }

 private:
  static constexpr double kStep = 1e-5;  // s
  // Guards: a run-up or a landing takes far fewer steps than these (a landing a / |j| of a
  // second). More means a state that cannot brake its acceleration: seconds() is then NaN.
  static constexpr int kMaxSteps = 10000000;
  static constexpr int kMaxLandingSteps = 1000000;

  // The path jerks [lo, hi] that keep both axes' jerk within J at (s, v, a).
  void jerkRange(double s, double v, double a, double& lo, double& hi) const {
    const double phi = s / r_, sn = std::sin(phi), cs = std::cos(phi), k = 1.0 / r_;
    lo = -std::numeric_limits<double>::infinity();
    hi = std::numeric_limits<double>::infinity();
    auto axis = [&](double coefficient, double rest) {  // |coefficient * j + rest| <= J
      if (std::abs(coefficient) < 1e-12) return;
      const double j1 = (-J_ - rest) / coefficient, j2 = (J_ - rest) / coefficient;
      lo = std::max(lo, std::min(j1, j2));
      hi = std::min(hi, std::max(j1, j2));
    };
    axis(-sn, -3.0 * v * a * k * cs + v * v * v * k * k * sn);
    axis(cs, -3.0 * v * a * k * sn - v * v * v * k * k * cs);
  }

  // The largest path acceleration that keeps both axes' acceleration within A at (s, v).
  double accelerationCeiling(double s, double v) const {
    const double phi = s / r_, sn = std::sin(phi), cs = std::cos(phi), c = v * v / r_;
    double hi = std::numeric_limits<double>::infinity();
    auto axis = [&](double coefficient, double rest) {  // |coefficient * a + rest| <= A
      if (std::abs(coefficient) < 1e-12) return;
      hi = std::min(hi, std::max((-A_ - rest) / coefficient, (A_ - rest) / coefficient));
    };
    axis(-sn, -c * cs);
    axis(cs, -c * sn);
    return hi;
  }

  // The speed at which a = 0 is reached from (s, v, a) braking the acceleration with the
  // least jerk allowed.
  double landingSpeed(double s, double v, double a) const {
    for (int step = 0; a > 0.0; ++step) {
      double lo, hi;
      jerkRange(s, v, a, lo, hi);
      if (!(lo < 0.0) || step > kMaxLandingSteps) return std::numeric_limits<double>::infinity();
      const double a_next = a + lo * kStep;
      if (a_next <= 0.0) return v + 0.5 * a * kStep * (a / (a - a_next));
      s += v * kStep + 0.5 * a * kStep * kStep;
      v += 0.5 * (a + a_next) * kStep;
      a = a_next;
    }
    return v;
  }

  double r_, A_, J_, top_;
};

}  // namespace ncc::bench
