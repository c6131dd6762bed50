// Bows: the chords of a smooth chain (continuous_path.h), drawn as the quintic Hermite curve
// between the chord's ends A, B with the chain's unit tangents t0, t1 and curvature vectors
// k0, k1 there (k_i normal to t_i):
//     x(u) = A + u D + H1(u) (S t0 - D) + H4(u) (S t1 - D) + H2(u) S^2 k0 + H3(u) S^2 k1,
// u = s / S, D = B - A, with the quintic Hermite weights
//     H1 = u - 6u^3 + 8u^4 - 3u^5,   H4 = -4u^3 + 7u^4 - 3u^5,
//     H2 = (u^2 - 3u^3 + 3u^4 - u^5) / 2,   H3 = (u^3 - 2u^4 + u^5) / 2
// (the straight chord A + u D is the Hermite curve of derivative D and no curvature at both
// ends). S, the bow's length in s, is the chord's |D| stretched by (a0^2 + a1^2) / 12 for the
// end tangents' angles a0, a1 to it: the arc of a circle through the chord is longer by that
// (to a4), and with S its arc length the quintic follows the circle closely (with S = |D|
// its speed bulged in the middle to cover the longer arc, and d3x/ds3 along the tangent
// swung between +1.35 and -2.25 k^2 instead of -k^2). So at the ends dx/ds is exactly t0,
// t1 and d2x/ds2 exactly k0, k1: neighbouring
// bows meet with the same position, velocity and acceleration, where the polygon's vertices
// were velocity steps (the "wiggle" the polygon's chains budget, limits.h), and a bow straight
// at an end (t = c, k = 0) meets a line or a corner blend there the same way.
//
// Bounds: x is the Bezier curve of the control points P0 = A, P1 = A + S t0 / 5,
// P2 = A + 2 S t0 / 5 + S^2 k0 / 20, P3 = B - 2 S t1 / 5 + S^2 k1 / 20, P4 = B - S t1 / 5,
// P5 = B, and its derivatives are Bezier curves of the control points' differences (times 5,
// 20, 60), each within the convex hull of its control points: |dx/ds|, |d2x/ds2| and their
// per-axis parts are at most the largest of theirs (|d3x/ds3|: see setBowBounds).
#include <algorithm>
#include <array>
#include <cmath>

#include "ncc/vm/motion/path.h"

namespace ncc::vm::motion {
namespace {

double norm(const AxisValues& v, int n) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += v[i] * v[i];
  return std::sqrt(sum);
}

double dot(const AxisValues& a, const AxisValues& b, int n) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += a[i] * b[i];
  return sum;
}

// The square of v's part across the unit vector c, given its part along c (rounding may take
// it below 0).
double acrossSquared(const AxisValues& v, double along, int n) {
  return dot(v, v, n) - along * along;
}

// The parts of v along the unit vector c and across it (their sizes; along signed).
struct Split {
  double along, across;
};
Split split(const AxisValues& v, const AxisValues& c, int n) {
  const double along = dot(v, c, n);
  return {along, std::sqrt(std::max(acrossSquared(v, along, n), 0.0))};
}

// Control points of dx/ds (4th degree), d2x/ds2 (3rd) and d3x/ds3 (2nd). Set and read for
// the segment's axes only (not zeroed: setBowBounds runs once per chord of a chain).
struct BowHull {
  std::array<AxisValues, 5> velocity;
  std::array<AxisValues, 4> curvature;
  std::array<AxisValues, 3> rate;
};

// max(acc, x clamped at 0), ignoring a NaN x as std::max(acc, x) does: the largest of values
// kept squared, so that one square root (monotone, correctly rounded) gives the largest root.
double maxSquare(double acc, double x) { return std::max(acc, std::max(x, 0.0)); }

}  // namespace

PathSegment PathSegment::bow(const AxisValues& from, const AxisValues& to,
                             const AxisValues& start_tangent, const AxisValues& end_tangent,
                             const AxisValues& start_curvature, const AxisValues& end_curvature,
                             int axis_count, bool bounds) {
  PathSegment p = line(from, to, axis_count);
  if (!(p.length_ > 0.0)) return p;
  const double S = bowLength(p.delta_, start_tangent, end_tangent, axis_count);
  bool bowed = false;
  for (int i = 0; i < axis_count; ++i) {
    p.bow_[0][i] = S * start_tangent[i] - p.delta_[i];
    p.bow_[1][i] = S * end_tangent[i] - p.delta_[i];
    p.bow_[2][i] = S * S * start_curvature[i];
    p.bow_[3][i] = S * S * end_curvature[i];
    for (const AxisValues& b : p.bow_) bowed = bowed || b[i] != 0.0;
  }
  if (!bowed) return p;
  p.shape_ = Shape::Bow;
  p.length_ = S;
  if (bounds) p.setBowBounds();
  return p;
}

