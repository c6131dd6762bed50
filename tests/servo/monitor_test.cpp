// Following-error monitoring (alarm 25050), standstill monitoring (25040) and limit counts.
#include <cmath>

#include "gtest/gtest.h"
#include "servo_test_util.h"

namespace ncc {
namespace {

using test::kvPerSecond;
using test::servoMachine;
using test::servoParams;

constexpr double kCycle = 0.001;

// A ramp at `speed` mm/s on Y (axis 1) for 1 s, then at rest for 1 s.
void runRamp(vm::ServoModel& model, double speed) {
  AxisValues sp{};
  for (long k = 0; k <= 2000; ++k) {
    sp[1] = speed * kCycle * static_cast<double>(std::min(k, 1000L));
    model.step(sp);
  }
}

MachineConfig rampMachine(double contour_tol) {
  MachineConfig m = servoMachine(servoParams(1.0, FeedForwardMode::None, 0.004));
  for (AxisConfig& a : m.axes) {
    a.servo.contour_tol = contour_tol;
    a.servo.standstill_pos_tol = 0.2;
  }
  return m;
}

TEST(ServoMonitor, NoAlarmBelowTheLimit) {
  const double steady = 10.0 / kvPerSecond(1.0);  // 0.6 mm
  vm::ServoModel model(rampMachine(steady * 1.01));
  runRamp(model, 10.0);
  EXPECT_EQ(model.alarm().code, 0);
}

TEST(ServoMonitor, ContourAlarmAboveTheLimit) {
  const double steady = 10.0 / kvPerSecond(1.0);
  vm::ServoModel model(rampMachine(steady * 0.99));
  runRamp(model, 10.0);
  const vm::ServoAlarm& alarm = model.alarm();
  EXPECT_EQ(alarm.code, vm::kAlarmContour);
  EXPECT_EQ(alarm.code, 25050);
  EXPECT_EQ(alarm.axis, 1);
  EXPECT_GT(alarm.value, steady * 0.99);
  // The error rises as steady * (1 - e^(p t)) after the start-up, p the slow pole of
  // T s^2 + s + Kv: it crosses 0.99 * steady after about ln(100) / |p| (256 ms).
  const double kv = kvPerSecond(1.0), t_eq = 0.004;
  const double pole = (1.0 - std::sqrt(1.0 - 4.0 * t_eq * kv)) / (2.0 * t_eq);
  EXPECT_NEAR(static_cast<double>(alarm.tick), std::log(100.0) / pole / kCycle, 5);
  // Reset clears it.
  model.reset(AxisValues{});
  EXPECT_EQ(model.alarm().code, 0);
}

TEST(ServoMonitor, StandstillAlarmWhenTheErrorDoesNotDecay) {
  // Kv 0.01 (m/min)/mm: the error decays with a 6 s time constant, still above 0.2 mm when
  // standstill monitoring starts 0.4 s after the setpoint stopped.
  MachineConfig m = servoMachine(servoParams(0.01, FeedForwardMode::None, 0.004));
  m.axes[1].servo.standstill_pos_tol = 0.2;
  m.axes[1].servo.standstill_delay_time = 0.4;
  vm::ServoModel model(m);
  runRamp(model, 1.0);
  EXPECT_EQ(model.alarm().code, vm::kAlarmStandstill);
  EXPECT_EQ(model.alarm().axis, 1);
  EXPECT_EQ(model.alarm().tick, 1000 + 400 + 1);
}

TEST(ServoMonitor, CountsLimitViolations) {
  MachineConfig m = servoMachine(servoParams(1.0, FeedForwardMode::Velocity, 0.004));
  m.axes[1].max_travel = 5.0;
  m.axes[1].max_velocity = 300.0;    // 5 mm/s
  m.axes[1].rapid_velocity = 300.0;
  vm::ServoModel model(m);
  runRamp(model, 10.0);  // 10 mm/s to Y10
  const vm::LimitViolations& v = model.violations(1);
  EXPECT_GT(v.travel, 900);    // from Y5 on, most of 1.5 s
  EXPECT_GT(v.velocity, 900);  // the whole ramp
  EXPECT_EQ(v.acceleration, 2);  // the velocity steps at start and stop
  EXPECT_EQ(model.violations(0), vm::LimitViolations{});
}

}  // namespace
}  // namespace ncc
