// A circle at constant F through the servo model: the steady-state radius of the actual path
// against the continuous-time formula of docs/servo.md,
//   r_act / r = |G(jw)|,  G(s) = (Kv F(s) + v s + u T s^2) / (T s^2 + s + Kv)
// (Kv in 1/s, T the speed loop's equivalent time constant, v the velocity feed-forward weight,
// u = 1 with torque feed-forward, F(s) = 1 / (1 + T s) the symmetrisation of the setpoint with
// velocity feed-forward, else 1). Without feed-forward and T = 0 this is the classic
// 1 / sqrt(1 + (w/Kv)^2); with ideal velocity feed-forward G = 1 / (1 + T s), whatever Kv.
// The discrete model's own steady state is |H(e^(jwT_c))| (docs/servo.md):
//   H(z) = P(z) (Kv S(z) + z F(z)) / (z - 1 + Kv P(z)),
//   P(z) = (T_c - L) + L (1 - b) / (z - b),  b = exp(-T_c/T), L = T (1 - b),
//   S(z) = P(z) / T_c with velocity feed-forward (and T > 0), else 1,
//   F(z) = v (1 - 1/z) / T_c + u T (1 - 1/z)^2 / T_c^2      (T_c: the IPO cycle).
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>

#include "gtest/gtest.h"
#include "servo_test_util.h"