double PathSegment::bowLength(const AxisValues& delta, const AxisValues& start_tangent,
                              const AxisValues& end_tangent, int axis_count) {
  const double L = norm(delta, axis_count);
  double a0 = 0.0, a1 = 0.0;  // |t - c|^2, the angles squared to a4
  for (int i = 0; i < axis_count; ++i) {
    a0 += (start_tangent[i] - delta[i] / L) * (start_tangent[i] - delta[i] / L);
    a1 += (end_tangent[i] - delta[i] / L) * (end_tangent[i] - delta[i] / L);
  }
  return L * (1.0 + (a0 + a1) / 12.0);
}

double PathSegment::bowOffset(const AxisValues& from, const AxisValues& to,
                              const AxisValues& start_tangent, const AxisValues& end_tangent,
                              const AxisValues& start_curvature, const AxisValues& end_curvature,
                              int axis_count) {
  // The bow less its chord A + u D is the Bezier curve of the control points' offsets from
  // the chord's evenly spaced ones: 0, (S t0 - D) / 5, 2 (S t0 - D) / 5 + S^2 k0 / 20, and
  // likewise from the other end, 0; within their hull.
  AxisValues delta{};
  for (int i = 0; i < axis_count; ++i) delta[i] = to[i] - from[i];
  if (!(norm(delta, axis_count) > 0.0)) return 0.0;
  const double S = bowLength(delta, start_tangent, end_tangent, axis_count);
  double o[4] = {0.0, 0.0, 0.0, 0.0};
  for (int i = 0; i < axis_count; ++i) {
    const double p0 = S * start_tangent[i] - delta[i], p1 = S * end_tangent[i] - delta[i];
    const double q0 = S * S * start_curvature[i], q1 = S * S * end_curvature[i];
    // (Products with 1/5 and 1/20 rather than six divisions an axis: a bound compared with
    // the tolerance, where the last bit does not matter.)
    const double terms[4] = {0.2 * p0, 0.4 * p0 + 0.05 * q0, -0.4 * p1 + 0.05 * q1, -0.2 * p1};
    for (int k = 0; k < 4; ++k) o[k] += terms[k] * terms[k];
  }
  return std::sqrt(std::max({o[0], o[1], o[2], o[3]}));
}

