// Leadscrew pitch-error tables: interpolation (exact at and between support points, end values
// held) and their effect in the servo model.
#include <cmath>

#include "gtest/gtest.h"
#include "ncc/vm/servo/pitch_compensation.h"
#include "servo_test_util.h"

namespace ncc {
namespace {

PitchTable table() { return PitchTable{-20.0, 10.0, {0.0, 0.004, -0.002, 0.010}}; }

TEST(PitchTable, ExactAtSupportPoints) {
  const PitchTable t = table();
  EXPECT_EQ(vm::pitchValue(t, -20.0), 0.0);
  EXPECT_EQ(vm::pitchValue(t, -10.0), 0.004);
  EXPECT_EQ(vm::pitchValue(t, 0.0), -0.002);
  EXPECT_EQ(vm::pitchValue(t, 10.0), 0.010);
}

TEST(PitchTable, LinearBetweenSupportPoints) {
  const PitchTable t = table();
  EXPECT_DOUBLE_EQ(vm::pitchValue(t, -15.0), 0.002);
  EXPECT_DOUBLE_EQ(vm::pitchValue(t, -7.5), 0.004 + 0.25 * (-0.006));
  EXPECT_DOUBLE_EQ(vm::pitchValue(t, 5.0), 0.004);
  EXPECT_DOUBLE_EQ(vm::pitchValue(t, 9.0), -0.002 + 0.9 * 0.012);
}

TEST(PitchTable, EndValuesHeldOutside) {
  const PitchTable t = table();
  EXPECT_EQ(vm::pitchValue(t, -1000.0), 0.0);
  EXPECT_EQ(vm::pitchValue(t, 1000.0), 0.010);
  EXPECT_EQ(vm::pitchValue(t, std::nan("")), 0.0);
  EXPECT_EQ(vm::pitchValue(PitchTable{}, 3.0), 0.0);
  EXPECT_EQ(vm::pitchValue(PitchTable{0.0, 1.0, {0.5}}, 3.0), 0.5);
}

// At rest at x, the table is at x + e(x) without compensation; with the same table as LEC
// compensation it is at x up to the second-order term e(x) * e'(x).
TEST(PitchTable, ServoModelAppliesAndCompensatesTheError) {
  MachineConfig m = test::servoMachine(ServoConfig{}, 1);
  m.axes[0].servo.pitch_error = table();
  for (double x : {-15.0, 0.0, 7.0}) {
    AxisValues p{};
    p[0] = x;
    vm::ServoModel raw(m);
    raw.reset(p);
    EXPECT_NEAR(raw.step(p).actual[0], x + vm::pitchValue(table(), x), 1e-15) << x;

    MachineConfig mc = m;
    mc.axes[0].servo.pitch_compensation = table();
    vm::ServoModel comp(mc);
    comp.reset(p);
    // |e * e'| <= 0.01 * 0.0012 here.
    EXPECT_NEAR(comp.step(p).actual[0], x, 2e-5) << x;
    EXPECT_EQ(comp.sample().following_error[0], 0.0);
  }
}

}  // namespace
}  // namespace ncc
