// After construction, reset() and step() allocate nothing (real-time discipline): a replaced
// global operator new counts every allocation of this binary.
#include <cstdlib>
#include <new>

#include "gtest/gtest.h"
#include "servo_test_util.h"

namespace {
long g_allocations = 0;
}  // namespace

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

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
  const long before = g_allocations;
  model.reset(AxisValues{});
  double sum = 0.0;
  for (long k = 0; k < 10000; ++k) {
    AxisValues sp{};
    for (int i = 0; i < 6; ++i) sp[i] = 0.01 * static_cast<double>(k % 700) - 3.0 * i;
    sum += model.step(sp).actual[0];
  }
  EXPECT_EQ(g_allocations - before, 0);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace ncc
