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

// At a support point and outside the table the value is the entry as it is (found in
// review: computed as v + 0 (v' - v), a -0 entry came out +0, and two huge neighbours whose
// difference overflows gave a NaN).
TEST(PitchTable, EntriesComeOutAsTheyAre) {
  const PitchTable signed_zero{0.0, 1.0, {-0.0, 0.001}};
  for (double x : {0.0, -5.0, std::nan("")}) {
    EXPECT_TRUE(std::signbit(vm::pitchValue(signed_zero, x))) << x;
    vm::PitchTables tables;
    tables.add(0, signed_zero);
    vm::PitchTables::Values position{};
    position[0] = x;
    tables.lookUp(1, position);
    EXPECT_TRUE(std::signbit(tables.values()[0])) << x;
    EXPECT_TRUE(std::signbit(tables.valueAt(0, x))) << x;
  }
  const PitchTable huge{0.0, 1.0, {1e308, -1e308}};
  EXPECT_EQ(vm::pitchValue(huge, 0.0), 1e308);
  EXPECT_EQ(vm::pitchValue(huge, 1.0), -1e308);
  EXPECT_EQ(vm::pitchValue(huge, 7.0), -1e308);
}

// The servo model's per-cycle path (all axes' divisions side by side, then the interpolation)
// gives pitchValue() bit for bit: inside, between and outside the support points, and NaN;
// an axis whose position repeats keeps its value, one that moves gets the new one.
TEST(PitchTable, ServoLookupIsPitchValue) {
  vm::PitchTables tables;
  tables.add(1, table());
  tables.add(3, PitchTable{0.0, 0.1, {0.0, -0.001, 0.0005}});
  const PitchTable* by_axis[4] = {nullptr, nullptr, nullptr, nullptr};
  const PitchTable t1 = table(), t3{0.0, 0.1, {0.0, -0.001, 0.0005}};
  by_axis[1] = &t1;
  by_axis[3] = &t3;
  vm::PitchTables::Values position{};
  auto expectPitchValues = [&] {
    for (int i = 0; i < 4; ++i) {
      const double expected = by_axis[i] ? vm::pitchValue(*by_axis[i], position[i]) : 0.0;
      EXPECT_EQ(tables.values()[i], expected) << "axis " << i << " at " << position[i];
      EXPECT_EQ(tables.valueAt(i, position[i]), expected) << "axis " << i;
    }
  };
  for (double x = -40.0; x <= 40.0; x += 0.0625) {
    for (int i = 0; i < 4; ++i) position[i] = i == 3 ? x / 100.0 : x;
    tables.lookUp(4, position);
    expectPitchValues();
    // Axis 1 at rest, axis 3 moved on: each value is the one at its position.
    position[3] = -position[3];
    tables.lookUp(4, position);
    expectPitchValues();
  }
  position[1] = std::nan("");
  tables.lookUp(4, position);
  EXPECT_EQ(tables.values()[1], 0.0);  // the first value
  position[1] = 25.0;
  tables.lookUp(4, position);
  expectPitchValues();
}

// The cycle keeps each lane's interval: jumps across the whole table and back, and a grid
// whose support points round together (step 0.5 where a double's spacing is 2, so that some
// intervals are empty) still give pitchValue() bit for bit, every value one of the entries or
// between two neighbours.
TEST(PitchTable, KeptIntervalsGivePitchValue) {
  const PitchTable coarse = table();
  const PitchTable rounded{1e16, 0.5, {1.0, 2.0, 3.0, 4.0, 5.0, 6.0}};
  vm::PitchTables tables;
  tables.add(0, coarse);
  tables.add(1, rounded);
  const double jumps[] = {-1000.0, 9.99, -19.99, 1000.0, -10.0, -10.000000001, 0.0, 10.0};
  for (double x : jumps) {
    vm::PitchTables::Values position{};
    position[0] = x;
    position[1] = 1e16 + 2.0 * x / 1000.0;  // about 1e16 - 2 .. 1e16 + 2
    tables.lookUp(2, position);
    EXPECT_EQ(tables.values()[0], vm::pitchValue(coarse, position[0])) << x;
    EXPECT_EQ(tables.values()[1], vm::pitchValue(rounded, position[1])) << x;
    EXPECT_GE(tables.values()[1], 1.0) << x;
    EXPECT_LE(tables.values()[1], 6.0) << x;
  }
  EXPECT_EQ(vm::pitchValue(rounded, 1e16 + 4.0), 6.0);  // past the last point (1e16 + 2.5 -> 2)
  // Before the first point: held at it, where x_0 = x_1 = x_2 = 1e16, and of support points
  // that coincide the last one holds.
  EXPECT_EQ(vm::pitchValue(rounded, 1e16 - 2.0), 3.0);
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