void PathSegment::setBowBounds() {
  const int n = axis_count_;
  const double L = length_;  // S
  const double chord = norm(delta_, n);
  // The derivatives' control points, from bow_ = {b0, b1, c0, c1} directly (differences of
  // the position's control points, which lie |D| apart, lost digits on micrometre chords):
  // dx/du: D + b0, D + b0 + c0/4, D - 2 b0 - 2 b1 + (c1 - c0)/4, D + b1 - c1/4, D + b1;
  // d2x/du2: c0, c1 - 2 c0 - 12 b0 - 8 b1, c0 - 2 c1 + 8 b0 + 12 b1, c1;
  // d3x/du3: 3 times the differences of those.
  AxisValues c{};
  BowHull h;
  // Scales by products with reciprocals: twelve divisions per axis were a third of this
  // function's time (the bounds may differ in their last bit).
  const double per_chord = 1.0 / chord;
  const double per_l = 1.0 / L, per_l2 = per_l * per_l, per_l3 = 3.0 * per_l2 * per_l;
  for (int i = 0; i < n; ++i) {
    c[i] = delta_[i] * per_chord;
    const double D = delta_[i], b0 = bow_[0][i], b1 = bow_[1][i], c0 = bow_[2][i], c1 = bow_[3][i];
    const double q[5] = {D + b0, D + b0 + 0.25 * c0, D - 2.0 * b0 - 2.0 * b1 + 0.25 * (c1 - c0),
                         D + b1 - 0.25 * c1, D + b1};
    const double r[4] = {c0, c1 - 2.0 * c0 - 12.0 * b0 - 8.0 * b1, c0 - 2.0 * c1 + 8.0 * b0 + 12.0 * b1,
                         c1};
    for (int k = 0; k < 5; ++k) h.velocity[k][i] = q[k] * per_l;
    for (int k = 0; k < 4; ++k) h.curvature[k][i] = r[k] * per_l2;
    for (int k = 0; k < 3; ++k) h.rate[k][i] = (r[k + 1] - r[k]) * per_l3;
  }
  BowBounds& b = bow_bounds_;
  b = BowBounds{};
  // The chain's reference G (docs/planner.md, "Chains"): d2x/ds2 linear from k0 to k1 along
  // the bow, continuous across vertices; G' = (k1 - k0) / S along the chord and across it,
  // and the residual x'' - G, whose Bezier points are x'''s less those of the line from k0
  // to k1 (raised to the third degree: k0, (2 k0 + k1) / 3, (k0 + 2 k1) / 3, k1).
  {
    const AxisValues& k0 = h.curvature[0];
    const AxisValues& k1 = h.curvature[3];
    AxisValues g{}, r1{}, r2{};
    for (int i = 0; i < n; ++i) {
      g[i] = (k1[i] - k0[i]) / L;
      r1[i] = h.curvature[1][i] - (2.0 * k0[i] + k1[i]) / 3.0;
      r2[i] = h.curvature[2][i] - (k0[i] + 2.0 * k1[i]) / 3.0;
    }
    const Split parts = split(g, c, n);
    b.reference_rate = norm(g, n);
    b.reference_along = std::abs(parts.along);
    b.reference_across = parts.across;
    b.residual = std::max(norm(r1, n), norm(r2, n));
  }
  // Largest sizes through their squares (one root each; the same values as a root per point).
  double slowest = 1.0;  // of x' . c, at least |x'|'s smallest
  double speed2 = 0.0;
  for (const AxisValues& v : h.velocity) {
    speed2 = maxSquare(speed2, dot(v, v, n));
    slowest = std::min(slowest, dot(v, c, n));
    for (int i = 0; i < n; ++i) b.tangent[i] = std::max(b.tangent[i], std::abs(v[i]));
  }
  b.speed = std::sqrt(speed2);
  double curvature2 = 0.0;
  for (const AxisValues& k : h.curvature) {
    curvature2 = maxSquare(curvature2, dot(k, k, n));
    for (int i = 0; i < n; ++i) b.axis_curvature[i] = std::max(b.axis_curvature[i], std::abs(k[i]));
  }
  b.curvature = std::sqrt(curvature2);
  // d3x/ds3 = q(u) = q0 + q1 u + q2 u^2 from its Bezier points (the hull is loose here: 6 k^2
  // on a circle whose d3x/ds3 is k^2): sampled at kRateSamples + 1 points. Between two, q is
  // their linear interpolation (within the larger of their sizes) plus q2 (u - u_a)(u - u_b),
  // at most |q2| h^2 / 4 for a step h; likewise its part along the chord and the rest.
  constexpr int kRateSamples = 16;
  AxisValues q0{}, q1{}, q2{};
  for (int i = 0; i < n; ++i) {
    q0[i] = h.rate[0][i];
    q1[i] = 2.0 * (h.rate[1][i] - h.rate[0][i]);
    q2[i] = h.rate[0][i] - 2.0 * h.rate[1][i] + h.rate[2][i];
  }
  const Split q2_parts = split(q2, c, n);
  // |q(u)|^2 and q(u) . c as polynomials in u, from the dot products of q0, q1, q2 (the
  // samples then cost no loop over the axes).
  const double q00 = dot(q0, q0, n), q01 = dot(q0, q1, n), q02 = dot(q0, q2, n);
  const double q11 = dot(q1, q1, n), q12 = dot(q1, q2, n), q22 = dot(q2, q2, n);
  const double c0 = dot(q0, c, n), c1 = dot(q1, c, n), c2 = q2_parts.along;
  double rate2 = 0.0, across2 = 0.0;
  for (int k = 0; k <= kRateSamples; ++k) {
    const double u = static_cast<double>(k) / kRateSamples;
    const double size2 = std::max(
        q00 + u * (2.0 * q01 + u * (q11 + 2.0 * q02 + u * (2.0 * q12 + u * q22))), 0.0);
    const double along = c0 + u * (c1 + u * c2);
    rate2 = maxSquare(rate2, size2);
    b.rate_along = std::max(b.rate_along, std::abs(along));
    across2 = maxSquare(across2, size2 - along * along);
  }
  b.rate = std::sqrt(rate2);
  b.rate_across = std::sqrt(across2);
  constexpr double kBetween = 0.25 / (kRateSamples * kRateSamples);
  b.rate += kBetween * norm(q2, n);
  b.rate_along += kBetween * std::abs(q2_parts.along);
  b.rate_across += kBetween * q2_parts.across;
  // The part of d2x/ds2 along the tangent, x'' . x' / |x'|, is at most max |x'' . x'| over
  // the smallest |x'|: x'' . x' is a 7th-degree Bezier whose coefficients are the products'
  // (c_k = sum over i + j = k of C(3, i) C(4, j) / C(7, k) x''_i . x'_j).
  constexpr double kBinom3[4] = {1, 3, 3, 1}, kBinom4[5] = {1, 4, 6, 4, 1};
  constexpr double kBinom7[8] = {1, 7, 21, 35, 35, 21, 7, 1};
  std::array<double, 8> product{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 5; ++j)
      product[i + j] += kBinom3[i] * kBinom4[j] / kBinom7[i + j] * dot(h.curvature[i], h.velocity[j], n);
  double tau = 0.0;
  for (double v : product) tau = std::max(tau, std::abs(v));
  b.stretch = b.speed;
  if (b.curvature > 0.0 && slowest > 0.0) b.stretch += tau / slowest / b.curvature;
  // The tangent within the chord's direction (the rotation of a circle lies along the
  // tangent, which turns from c by at most this angle's sine).
  double off = 0.0;
  if (slowest > 0.0) {
    double across2 = 0.0;  // (a division by slowest > 0 is monotone too)
    for (const AxisValues& v : h.velocity)
      across2 = maxSquare(across2, acrossSquared(v, dot(v, c, n), n));
    off = std::sqrt(across2) / slowest;
  }
  b.off_chord = std::min(off, 1.0);
}

