// The actual motion respects the acceleration limit its setpoint respects. With velocity
// feed-forward the speed setpoint reaches the motor through the speed loop's lag; the position
// setpoint is delayed by the same lag (symmetrisation, docs/servo.md), so the position loop
// does not fight the lag and the motor's speed is the setpoint's speed through a first-order
// lag: its changes are weighted averages of the setpoint's, never larger. (Without the
// symmetrisation the position loop pushed the lag back out: on this S-curve the motor reached
// 2085 mm/s^2 against the setpoint's 2000, 333 samples over the limit.)
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gtest/gtest.h"
#include "servo_test_util.h"

namespace ncc {
namespace {

using test::servoMachine;
using test::servoParams;

constexpr double kCycle = 0.001;

// A jerk-limited (S-curve) move from 0 over `distance` mm: jerk j, acceleration a, speed v,
// seven phases of constant jerk; position at time t.
class SCurve {
 public:
  SCurve(double distance, double v, double a, double j) {
    const double t_jerk = a / j;
    const double t_accel = v / a - t_jerk;  // at constant acceleration
    const double ramp_distance = v * (t_accel + 2.0 * t_jerk);  // accelerate + decelerate
    const double t_cruise = (distance - ramp_distance) / v;
    const double phases[7][2] = {{j, t_jerk}, {0, t_accel},  {-j, t_jerk}, {0, t_cruise},
                                 {-j, t_jerk}, {0, t_accel}, {j, t_jerk}};
    for (int i = 0; i < 7; ++i) phases_[i] = {phases[i][0], phases[i][1]};
  }
  double position(double t) const {
    double p = 0.0, v = 0.0, a = 0.0;
    for (const Phase& ph : phases_) {
      const double d = std::min(t, ph.duration);
      p += v * d + a * d * d / 2.0 + ph.jerk * d * d * d / 6.0;
      v += a * d + ph.jerk * d * d / 2.0;
      a += ph.jerk * d;
      t -= d;
      if (t <= 0.0) break;
    }
    return p;
  }
  double duration() const {
    double d = 0.0;
    for (const Phase& ph : phases_) d += ph.duration;
    return d;
  }

 private:
  struct Phase {
    double jerk = 0.0, duration = 0.0;
  };
  Phase phases_[7];
};

struct Peak {
  double acceleration = 0.0;  // max |motor acceleration|, mm/s^2
  int64_t violations = 0;     // the model's own count of samples over max_acceleration
};

// X moves 200 mm out and back along the S-curve at the axis's limits.
Peak runSCurve(const ServoConfig& servo) {
  MachineConfig m = servoMachine(servo, 1);
  const AxisConfig& x = m.axes[0];
  const SCurve move(200.0, x.max_velocity / 60.0 * 0.5, x.max_acceleration, x.max_jerk);
  const long ticks = static_cast<long>(std::ceil(move.duration() / kCycle));
  vm::ServoModel model(m);
  Peak peak;
  for (long k = 0; k <= 2 * ticks + 500; ++k) {
    const double t = kCycle * static_cast<double>(k);
    AxisValues sp{};
    sp[0] = k <= ticks ? move.position(t) : 200.0 - move.position(t - kCycle * ticks);
    peak.acceleration = std::max(peak.acceleration, std::fabs(model.step(sp).acceleration[0]));
  }
  peak.violations = model.violations(0).acceleration;
  return peak;
}

TEST(ServoAcceleration, VelocityFeedForwardStaysWithinTheSetpointsLimit) {
  const double limit = defaultMachine().axes[0].max_acceleration;
  const Peak peak = runSCurve(servoParams(1.0, FeedForwardMode::Velocity, 0.004));
  std::printf("S-curve at a = %.0f mm/s^2, velocity FFW: peak actual acceleration %.9f mm/s^2 "
              "(%+.3g relative), %lld samples over the limit\n", limit, peak.acceleration,
              peak.acceleration / limit - 1.0, static_cast<long long>(peak.violations));
  // Margin: rounding only (the sampled S-curve's second differences are at most a).
  EXPECT_LE(peak.acceleration, limit * (1.0 + 1e-9));
  EXPECT_GT(peak.acceleration, 0.95 * limit);  // the move does use the limit
  EXPECT_EQ(peak.violations, 0);
}

// Without feed-forward the loop (Kv, then the lag) is overdamped here (4 T_eq Kv < 1): its
// step response does not overshoot, so neither does the acceleration.
TEST(ServoAcceleration, WithoutFeedForwardTheOverdampedLoopOnlySmoothes) {
  const double limit = defaultMachine().axes[0].max_acceleration;
  const Peak peak = runSCurve(servoParams(1.0, FeedForwardMode::None, 0.004));
  std::printf("S-curve, no FFW: peak actual acceleration %.6f mm/s^2 (%+.3g relative)\n",
              peak.acceleration, peak.acceleration / limit - 1.0);
  EXPECT_LE(peak.acceleration, limit * (1.0 + 1e-9));
  EXPECT_EQ(peak.violations, 0);
}

// Torque feed-forward adds T_eq times the setpoint's acceleration (a backward difference) to
// the speed setpoint to cancel the speed loop's lag. For the sampled lag the exact inverse
// would weigh the speed step by b / (1 - b) = T_eq / T - 1/2 + O(T / T_eq) instead of
// T_eq / T: the speed leads by about T/2, so at the end of a jerk phase the acceleration
// overshoots by up to J T / 2 (25 mm/s^2 at J = 50 m/s^3, 1 %; the position loop takes back a
// little). A known limit of the discrete torque path (docs/servo.md), pinned so it cannot grow.
TEST(ServoAcceleration, TorqueFeedForwardOvershootsByTheSamplingOnly) {
  const double limit = defaultMachine().axes[0].max_acceleration;
  const Peak peak = runSCurve(servoParams(1.0, FeedForwardMode::Torque, 0.004));
  std::printf("S-curve, torque FFW: peak actual acceleration %.6f mm/s^2 (%+.3g relative), "
              "%lld samples over the limit\n", peak.acceleration, peak.acceleration / limit - 1.0,
              static_cast<long long>(peak.violations));
  EXPECT_LE(peak.acceleration, limit * 1.015);
}

}  // namespace
}  // namespace ncc
