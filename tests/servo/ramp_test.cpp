// Following error of a constant-velocity ramp (issue 3 "Done when"): v/Kv without
// feed-forward, (1 - w) v/Kv with velocity feed-forward weight w, 0 with ideal feed-forward;
// and under constant acceleration 0 with either feed-forward (velocity FFW: the setpoint is
// symmetrised by the speed loop's lag; torque FFW: it compensates that lag).
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

// Constant acceleration a from rest (0.4 s, long past the loop's transients). With velocity
// feed-forward the position setpoint is delayed by the speed loop's lag (symmetrisation), so
// the position controller's error stays 0 while the axis itself trails the setpoint by the
// lag's response to a parabola, T_eq v - T_eq^2 a. Torque feed-forward cancels the speed
// loop's lag: no error and (up to the sampling) no lag. Without symmetrisation the velocity
// FFW error was T_eq a / Kv, which the position loop pushed back out with an acceleration
// overshoot (acceleration_test.cpp).
struct AccelerationRun {
  double error = 0.0;  // following error (control deviation) at the end
  double lag = 0.0;    // setpoint - actual at the end
};

AccelerationRun constantAcceleration(FeedForwardMode mode, double accel, double t_eq,
                                     long ticks) {
  vm::ServoModel model(servoMachine(servoParams(1.0, mode, t_eq), 1));
  AccelerationRun run;
  for (long k = 0; k <= ticks; ++k) {
    const double t = kCycle * static_cast<double>(k);
    AxisValues sp{};
    sp[0] = 0.5 * accel * t * t;
    const vm::ServoSample& s = model.step(sp);
    run.error = s.following_error[0];
    run.lag = sp[0] - s.actual[0];
  }
  return run;
}

TEST(ServoRamp, VelocityFeedForwardFollowsThroughTheSpeedLoopLag) {
  const double accel = 1000.0;  // mm/s^2
  const double t_eq = 0.004;
  const long ticks = 400;
  const double v = accel * kCycle * static_cast<double>(ticks);
  const AccelerationRun run = constantAcceleration(FeedForwardMode::Velocity, accel, t_eq, ticks);
  const double expected_lag = t_eq * v - t_eq * t_eq * accel;
  std::printf("constant acceleration, velocity FFW: e=%.3g mm, setpoint - actual %.9f mm "
              "(T_eq v - T_eq^2 a = %.9f mm)\n", run.error, run.lag, expected_lag);
  EXPECT_EQ(run.error, 0.0);  // the reference and the motor take bit-identical steps
  // The setpoint is linear between samples, a T^2 / 12 above the parabola on average: the
  // actual follows that polygon.
  EXPECT_NEAR(run.lag, expected_lag - accel * kCycle * kCycle / 12.0, 1e-6);
}

TEST(ServoRamp, TorqueFeedForwardCompensatesTheSpeedLoopLag) {
  const double accel = 1000.0;
  const double t_eq = 0.004;
  const AccelerationRun run = constantAcceleration(FeedForwardMode::Torque, accel, t_eq, 400);
  const double scale = t_eq * accel / kvPerSecond(1.0);  // velocity FFW's error unsymmetrised
  std::printf("constant acceleration, torque FFW: e=%.3g mm, setpoint - actual %.3g mm\n",
              run.error, run.lag);
  EXPECT_LT(std::fabs(run.error), 0.02 * scale);
  EXPECT_LT(std::fabs(run.lag), 0.02 * scale);
}

}  // namespace
}  // namespace ncc
