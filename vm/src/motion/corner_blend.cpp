#include "ncc/vm/motion/corner_blend.h"

#include <algorithm>
#include <cmath>

namespace ncc::vm::motion {
namespace {

// 5-point Gauss-Legendre on [-1, 1].
constexpr std::array<double, 5> kNodes = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                          0.5384693101056831, 0.9061798459386640};
constexpr std::array<double, 5> kWeights = {0.2369268850561891, 0.4786286704993665,
                                            0.5688888888888889, 0.4786286704993665,
                                            0.2369268850561891};
// Samples for the curvature bounds, and the margin on them: between samples the quintic's
// curvature changes by far less than 2 %.
constexpr int kBoundSamples = 128;
constexpr double kBoundMargin = 1.02;

// Power-basis coefficients of a degree-5 Bezier with control values b.
std::array<double, 6> powerBasis(const std::array<double, 6>& b) {
  constexpr double kBinomial[6][6] = {{1, 0, 0, 0, 0, 0},  {1, 1, 0, 0, 0, 0},
                                      {1, 2, 1, 0, 0, 0},  {1, 3, 3, 1, 0, 0},
                                      {1, 4, 6, 4, 1, 0},  {1, 5, 10, 10, 5, 1}};
  std::array<double, 6> a{};
  for (int k = 0; k <= 5; ++k) {
    double sum = 0.0;
    for (int i = 0; i <= k; ++i) sum += ((k - i) % 2 == 0 ? 1.0 : -1.0) * kBinomial[k][i] * b[i];
    a[k] = kBinomial[5][k] * sum;
  }
  return a;
}

// Coefficients of the derivative of sum a_k t^k.
template <std::size_t N>
std::array<double, N - 1> differentiate(const std::array<double, N>& a) {
  std::array<double, N - 1> d{};
  for (std::size_t k = 1; k < N; ++k) d[k - 1] = static_cast<double>(k) * a[k];
  return d;
}

template <std::size_t N>
double horner(const std::array<double, N>& a, double t) {
  double r = a[N - 1];
  for (std::size_t k = N - 1; k-- > 0;) r = r * t + a[k];
  return r;
}

}  // namespace

CornerBlend CornerBlend::make(const AxisValues& corner, const AxisValues& u_in,
                              const AxisValues& u_out, double d, int axis_count) {
  CornerBlend b;
  b.axis_count_ = axis_count;
  b.corner_ = corner;
  double cos_t = 0.0;
  for (int i = 0; i < axis_count; ++i) cos_t += u_in[i] * u_out[i];
  double norm = 0.0;
  for (int i = 0; i < axis_count; ++i) {
    b.e1_[i] = u_in[i];
    b.e2_[i] = u_out[i] - cos_t * u_in[i];
    norm += b.e2_[i] * b.e2_[i];
  }
  const double sin_t = std::sqrt(norm);
  for (int i = 0; i < axis_count; ++i) {
    b.e2_[i] = sin_t > 0.0 ? b.e2_[i] / sin_t : 0.0;
    b.plane_share_[i] = std::min(1.0, std::hypot(b.e1_[i], b.e2_[i]));
  }
  b.px_ = powerBasis({-kOuter * d, -kMiddle * d, -kInner * d, kInner * d * cos_t,
                      kMiddle * d * cos_t, kOuter * d * cos_t});
  b.py_ = powerBasis({0.0, 0.0, 0.0, kInner * d * sin_t, kMiddle * d * sin_t, kOuter * d * sin_t});
  b.vx_ = differentiate(b.px_);
  b.vy_ = differentiate(b.py_);
  b.ax_ = differentiate(b.vx_);
  b.ay_ = differentiate(b.vy_);

  b.s_table_[0] = 0.0;
  for (int k = 0; k < kTableSteps; ++k) {
    const double t0 = static_cast<double>(k) / kTableSteps;
    const double t1 = static_cast<double>(k + 1) / kTableSteps;
    b.s_table_[k + 1] = b.s_table_[k] + b.arcLength(t0, t1);
  }

  // Curvature bounds from the plane curve's derivatives.
  const auto jx = differentiate(b.ax_), jy = differentiate(b.ay_);
  for (int k = 0; k <= kBoundSamples; ++k) {
    const double t = static_cast<double>(k) / kBoundSamples;
    const double x1 = horner(b.vx_, t), y1 = horner(b.vy_, t);
    const double x2 = horner(b.ax_, t), y2 = horner(b.ay_, t);
    const double x3 = horner(jx, t), y3 = horner(jy, t);
    const double sp2 = x1 * x1 + y1 * y1;
    const double sp = std::sqrt(sp2);
    const double cross = x1 * y2 - y1 * x2;
    const double kappa = cross / (sp2 * sp);
    const double dkappa_dt =
        ((x1 * y3 - y1 * x3) * sp2 - 3.0 * cross * (x1 * x2 + y1 * y2)) / (sp2 * sp2 * sp);
    const double dkappa_ds = dkappa_dt / sp;
    b.max_curvature_ = std::max(b.max_curvature_, std::abs(kappa));
    b.max_curvature_rate_ =
        std::max(b.max_curvature_rate_, std::sqrt(dkappa_ds * dkappa_ds + kappa * kappa * kappa * kappa));
  }
  b.max_curvature_ *= kBoundMargin;
  b.max_curvature_rate_ *= kBoundMargin;
  return b;
}

