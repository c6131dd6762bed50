// Backlash reversal on a circle: with play b on X and no compensation, the table's X jumps by
// b against the same machine without play at each X reversal (the quadrant glitch) and keeps
// that offset until the next reversal; with MD 32450 BACKLASH = b the offset is made up by
// the position loop within a few 1/Kv after the reversal.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "gtest/gtest.h"
#include "ncc/vm/servo/backlash.h"
#include "servo_test_util.h"

namespace ncc {
namespace {

using test::circleSetpoint;
using test::kvPerSecond;
using test::servoMachine;
using test::servoParams;

constexpr double kCycle = 0.001;
constexpr double kRadius = 10.0;
constexpr double kPlay = 0.02;  // mm

// X of the table over two revolutions of a circle at F1000.
std::vector<double> tableX(double play, double compensation) {
  ServoConfig s = servoParams(3.0, FeedForwardMode::Velocity, 0.004);
  MachineConfig m = servoMachine(s);
  m.axes[0].servo.backlash = play;
  m.axes[0].servo.backlash_compensation = compensation;
  const double omega = 1000.0 / 60.0 / kRadius;
  const long ticks = std::lround(2.0 * 2.0 * std::acos(-1.0) / omega / kCycle);
  vm::ServoModel model(m);
  model.reset(circleSetpoint(kRadius, omega, kCycle, 0));
  std::vector<double> x;
  for (long k = 0; k <= ticks; ++k)
    x.push_back(model.step(circleSetpoint(kRadius, omega, kCycle, k)).actual[0]);
  return x;
}

// X reverses at phi = pi (k * omega * T = pi) and 2 pi, ...: ticks near them.
bool nearReversal(long k, double window_seconds) {
  const double omega = 1000.0 / 60.0 / kRadius;
  const double phi = omega * kCycle * static_cast<double>(k);
  const double pi = std::acos(-1.0);
  const double since = std::fmod(phi, pi) / omega;  // seconds since the last reversal
  return phi >= pi - 1e-12 ? since < window_seconds : true;  // before the first: settling
}

TEST(ServoBacklash, QuadrantGlitchIsTheBacklashWithoutCompensation) {
  const std::vector<double> ref = tableX(0.0, 0.0);
  const std::vector<double> raw = tableX(kPlay, 0.0);
  double lo = 1e300, hi = -1e300, min_outside = 1e300;
  for (size_t k = 0; k < ref.size(); ++k) {
    const double d = raw[k] - ref[k];
    lo = std::min(lo, d);
    hi = std::max(hi, d);
    if (!nearReversal(static_cast<long>(k), 0.1)) min_outside = std::min(min_outside, std::fabs(d));
  }
  std::printf("backlash %.3f mm, no compensation: X deviation %.6f..%.6f (glitch %.6f), "
              "away from reversals |dev| >= %.6f\n", kPlay, lo, hi, hi - lo, min_outside);
  EXPECT_NEAR(hi - lo, kPlay, 1e-9);
  EXPECT_NEAR(min_outside, kPlay / 2, 1e-9);  // the offset persists between reversals
}

TEST(ServoBacklash, CompensationRemovesIt) {
  const std::vector<double> ref = tableX(0.0, 0.0);
  const std::vector<double> comp = tableX(kPlay, kPlay);
  const double window = 5.0 / kvPerSecond(3.0);  // 5 position-loop time constants
  double peak = 0.0, max_outside = 0.0;
  for (size_t k = 0; k < ref.size(); ++k) {
    const double d = std::fabs(comp[k] - ref[k]);
    peak = std::max(peak, d);
    if (!nearReversal(static_cast<long>(k), window)) max_outside = std::max(max_outside, d);
  }
  std::printf("backlash %.3f mm, compensated: peak |dev| %.6f mm right after a reversal, "
              "%.3g mm from %.0f ms after it\n", kPlay, peak, max_outside, window * 1000);
  EXPECT_LE(peak, kPlay + 1e-9);
  EXPECT_LT(max_outside, 0.01 * kPlay);
}

TEST(MechanicalPlay, TableWaitsUntilThePlayIsTakenUp) {
  vm::MechanicalPlay play(0.1);
  play.reset(0.0);
  EXPECT_EQ(play.load(0.04), 0.0);         // inside the play: the table stays
  EXPECT_DOUBLE_EQ(play.load(0.15), 0.1);  // dragged 0.05 behind
  EXPECT_DOUBLE_EQ(play.load(0.1), 0.1);   // reversal: stays again
  EXPECT_DOUBLE_EQ(play.load(0.0), 0.05);  // dragged 0.05 ahead
  vm::MechanicalPlay negative(-0.1);       // encoder lags the table
  negative.reset(0.0);
  EXPECT_DOUBLE_EQ(negative.load(1.0), 1.05);
}

}  // namespace
}  // namespace ncc