void PathSegment::bowPosition(double s, AxisValues& out) const {
  const double u = s / length_, u2 = u * u, u3 = u2 * u, u4 = u3 * u, u5 = u4 * u;
  const double h1 = u - 6.0 * u3 + 8.0 * u4 - 3.0 * u5, h4 = -4.0 * u3 + 7.0 * u4 - 3.0 * u5;
  const double h2 = 0.5 * (u2 - 3.0 * u3 + 3.0 * u4 - u5), h3 = 0.5 * (u3 - 2.0 * u4 + u5);
  out = from_;
  for (int i = 0; i < axis_count_; ++i)
    out[i] = from_[i] + u * delta_[i] + h1 * bow_[0][i] + h4 * bow_[1][i] + h2 * bow_[2][i] +
             h3 * bow_[3][i];
}

void PathSegment::bowVelocity(double s, AxisValues& out) const {
  const double u = std::clamp(s / length_, 0.0, 1.0), u2 = u * u, u3 = u2 * u, u4 = u3 * u;
  const double d1 = 1.0 - 18.0 * u2 + 32.0 * u3 - 15.0 * u4, d4 = -12.0 * u2 + 28.0 * u3 - 15.0 * u4;
  const double d2 = 0.5 * (2.0 * u - 9.0 * u2 + 12.0 * u3 - 5.0 * u4);
  const double d3 = 0.5 * (3.0 * u2 - 8.0 * u3 + 5.0 * u4);
  out = AxisValues{};
  for (int i = 0; i < axis_count_; ++i)
    out[i] = (delta_[i] + d1 * bow_[0][i] + d4 * bow_[1][i] + d2 * bow_[2][i] + d3 * bow_[3][i]) /
             length_;
}

void PathSegment::bowCurvature(double s, AxisValues& out) const {
  const double u = std::clamp(s / length_, 0.0, 1.0), u2 = u * u, u3 = u2 * u;
  const double e1 = -36.0 * u + 96.0 * u2 - 60.0 * u3, e4 = -24.0 * u + 84.0 * u2 - 60.0 * u3;
  const double e2 = 0.5 * (2.0 - 18.0 * u + 36.0 * u2 - 20.0 * u3);
  const double e3 = 0.5 * (6.0 * u - 24.0 * u2 + 20.0 * u3);
  const double L2 = length_ * length_;
  out = AxisValues{};
  for (int i = 0; i < axis_count_; ++i)
    out[i] = (e1 * bow_[0][i] + e4 * bow_[1][i] + e2 * bow_[2][i] + e3 * bow_[3][i]) / L2;
}

}  // namespace ncc::vm::motion