void CornerBlend::derivative(double t, double& dx, double& dy) const {
  dx = horner(vx_, t);
  dy = horner(vy_, t);
}

double CornerBlend::speed(double t) const {
  double dx, dy;
  derivative(t, dx, dy);
  return std::sqrt(dx * dx + dy * dy);
}

double CornerBlend::arcLength(double t0, double t1) const {
  const double half = 0.5 * (t1 - t0), mid = 0.5 * (t1 + t0);
  double sum = 0.0;
  for (std::size_t i = 0; i < kNodes.size(); ++i) sum += kWeights[i] * speed(mid + half * kNodes[i]);
  return half * sum;
}

double CornerBlend::parameterAt(double s) const {
  // The table step holding s (s_table_ is increasing).
  const auto it = std::upper_bound(s_table_.begin() + 1, s_table_.end() - 1, s);
  const int k = static_cast<int>(it - s_table_.begin()) - 1;
  const double t0 = static_cast<double>(k) / kTableSteps;
  const double t1 = static_cast<double>(k + 1) / kTableSteps;
  const double s0 = s_table_[k], s1 = s_table_[k + 1];
  double t = t0 + (t1 - t0) * (s - s0) / (s1 - s0);
  // Newton on S(t) - s: the speed is the derivative; three steps reach rounding from the
  // linear guess (the speed changes little within a step).
  for (int i = 0; i < 3; ++i) {
    t -= (s0 + arcLength(t0, t) - s) / speed(t);
    t = std::clamp(t, t0, t1);
  }
  return t;
}

void CornerBlend::position(double s, AxisValues& out) const {
  const double t = parameterAt(s);
  const double x = horner(px_, t), y = horner(py_, t);
  out = corner_;
  for (int i = 0; i < axis_count_; ++i) out[i] = corner_[i] + x * e1_[i] + y * e2_[i];
}

void CornerBlend::tangent(double s, AxisValues& out) const {
  const double t = parameterAt(s);
  double dx, dy;
  derivative(t, dx, dy);
  const double sp = std::sqrt(dx * dx + dy * dy);
  out = AxisValues{};
  for (int i = 0; i < axis_count_; ++i) out[i] = (dx * e1_[i] + dy * e2_[i]) / sp;
}

void CornerBlend::curvature(double s, AxisValues& out) const {
  const double t = parameterAt(s);
  const double x1 = horner(vx_, t), y1 = horner(vy_, t);
  const double x2 = horner(ax_, t), y2 = horner(ay_, t);
  const double sp2 = x1 * x1 + y1 * y1;
  // d2x/ds2 = (c'' - (c'' . T) T) / |c'|^2 with T = c' / |c'|.
  const double along = (x2 * x1 + y2 * y1) / sp2;
  const double kx = (x2 - along * x1) / sp2, ky = (y2 - along * y1) / sp2;
  out = AxisValues{};
  for (int i = 0; i < axis_count_; ++i) out[i] = kx * e1_[i] + ky * e2_[i];
}

}  // namespace ncc::vm::motion
