// After construction, reset() and step() allocate nothing (real-time discipline): a replaced
// global operator new counts every allocation of this binary.
#include "allocation_counter.h"

#include "gtest/gtest.h"
#include "servo_test_util.h"

namespace ncc {
namespace {

TEST(ServoAllocation, StepAllocatesNothing) {
  MachineConfig m = test::servoMachine(test::servoParams(1.0, FeedForwardMode::Torque, 0.004), 6);
  for (AxisConfig& a : m.axes) {
    a.servo.backlash = 0.01;
    a.servo.backlash_compensation = 0.01;
    a.servo.pitch_error = PitchTable{-100.0, 10.0, std::vector<double>(21, 0.001)};
    a.servo.pitch_compensation = a.servo.pitch_error;
  }
  vm::ServoModel model(m);
  const long before = test::allocationCount();
  model.reset(AxisValues{});
  double sum = 0.0;
  for (long k = 0; k < 10000; ++k) {
    AxisValues sp{};
    for (int i = 0; i < 6; ++i) sp[i] = 0.01 * static_cast<double>(k % 700) - 3.0 * i;
    sum += model.step(sp).actual[0];
  }
  EXPECT_EQ(test::allocationCount() - before, 0);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace ncc
