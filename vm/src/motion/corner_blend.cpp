#include "ncc/vm/motion/corner_blend.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncc::vm::motion {
namespace {

// 5-point Gauss-Legendre on [-1, 1].
constexpr std::array<double, 5> kNodes = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                          0.5384693101056831, 0.9061798459386640};
constexpr std::array<double, 5> kWeights = {0.2369268850561891, 0.4786286704993665,
                                            0.5688888888888889, 0.4786286704993665,
                                            0.2369268850561891};
// The curvature bounds of the blend with d = 1, tabulated over the turning angle. The
// blend's shape depends on theta alone and d only scales it, so its curvature scales as 1/d
// and its curvature rate as 1/d^2: make() needs a look-up, not a sampling of the curve.
// kBoundSamples samples along the curve per angle, kBoundAngles + 1 angles over
// [0, kMaxTurn]. What is tabulated is bound / theta, which is smooth and tends to a constant
// at theta = 0 (both bounds grow like theta for small turns); between two tabulated angles
// the larger ratio is taken. The margin covers the curve between samples (its curvature
// changes by far less than 2 % there). tests/motion/corner_blend_test.cpp checks the bounds
// against dense sampling.
constexpr int kBoundSamples = 128;
constexpr int kBoundAngles = 512;
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

// Per tabulated angle: the d = 1 blend's largest curvature and curvature rate, over theta.
struct UnitBounds {
  std::array<double, kBoundAngles + 1> curvature{};
  std::array<double, kBoundAngles + 1> curvature_rate{};
};

// Power-basis coefficients of the plane curve (origin at the corner, x along the incoming
// line) for turning angle theta (cos_t, sin_t) and trim d.
void planeCurve(double cos_t, double sin_t, double d, std::array<double, 6>& px,
                std::array<double, 6>& py) {
  using B = CornerBlend;
  px = powerBasis({-B::kOuter * d, -B::kMiddle * d, -B::kInner * d, B::kInner * d * cos_t,
                   B::kMiddle * d * cos_t, B::kOuter * d * cos_t});
  py = powerBasis({0.0, 0.0, 0.0, B::kInner * d * sin_t, B::kMiddle * d * sin_t,
                   B::kOuter * d * sin_t});
}

// Largest curvature |d2x/ds2| and curvature rate |d3x/ds3| (sqrt(k'^2 + k^4) on a plane
// curve, plus the torsion's part on a space curve) of the curve (px, py, pz) at `samples` + 1
// equal steps of its parameter.
void sampleCurveBounds(const std::array<double, 6>& px, const std::array<double, 6>& py,
                       const std::array<double, 6>& pz, int samples, double& curvature,
                       double& curvature_rate) {
  const std::array<std::array<double, 6>, 3> p = {px, py, pz};
  std::array<std::array<double, 5>, 3> c1;
  std::array<std::array<double, 4>, 3> c2;
  std::array<std::array<double, 3>, 3> c3;
  for (int i = 0; i < 3; ++i) {
    c1[i] = differentiate(p[i]);
    c2[i] = differentiate(c1[i]);
    c3[i] = differentiate(c2[i]);
  }
  curvature = curvature_rate = 0.0;
  for (int k = 0; k <= samples; ++k) {
    const double t = static_cast<double>(k) / samples;
    // With v, a, j the curve's first three derivatives in t, sp2 = |v|^2 and along = a . v,
    // the curvature vector is a / sp2 - along v / sp2^2, and d3x/ds3 its t-derivative over
    // |v|: (j / sp2 - 3 along a / sp2^2 - (j . v + |a|^2) v / sp2^2 + 4 along^2 v / sp2^3) / |v|.
    std::array<double, 3> v, a, j;
    for (int i = 0; i < 3; ++i) {
      v[i] = horner(c1[i], t);
      a[i] = horner(c2[i], t);
      j[i] = horner(c3[i], t);
    }
    const double sp2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    const double sp = std::sqrt(sp2);
    const double along = a[0] * v[0] + a[1] * v[1] + a[2] * v[2];
    const double along_rate =
        j[0] * v[0] + j[1] * v[1] + j[2] * v[2] + a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    double k2 = 0.0, r2 = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double kv = a[i] / sp2 - along * v[i] / (sp2 * sp2);
      const double rv = (j[i] / sp2 - 3.0 * along * a[i] / (sp2 * sp2) -
                         along_rate * v[i] / (sp2 * sp2) +
                         4.0 * along * along * v[i] / (sp2 * sp2 * sp2)) /
                        sp;
      k2 += kv * kv;
      r2 += rv * rv;
    }
    if (!std::isfinite(r2)) {  // a cusp (join() with extreme ends): unbounded
      curvature = curvature_rate = std::numeric_limits<double>::infinity();
      return;
    }
    curvature = std::max(curvature, std::sqrt(k2));
    curvature_rate = std::max(curvature_rate, std::sqrt(r2));
  }
}

