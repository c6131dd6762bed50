// What ServoModel::step() reports, whatever the layout inside: every axis is simulated on its
// own (an axis of a six-axis machine gives bit for bit the samples it gives alone), the
// setpoint is echoed, and axes beyond the machine's stay 0.
#include <cmath>
#include <cstring>
#include <vector>

#include "gtest/gtest.h"
#include "servo_test_util.h"

namespace ncc {
namespace {

// Six axes, each configured differently (feed-forward modes, T_eq, backlash, tables).
MachineConfig mixedMachine() {
  MachineConfig m = test::servoMachine(ServoConfig{}, 6);
  const FeedForwardMode modes[] = {FeedForwardMode::Velocity, FeedForwardMode::Torque,
                                   FeedForwardMode::None};
  for (int i = 0; i < 6; ++i) {
    ServoConfig& s = m.axes[i].servo;
    s.ffw_mode = modes[i % 3];
    s.kv = 0.5 + 0.7 * i;
    s.equiv_speedctrl_time = i == 4 ? 0.0 : 0.001 * (i + 1);
    s.velo_ffw_weight = i == 3 ? 0.8 : 1.0;
    s.backlash = 0.004 * (i % 3);
    s.backlash_compensation = 0.003 * (i % 2);
    if (i % 2 == 0) s.pitch_error = PitchTable{-30.0, 7.5, {0.0, 0.002, -0.001, 0.003, 0.0}};
    if (i >= 3) s.pitch_compensation = PitchTable{-30.0, 5.0, {0.001, -0.002, 0.0, 0.002}};
    s.contour_tol = 0.05;
    s.standstill_pos_tol = 0.01;
  }
  return m;
}

double setpointOf(int axis, long k) {
  const double t = 0.001 * static_cast<double>(k);
  return k > 3000 ? 2.0 : 20.0 * std::sin(2.0 * t + axis) + 0.2 * std::sin(23.0 * t);
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

TEST(ServoSample, EachAxisIsSimulatedOnItsOwn) {
  const MachineConfig m = mixedMachine();
  vm::ServoModel all(m);
  std::vector<vm::ServoModel> alone;
  for (int i = 0; i < 6; ++i) {
    MachineConfig one = m;
    one.axes = {m.axes[i]};
    alone.emplace_back(one);
  }
  for (long k = 0; k < 4000; ++k) {
    AxisValues sp{};
    for (int i = 0; i < 6; ++i) sp[i] = setpointOf(i, k);
    const vm::ServoSample& s = all.step(sp);
    for (int i = 0; i < 6; ++i) {
      AxisValues one{};
      one[0] = sp[i];
      const vm::ServoSample& o = alone[i].step(one);
      ASSERT_TRUE(sameBits(s.actual[i], o.actual[0])) << "axis " << i << " tick " << k;
      ASSERT_TRUE(sameBits(s.following_error[i], o.following_error[0])) << i << " " << k;
      ASSERT_TRUE(sameBits(s.velocity[i], o.velocity[0])) << i << " " << k;
      ASSERT_TRUE(sameBits(s.acceleration[i], o.acceleration[0])) << i << " " << k;
    }
  }
  for (int i = 0; i < 6; ++i) EXPECT_EQ(all.violations(i), alone[i].violations(0)) << i;
  // The alarm is the first axis's to trip (both models trip at tick 0 here).
  EXPECT_NE(all.alarm().code, 0);
  EXPECT_EQ(all.alarm().code, alone[all.alarm().axis].alarm().code);
  EXPECT_EQ(all.alarm().tick, alone[all.alarm().axis].alarm().tick);
}

TEST(ServoSample, EchoesTheSetpointAndIgnoresAxesBeyondTheMachine) {
  vm::ServoModel model(test::servoMachine(ServoConfig{}, 2));
  AxisValues sp{};
  for (int i = 0; i < kMaxAxes; ++i) sp[i] = 1.0 + i;
  const vm::ServoSample& s = model.step(sp);
  EXPECT_EQ(s.tick, 0);
  EXPECT_EQ(s.setpoint[0], 1.0);
  EXPECT_EQ(s.setpoint[1], 2.0);
  for (int i = 2; i < kMaxAxes; ++i) {
    EXPECT_EQ(s.setpoint[i], 0.0) << i;
    EXPECT_EQ(s.actual[i], 0.0) << i;
    EXPECT_EQ(s.following_error[i], 0.0) << i;
    EXPECT_EQ(s.velocity[i], 0.0) << i;
    EXPECT_EQ(s.acceleration[i], 0.0) << i;
  }
  EXPECT_EQ(model.step(sp).tick, 1);
}

}  // namespace
}  // namespace ncc
