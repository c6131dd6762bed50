// Following error of a constant-velocity ramp (issue 3 "Done when"): v/Kv without
// feed-forward, (1 - w) v/Kv with velocity feed-forward weight w, 0 with ideal feed-forward;
// and under constant acceleration T_eq a/Kv with velocity feed-forward, ~0 with torque
// feed-forward (which compensates the speed-loop lag).
#include <cmath>
#include <cstdio>

#include "gtest/gtest.h"
#include "servo_test_util.h"

namespace ncc {
namespace {

using test::kvPerSecond;
using test::servoMachine;
using test::servoParams;

constexpr double kCycle = 0.001;
constexpr double kSpeed = 10.0;  // mm/s (600 mm/min)

// Runs a ramp at kSpeed on X from rest for `seconds` and returns the last following error.
double rampError(const ServoConfig& servo, double seconds) {
  vm::ServoModel model(servoMachine(servo, 1));
  const long ticks = std::lround(seconds / kCycle);
  double error = 0.0;
  for (long k = 0; k <= ticks; ++k) {
    AxisValues sp{};
    sp[0] = kSpeed * kCycle * static_cast<double>(k);
    error = model.step(sp).following_error[0];
  }
  return error;
}

TEST(ServoRamp, WithoutFeedForwardTheErrorIsVOverKv) {
  for (double kv : {0.5, 1.0, 3.0}) {
    ServoConfig s = servoParams(kv, FeedForwardMode::None, 0.004);
    const double expected = kSpeed / kvPerSecond(kv);
    const double e = rampError(s, 3.0);
    std::printf("ramp kv=%.1f: e=%.12f mm, v/Kv=%.12f mm\n", kv, e, expected);
    EXPECT_NEAR(e, expected, 1e-9) << "kv " << kv;
  }
}

TEST(ServoRamp, VelocityFeedForwardWeightScalesTheError) {
  ServoConfig s = servoParams(1.0, FeedForwardMode::Velocity, 0.004);
  s.velo_ffw_weight = 0.5;
  EXPECT_NEAR(rampError(s, 3.0), 0.5 * kSpeed / kvPerSecond(1.0), 1e-9);
}

TEST(ServoRamp, IdealFeedForwardRemovesTheError) {
  for (FeedForwardMode mode : {FeedForwardMode::Velocity, FeedForwardMode::Torque}) {
    ServoConfig s = servoParams(1.0, mode, 0.004);
    const double e = rampError(s, 3.0);
    std::printf("ramp with feed-forward mode %d: e=%.3g mm\n", static_cast<int>(mode), e);
    EXPECT_LT(std::fabs(e), 1e-9);
  }
}

// Constant acceleration a from rest: the speed loop lags the feed-forward speed by T_eq a,
// which the position loop must make up (e = T_eq a / Kv); torque feed-forward supplies it.
TEST(ServoRamp, TorqueFeedForwardCompensatesTheSpeedLoopLag) {
  const double accel = 1000.0;  // mm/s^2
  const double t_eq = 0.004;
  auto errorAfter = [&](FeedForwardMode mode) {
    vm::ServoModel model(servoMachine(servoParams(1.0, mode, t_eq), 1));
    double e = 0.0;
    for (long k = 0; k <= 400; ++k) {  // 0.4 s: long past the loop's transients
      const double t = kCycle * static_cast<double>(k);
      AxisValues sp{};
      sp[0] = 0.5 * accel * t * t;
      e = model.step(sp).following_error[0];
    }
    return e;
  };
  const double velocity_only = errorAfter(FeedForwardMode::Velocity);
  const double torque = errorAfter(FeedForwardMode::Torque);
  const double expected = t_eq * accel / kvPerSecond(1.0);
  std::printf("constant acceleration: velocity FFW e=%.6f mm (T_eq a/Kv=%.6f), torque FFW "
              "e=%.3g mm\n", velocity_only, expected, torque);
  // The discrete backward differences and the exact lag shift this by O(T / T_eq).
  EXPECT_NEAR(velocity_only, expected, 0.15 * expected);
  EXPECT_LT(std::fabs(torque), 0.02 * expected);
}

}  // namespace
}  // namespace ncc
