// The same setpoints give bit-identical samples: a hash of every sample's bytes against a
// value pinned once. A change of this value means the model's arithmetic changed (say so in
// docs/servo.md) or determinism broke (compiler flags, FMA contraction, ...).
#include <cmath>
#include <cstdint>
#include <cstring>

#include "gtest/gtest.h"
#include "servo_test_util.h"

namespace ncc {
namespace {

uint64_t fnv1a(uint64_t h, const void* data, size_t n) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 0x100000001b3ULL;
  }
  return h;
}

uint64_t hashRun() {
  ServoConfig s = test::servoParams(2.0, FeedForwardMode::Torque, 0.003);
  MachineConfig m = test::servoMachine(s, 3);
  m.axes[0].servo.backlash = 0.01;
  m.axes[0].servo.backlash_compensation = 0.008;
  m.axes[1].servo.ffw_mode = FeedForwardMode::Velocity;
  m.axes[1].servo.pitch_error = PitchTable{-20.0, 5.0, {0.0, 0.003, -0.001, 0.002, 0.004}};
  m.axes[1].servo.pitch_compensation = m.axes[1].servo.pitch_error;
  m.axes[2].servo.ffw_mode = FeedForwardMode::None;
  vm::ServoModel model(m);
  uint64_t h = 0xcbf29ce484222325ULL;
  for (long k = 0; k < 5000; ++k) {
    const double t = 0.001 * static_cast<double>(k);
    AxisValues sp{};
    sp[0] = 10.0 * std::cos(3.0 * t);
    sp[1] = 10.0 * std::sin(3.0 * t);
    sp[2] = k < 2500 ? 0.5 * 200.0 * t * t : 625.0;
    const vm::ServoSample& out = model.step(sp);
    for (int i = 0; i < 3; ++i) {
      h = fnv1a(h, &out.actual[i], sizeof(double));
      h = fnv1a(h, &out.following_error[i], sizeof(double));
      h = fnv1a(h, &out.velocity[i], sizeof(double));
      h = fnv1a(h, &out.acceleration[i], sizeof(double));
    }
  }
  return h;
}

TEST(ServoDeterminism, SameSetpointsSameBits) {
  const uint64_t a = hashRun();
  EXPECT_EQ(a, hashRun());
  std::printf("servo trace hash: 0x%016llx\n", static_cast<unsigned long long>(a));
  EXPECT_EQ(a, 0xae1ad863848cd433ULL);
}

}  // namespace
}  // namespace ncc