namespace ncc {
namespace {

using test::circleSetpoint;
using test::kvPerSecond;
using test::servoMachine;
using test::servoParams;

constexpr double kCycle = 0.001;
constexpr double kRadius = 10.0;  // mm

// Velocity feed-forward delays the setpoint by the speed loop's lag (symmetrisation).
bool symmetrised(const ServoConfig& s) {
  return s.ffw_mode == FeedForwardMode::Velocity && s.equiv_speedctrl_time > 0.0;
}

double analyticRatio(const ServoConfig& s, double omega) {
  using C = std::complex<double>;
  const double kv = kvPerSecond(s.kv);
  const double t = s.equiv_speedctrl_time;
  const double w = s.ffw_mode == FeedForwardMode::None ? 0.0 : s.velo_ffw_weight;
  const double u = s.ffw_mode == FeedForwardMode::Torque ? 1.0 : 0.0;
  const C jw(0.0, omega);
  const C filter = symmetrised(s) ? 1.0 / (1.0 + t * jw) : C(1.0);
  return std::abs((kv * filter + w * jw + u * t * jw * jw) / (t * jw * jw + jw + kv));
}

double discreteRatio(const ServoConfig& s, double omega) {
  using C = std::complex<double>;
  const double kv = kvPerSecond(s.kv);
  const double t = s.equiv_speedctrl_time;
  const double w = s.ffw_mode == FeedForwardMode::None ? 0.0 : s.velo_ffw_weight;
  const double u = s.ffw_mode == FeedForwardMode::Torque ? 1.0 : 0.0;
  const double b = t > 0.0 ? std::exp(-kCycle / t) : 0.0;
  const double lag = t * (1.0 - b);
  const C z = std::polar(1.0, omega * kCycle);
  const C p = (kCycle - lag) + lag * (1.0 - b) / (z - b);
  const C filter = symmetrised(s) ? p / kCycle : C(1.0);
  const C d = 1.0 - 1.0 / z;
  const C f = w * d / kCycle + u * t * d * d / (kCycle * kCycle);
  return std::abs(p * (kv * filter + z * f) / (z - 1.0 + kv * p));
}

struct RadiusRange {
  double min = 1e300, max = -1e300;
};

// Runs 3 s to settle, then measures the actual radius over one full revolution.
RadiusRange actualRadius(const ServoConfig& servo, double omega) {
  vm::ServoModel model(servoMachine(servo));
  model.reset(circleSetpoint(kRadius, omega, kCycle, 0));
  const long settle = 3000;
  const long period = std::lround(2.0 * std::acos(-1.0) / omega / kCycle);
  RadiusRange r;
  for (long k = 0; k <= settle + period; ++k) {
    const vm::ServoSample& s = model.step(circleSetpoint(kRadius, omega, kCycle, k));
    if (k < settle) continue;
    const double rad = std::hypot(s.actual[0], s.actual[1]);
    r.min = std::min(r.min, rad);
    r.max = std::max(r.max, rad);
  }
  return r;
}

struct Case {
  const char* name;
  ServoConfig servo;
  double feed;       // mm/min
  double tolerance;  // against the continuous formula, mm (the exact discrete one: 1e-9)
};

TEST(ServoCircle, RadiusErrorMatchesTheAnalyticFormula) {
  // Continuous tolerances: 10 % of the radius error (the cycle is 1.7-5 % of 1/Kv; the
  // sampled loop acts about half a cycle late), 0.02 mm for torque FFW at 11 m/s^2; with the
  // symmetrised velocity FFW the actual path is the setpoint polygon through the lag, which
  // cuts the circle by about r (w T_c)^2 / 12 (8e-5 mm at F6000, 9e-4 mm at F20000).
  ServoConfig half_weight = servoParams(1.0, FeedForwardMode::Velocity, 0.004);
  half_weight.velo_ffw_weight = 0.5;
  const Case cases[] = {
      {"no FFW, T=0, F6000", servoParams(1.0, FeedForwardMode::None, 0.0), 6000.0, 0.15},
      {"no FFW, T=4ms, F6000", servoParams(1.0, FeedForwardMode::None, 0.004), 6000.0, 0.13},
      {"no FFW, Kv3, F3000", servoParams(3.0, FeedForwardMode::None, 0.004), 3000.0, 0.003},
      {"vel FFW, T=4ms, F6000", servoParams(1.0, FeedForwardMode::Velocity, 0.004), 6000.0,
       1.5e-4},
      {"vel FFW, T=4ms, F20000", servoParams(1.0, FeedForwardMode::Velocity, 0.004), 20000.0,
       1e-3},
      {"vel FFW, Kv3, F20000", servoParams(3.0, FeedForwardMode::Velocity, 0.004), 20000.0,
       1e-3},
      {"vel FFW 0.5, F6000", half_weight, 6000.0, 0.02},
      {"vel FFW, T=0, F6000", servoParams(1.0, FeedForwardMode::Velocity, 0.0), 6000.0, 1e-9},
      {"torque FFW, T=4ms, F20000", servoParams(1.0, FeedForwardMode::Torque, 0.004), 20000.0,
       0.02},
  };
  for (const Case& c : cases) {
    const double omega = c.feed / 60.0 / kRadius;
    const RadiusRange r = actualRadius(c.servo, omega);
    const double continuous = kRadius * (1.0 - analyticRatio(c.servo, omega));
    const double discrete = kRadius * (1.0 - discreteRatio(c.servo, omega));
    const double error_min = kRadius - r.max, error_max = kRadius - r.min;
    std::printf("circle %-26s: radius error %.9f..%.9f mm, discrete H %.9f, continuous %.6f mm\n",
                c.name, error_min, error_max, discrete, continuous);
    // The model against its own exact steady state: only rounding and the decayed start-up.
    EXPECT_NEAR(error_min, discrete, 1e-9) << c.name;
    EXPECT_NEAR(error_max, discrete, 1e-9) << c.name;
    // Against continuous time: the difference is O(T) (the cycle against 1/Kv and T_eq).
    EXPECT_NEAR(error_min, continuous, c.tolerance) << c.name;
    EXPECT_NEAR(error_max, continuous, c.tolerance) << c.name;
  }
}

// Manual (K3, "influence on the servo gain"): with feed-forward set correctly the response to
// setpoint changes is as dynamic as the speed loop's, and Kv barely affects the radius error.
// In this model it is exactly the speed loop's: the same radius for any Kv.
TEST(ServoCircle, WithVelocityFeedForwardKvDoesNotChangeTheRadius) {
  const double omega = 20000.0 / 60.0 / kRadius;
  const RadiusRange slow = actualRadius(servoParams(0.5, FeedForwardMode::Velocity, 0.004), omega);
  const RadiusRange fast = actualRadius(servoParams(5.0, FeedForwardMode::Velocity, 0.004), omega);
  const double lag = kRadius * (1.0 - 1.0 / std::hypot(1.0, omega * 0.004));
  std::printf("velocity FFW at F20000: radius error %.9f mm (Kv 0.5), %.9f mm (Kv 5), speed "
              "loop alone %.9f mm\n", kRadius - slow.max, kRadius - fast.max, lag);
  EXPECT_NEAR(slow.min, fast.min, 1e-12);
  EXPECT_NEAR(slow.max, fast.max, 1e-12);
}

// The brief's closed form for a first-order position loop (no FFW, no speed-loop lag).
TEST(ServoCircle, FirstOrderLoopShrinksTheCircleByTheClassicFormula) {
  const ServoConfig s = servoParams(2.0, FeedForwardMode::None, 0.0);
  const double omega = 4000.0 / 60.0 / kRadius;
  const double ratio = omega / kvPerSecond(2.0);
  const double expected = kRadius * (1.0 - 1.0 / std::sqrt(1.0 + ratio * ratio));
  const RadiusRange r = actualRadius(s, omega);
  std::printf("first-order loop: radius error %.6f mm, r (1 - 1/sqrt(1 + (w/Kv)^2)) = %.6f mm, "
              "discrete %.6f mm\n", kRadius - r.max, expected,
              kRadius * (1.0 - discreteRatio(s, omega)));
  EXPECT_NEAR(kRadius - r.max, expected, 0.1 * expected);
  EXPECT_NEAR(kRadius - r.min, expected, 0.1 * expected);
  EXPECT_NEAR(kRadius - r.max, kRadius * (1.0 - discreteRatio(s, omega)), 1e-9);
}

}  // namespace
}  // namespace ncc