// The same for the d = 1 corner blend of turning angle theta.
void sampleBounds(double theta, double& curvature, double& curvature_rate) {
  std::array<double, 6> px, py;
  planeCurve(std::cos(theta), std::sin(theta), 1.0, px, py);
  sampleCurveBounds(px, py, {}, kBoundSamples, curvature, curvature_rate);
}

const UnitBounds& unitBounds() {
  static const UnitBounds table = [] {
    UnitBounds t;
    for (int k = 0; k <= kBoundAngles; ++k) {
      // Node 0: the limit theta -> 0, taken at a tiny angle.
      const double theta =
          CornerBlend::kMaxTurn * (k == 0 ? 1e-6 : static_cast<double>(k)) / kBoundAngles;
      sampleBounds(theta, t.curvature[k], t.curvature_rate[k]);
      t.curvature[k] /= theta;
      t.curvature_rate[k] /= theta;
    }
    return t;
  }();
  return table;
}

}  // namespace

void CornerBlend::prepareTables() { (void)unitBounds(); }

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
  planeCurve(cos_t, sin_t, d, b.px_, b.py_);
  b.buildTables(true);

  // Curvature bounds: the d = 1 table at theta, scaled.
  const double theta = std::atan2(sin_t, cos_t);
  b.interpolation_exact_ = theta <= kInterpolationExactTurn;
  const double cell = std::clamp(theta / kMaxTurn, 0.0, 1.0) * kBoundAngles;
  const int lo = std::min(static_cast<int>(cell), kBoundAngles - 1);
  const UnitBounds& unit = unitBounds();
  const double scale = kBoundMargin * theta;
  b.max_curvature_ = scale * std::max(unit.curvature[lo], unit.curvature[lo + 1]) / d;
  b.max_curvature_rate_ =
      scale * std::max(unit.curvature_rate[lo], unit.curvature_rate[lo + 1]) / (d * d);
  return b;
}

CornerBlend CornerBlend::join(const AxisValues& origin, const AxisValues& e1,
                              const AxisValues& e2, const AxisValues& e3, const End& start,
                              const End& end, double handle_start, double handle_end,
                              int axis_count, Bounds bounds) {
  CornerBlend b;
  b.axis_count_ = axis_count;
  b.corner_ = origin;
  b.e1_ = e1;
  b.e2_ = e2;
  b.e3_ = e3;
  for (int i = 0; i < axis_count; ++i)
    b.plane_share_[i] = std::min(1.0, std::sqrt(e1[i] * e1[i] + e2[i] * e2[i] + e3[i] * e3[i]));
  // Control points P0..P5. The second derivative at an end is 20 times the third control
  // point's offset from the straight handle (the handles along the tangent cancel), and the
  // curvature vector is its part across the tangent over the speed squared, (5 h)^2: an offset
  // of 1.25 h^2 k (k the end's curvature vector, across its tangent) gives the curvature k.
  const double h0 = handle_start, h1 = handle_end;
  std::array<std::array<double, 6>, 3> control;
  for (int i = 0; i < 3; ++i) {
    const double p0 = start.position[i], t0 = start.tangent[i];
    const double p5 = end.position[i], t5 = end.tangent[i];
    control[i] = {p0,
                  p0 + h0 * t0,
                  p0 + 2.0 * h0 * t0 + 1.25 * h0 * h0 * start.curvature[i],
                  p5 - 2.0 * h1 * t5 + 1.25 * h1 * h1 * end.curvature[i],
                  p5 - h1 * t5,
                  p5};
  }
  b.px_ = powerBasis(control[0]);
  b.py_ = powerBasis(control[1]);
  b.pz_ = powerBasis(control[2]);
  for (double c : control[2]) b.spatial_ = b.spatial_ || c != 0.0;
  b.buildTables(false);
  b.interpolation_exact_ = false;
  if (bounds == Bounds::Sampled) {
    b.sampleBounds();
  } else {
    b.max_curvature_ = b.max_curvature_rate_ = std::numeric_limits<double>::infinity();
  }
  return b;
}

void CornerBlend::sampleBounds() {
  // No table for an asymmetric shape: sampled, finer than the table's samples.
  double curvature = 0.0, rate = 0.0;
  sampleCurveBounds(px_, py_, pz_, 4 * kBoundSamples, curvature, rate);
  max_curvature_ = kBoundMargin * curvature;
  max_curvature_rate_ = kBoundMargin * rate;
}

