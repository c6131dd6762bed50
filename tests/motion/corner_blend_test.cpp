// The G64 corner blend's geometry: it meets both lines with the same tangent and zero
// curvature, stays within kDeviationFactor * d * sin(theta/2) of the programmed corner lines,
// is parametrised by its exact arc length, and its curvature bounds hold.
#include "ncc/vm/motion/corner_blend.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "gtest/gtest.h"
#include "motion_test_util.h"

namespace ncc::vm::motion {
namespace {

using motion_test::distance;
using motion_test::toSegment;

constexpr int kAxes = 3;

AxisValues unit(double x, double y, double z) {
  const double n = std::sqrt(x * x + y * y + z * z);
  AxisValues v{};
  v[0] = x / n;
  v[1] = y / n;
  v[2] = z / n;
  return v;
}

double norm(const AxisValues& v) {
  double s = 0.0;
  for (int i = 0; i < kAxes; ++i) s += v[i] * v[i];
  return std::sqrt(s);
}

struct Corner {
  AxisValues corner, in, out;
  double d;
};

// Corners from 0.5 to 150 degrees (the largest turn the planner blends), in and out of the coordinate planes.
std::vector<Corner> corners() {
  std::vector<Corner> out;
  const AxisValues p = unit(3.0, -1.0, 2.0);
  for (double deg : {0.5, 10.0, 45.0, 90.0, 135.0, 150.0}) {
    const double th = deg * std::numbers::pi / 180.0;
    out.push_back({p, unit(1, 0, 0), unit(std::cos(th), std::sin(th), 0), 0.7});
    out.push_back({p, unit(1, 2, -0.5), unit(std::cos(th), 0.3 * std::sin(th), std::sin(th)), 0.013});
  }
  return out;
}

double turn(const Corner& c) {
  double dot = 0.0;
  for (int i = 0; i < kAxes; ++i) dot += c.in[i] * c.out[i];
  return std::acos(std::clamp(dot, -1.0, 1.0));
}

TEST(CornerBlend, MeetsBothLinesWithSameTangentAndZeroCurvature) {
  for (const Corner& c : corners()) {
    const CornerBlend b = CornerBlend::make(c.corner, c.in, c.out, c.d, kAxes);
    const double L = b.length();
    AxisValues start{}, end{}, p{};
    for (int i = 0; i < kAxes; ++i) {
      start[i] = c.corner[i] - c.d * c.in[i];
      end[i] = c.corner[i] + c.d * c.out[i];
    }
    b.position(1e-12 * L, p);
    EXPECT_LT(distance(p, start), 1e-9 * c.d);
    b.position(L * (1.0 - 1e-12), p);
    EXPECT_LT(distance(p, end), 1e-9 * c.d);
    AxisValues t0{}, t1{}, k0{}, k1{};
    b.tangent(0.0, t0);
    b.tangent(L, t1);
    b.curvature(0.0, k0);
    b.curvature(L, k1);
    for (int i = 0; i < kAxes; ++i) {
      EXPECT_NEAR(t0[i], c.in[i], 1e-12);
      EXPECT_NEAR(t1[i], c.out[i], 1e-12);
    }
    EXPECT_LT(norm(k0), 1e-9 * b.maxCurvature());
    EXPECT_LT(norm(k1), 1e-9 * b.maxCurvature());
  }
}

TEST(CornerBlend, StaysWithinTheDeviationOfTheProgrammedCorner) {
  for (const Corner& c : corners()) {
    const CornerBlend b = CornerBlend::make(c.corner, c.in, c.out, c.d, kAxes);
    const double bound = CornerBlend::kDeviationFactor * c.d * std::sin(0.5 * turn(c));
    AxisValues mid{};
    b.position(0.5 * b.length(), mid);
    EXPECT_NEAR(distance(mid, c.corner), bound, 1e-9 * bound);
    AxisValues a{}, z{};
    for (int i = 0; i < kAxes; ++i) {
      a[i] = c.corner[i] - c.d * c.in[i];
      z[i] = c.corner[i] + c.d * c.out[i];
    }
    double worst = 0.0, closest = 1e300;
    for (int k = 1; k < 2000; ++k) {
      AxisValues p{};
      b.position(b.length() * k / 2000.0, p);
      worst = std::max(worst, std::min(toSegment(p, a, c.corner), toSegment(p, c.corner, z)));
      closest = std::min(closest, distance(p, c.corner));
    }
    EXPECT_LE(worst, bound * (1.0 + 1e-9)) << turn(c);
    // The corner itself is cut by exactly the bound: it is tight, not vacuous.
    EXPECT_NEAR(closest, bound, 1e-6 * bound) << turn(c);
  }
}

TEST(CornerBlend, IsParametrisedByArcLength) {
  for (const Corner& c : corners()) {
    const CornerBlend b = CornerBlend::make(c.corner, c.in, c.out, c.d, kAxes);
    const int n = 4000;
    const double step = b.length() / n;
    AxisValues prev{}, p{};
    b.position(1e-15, prev);
    double sum = 0.0;
    for (int k = 1; k <= n; ++k) {
      b.position(k == n ? b.length() * (1 - 1e-15) : step * k, p);
      // A chord of arc length h on curvature k is shorter by at most (k h)^2 / 24.
      const double chord = distance(p, prev);
      const double kh = b.maxCurvature() * step;
      EXPECT_LE(chord, step * (1.0 + 1e-9)) << k;
      EXPECT_GE(chord, step * (1.0 - kh * kh / 24.0 - 1e-9)) << k;
      sum += chord;
      prev = p;
    }
    EXPECT_NEAR(sum, b.length(), 1e-6 * b.length());
    EXPECT_GT(b.length(), distance(prev, c.corner));  // sanity: not degenerate
    // Shorter than the two cut-off line pieces, longer than the chord between their ends.
    EXPECT_LT(b.length(), 2.0 * c.d);
  }
}

// The largest curvature |d2x/ds2| and curvature rate (finite differences of the curvature
// vector) over n equal steps of the blend.
struct Sampled {
  double curvature, rate;
};
Sampled sampledCurvature(const CornerBlend& b, int n) {
  const double h = b.length() / n;
  Sampled top{0.0, 0.0};
  AxisValues prev{};
  b.curvature(0.0, prev);
  for (int k = 1; k <= n; ++k) {
    AxisValues kv{};
    b.curvature(h * k, kv);
    top.curvature = std::max(top.curvature, norm(kv));
    AxisValues dk{};
    for (int i = 0; i < kAxes; ++i) dk[i] = (kv[i] - prev[i]) / h;
    top.rate = std::max(top.rate, norm(dk));
    prev = kv;
  }
  return top;
}

TEST(CornerBlend, CurvatureStaysWithinItsBounds) {
  for (const Corner& c : corners()) {
    const CornerBlend b = CornerBlend::make(c.corner, c.in, c.out, c.d, kAxes);
    const auto [top, top_rate] = sampledCurvature(b, 3000);
    EXPECT_LE(top, b.maxCurvature());
    EXPECT_GT(top, 0.9 * b.maxCurvature());
    EXPECT_LE(top_rate, b.maxCurvatureRate());
    // Zero at both ends: the curvature must rise and fall inside, at least 2 * turn / length.
    EXPECT_GT(top, 2.0 * turn(c) / b.length() * 0.5);
  }
}

// The bounds come from a table over the turning angle (d = 1, scaled by 1/d and 1/d^2): at
// angles between its entries, over the whole blendable range and at several sizes, they hold
// against dense sampling and stay within 6 % of the sampled maximum (not vacuous).
TEST(CornerBlend, TabulatedBoundsHoldBetweenTableAngles) {
  const AxisValues corner = unit(1.0, 2.0, 3.0);
  for (int k = 1; k <= 199; ++k) {
    const double th = CornerBlend::kMaxTurn * (k - 0.37) / 199.0;
    const double d = k % 3 == 0 ? 0.004 : k % 3 == 1 ? 0.5 : 12.0;
    const CornerBlend b = CornerBlend::make(corner, unit(0, 1, 0),
                                            unit(0, std::cos(th), std::sin(th)), d, kAxes);
    const auto [top, top_rate] = sampledCurvature(b, 1500);
    EXPECT_LE(top, b.maxCurvature()) << th;
    EXPECT_GT(top, b.maxCurvature() / 1.06) << th;
    EXPECT_LE(top_rate, b.maxCurvatureRate()) << th;
    EXPECT_GT(top_rate, b.maxCurvatureRate() / 1.10) << th;
  }
}

// Small turns (up to 0.05 rad, what CAM polylines mostly have) are inverted by interpolation
// alone, without a Newton step: still arc length to about 1e-12 of a 1/4000 step.
TEST(CornerBlend, SmallTurnsAreParametrisedByArcLengthWithoutNewton) {
  const AxisValues corner = unit(2.0, -1.0, 0.5);
  for (double th : {0.001, 0.01, 0.03, 0.0499, 0.07, 0.0999}) {
    for (double d : {0.005, 0.3, 20.0}) {
      const CornerBlend b = CornerBlend::make(corner, unit(1, 0, 0),
                                              unit(std::cos(th), 0, std::sin(th)), d, kAxes);
      const int n = 4000;
      const double step = b.length() / n;
      AxisValues prev{}, p{};
      b.position(0.0, prev);
      for (int k = 1; k <= n; ++k) {
        b.position(step * k, p);
        // The chord of an arc of length h on curvature k is shorter by at most (k h)^2 / 24.
        const double kh = b.maxCurvature() * step;
        const double chord = distance(p, prev);
        ASSERT_LE(chord, step * (1.0 + 1e-10)) << th << " " << d << " " << k;
        ASSERT_GE(chord, step * (1.0 - kh * kh / 24.0 - 1e-10)) << th << " " << d << " " << k;
        prev = p;
      }
    }
  }
}

}  // namespace
}  // namespace ncc::vm::motion