void CornerBlend::buildTables(bool mirror_symmetric) {
  vx_ = differentiate(px_);
  vy_ = differentiate(py_);
  vz_ = differentiate(pz_);
  ax_ = differentiate(vx_);
  ay_ = differentiate(vy_);
  az_ = differentiate(vz_);

  // A mirror-symmetric curve runs its second half as the mirror image of its first, backwards
  // (t -> 1 - t): the same speed, s(1 - t) = length - s(t), and t''(s) with its sign turned.
  // Only the first half is integrated.
  constexpr int kHalf = kTableSteps / 2;
  const int integrated = mirror_symmetric ? kHalf : kTableSteps;
  s_table_[0] = 0.0;
  for (int k = 0; k < integrated; ++k) {
    const double t0 = static_cast<double>(k) / kTableSteps;
    const double t1 = static_cast<double>(k + 1) / kTableSteps;
    s_table_[k + 1] = s_table_[k] + arcLength(t0, t1);
  }
  for (int k = 0; k <= integrated; ++k) {
    const double t = static_cast<double>(k) / kTableSteps;
    double dx, dy, dz;
    derivative(t, dx, dy, dz);
    const double sp2 = dx * dx + dy * dy + dz * dz;
    speed_table_[k] = std::sqrt(sp2);
    // t''(s) = -(c' . c'') / |c'|^4
    const double along = dx * horner(ax_, t) + dy * horner(ay_, t);
    dtds2_table_[k] = -(spatial_ ? along + dz * horner(az_, t) : along) / (sp2 * sp2);
  }
  if (!mirror_symmetric) return;
  const double length = 2.0 * s_table_[kHalf];
  dtds2_table_[kHalf] = 0.0;  // the speed is extremal at the middle
  for (int k = 0; k < kHalf; ++k) {
    s_table_[kTableSteps - k] = length - s_table_[k];
    speed_table_[kTableSteps - k] = speed_table_[k];
    dtds2_table_[kTableSteps - k] = -dtds2_table_[k];
  }
}

void CornerBlend::derivative(double t, double& dx, double& dy, double& dz) const {
  dx = horner(vx_, t);
  dy = horner(vy_, t);
  dz = spatial_ ? horner(vz_, t) : 0.0;
}

double CornerBlend::speed(double t) const {
  double dx, dy, dz;
  derivative(t, dx, dy, dz);
  return std::sqrt(dx * dx + dy * dy + dz * dz);
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
  // Quintic Hermite interpolation of t(s) over the step, from t, dt/ds = 1/|c'| and
  // d2t/ds2 at both ends (u = (s - s0) / h, derivatives per unit u). For small turns the speed
  // hardly changes and this is t to about 1e-14 (corner_blend_test checks it); otherwise one
  // Newton step on S(t) - s (the speed is its derivative) from it reaches rounding.
  const double h = s1 - s0;
  const double u = (s - s0) / h;
  const double m0 = h / speed_table_[k], m1 = h / speed_table_[k + 1];
  const double a0 = h * h * dtds2_table_[k], a1 = h * h * dtds2_table_[k + 1];
  const double u2 = u * u, u3 = u2 * u, u4 = u3 * u, u5 = u4 * u;
  double t = (1.0 - 10.0 * u3 + 15.0 * u4 - 6.0 * u5) * t0 +
             (u - 6.0 * u3 + 8.0 * u4 - 3.0 * u5) * m0 +
             (0.5 * u2 - 1.5 * u3 + 1.5 * u4 - 0.5 * u5) * a0 +
             (0.5 * u3 - u4 + 0.5 * u5) * a1 + (-4.0 * u3 + 7.0 * u4 - 3.0 * u5) * m1 +
             (10.0 * u3 - 15.0 * u4 + 6.0 * u5) * t1;
  if (!interpolation_exact_) t -= (s0 + arcLength(t0, t) - s) / speed(t);
  return std::clamp(t, t0, t1);
}

void CornerBlend::position(double s, AxisValues& out) const {
  const double t = parameterAt(s);
  const double x = horner(px_, t), y = horner(py_, t), z = spatial_ ? horner(pz_, t) : 0.0;
  out = corner_;
  for (int i = 0; i < axis_count_; ++i) out[i] = corner_[i] + x * e1_[i] + y * e2_[i] + z * e3_[i];
}

void CornerBlend::tangent(double s, AxisValues& out) const {
  const double t = parameterAt(s);
  double dx, dy, dz;
  derivative(t, dx, dy, dz);
  const double sp = std::sqrt(dx * dx + dy * dy + dz * dz);
  out = AxisValues{};
  for (int i = 0; i < axis_count_; ++i) out[i] = (dx * e1_[i] + dy * e2_[i] + dz * e3_[i]) / sp;
}

void CornerBlend::curvature(double s, AxisValues& out) const {
  const double t = parameterAt(s);
  double x1, y1, z1;
  derivative(t, x1, y1, z1);
  const double x2 = horner(ax_, t), y2 = horner(ay_, t), z2 = spatial_ ? horner(az_, t) : 0.0;
  const double sp2 = x1 * x1 + y1 * y1 + z1 * z1;
  // d2x/ds2 = (c'' - (c'' . T) T) / |c'|^2 with T = c' / |c'|.
  const double along = (x2 * x1 + y2 * y1 + z2 * z1) / sp2;
  const double kx = (x2 - along * x1) / sp2, ky = (y2 - along * y1) / sp2,
               kz = (z2 - along * z1) / sp2;
  out = AxisValues{};
  for (int i = 0; i < axis_count_; ++i) out[i] = kx * e1_[i] + ky * e2_[i] + kz * e3_[i];
}

}  // namespace ncc::vm::motion
