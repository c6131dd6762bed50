// Spirals: arcs whose end radius differs from their start radius (path.h). The radius is
// linear in the angle phi travelled, r = r0 + b phi, and so is every other axis (Lambda_i per
// radian), as on a helix. The true speed per radian, G(phi) = |dx/dphi| =
// sqrt(b^2 + r^2 + |Lambda|^2), is convex in phi; s is the integral of the line S through G
// at both ends, S(phi) = rate0 + m phi:
//     s(phi) = rate0 phi + m phi^2 / 2,   phi(s) = 2 s / (rate0 + sqrt(rate0^2 + 2 m s)),
// so |dx/ds| = G / S is 1 at both ends (a spiral joins its neighbours and corner blends
// without a velocity step) and, S being a chord above the convex G, at most 1 between. A part
// (a spiral trimmed by corner blends) is parametrised the same way between its own ends. The
// mean-radius arc length, r linear in s, made |dx/ds| 34 on a 0.001 rad arc at R 0.2 growing
// 0.01 mm, and 0.989 at the end of a spiral shrinking 2 % (1.1x the jerk limit at the corner
// blend after it).
#include <algorithm>
#include <cmath>

#include "ncc/vm/motion/path.h"

namespace ncc::vm::motion {

double PathSegment::spiralTrueRate(double r) const {
  const double b = (r1_ - r0_) / sweep_;
  double other = 0.0;  // |Lambda|^2 sweep^2 (delta_ is 0 on the plane axes)
  for (int i = 0; i < axis_count_; ++i) other += delta_[i] * delta_[i];
  other /= sweep_ * sweep_;
  return std::sqrt(b * b + r * r + other);
}

void PathSegment::setSpiralParameter() {
  rate0_ = spiralTrueRate(r0_);
  rate1_ = spiralTrueRate(r1_);
  length_ = 0.5 * (rate0_ + rate1_) * std::abs(sweep_);
  spiral_bounds_ = computeSpiralBounds();
  plane_share_ = spiral_bounds_.plane_speed;
}

double PathSegment::spiralFraction(double s) const {
  if (!(s > 0.0)) return 0.0;
  if (s >= length_) return 1.0;
  const double sweep = std::abs(sweep_), m = (rate1_ - rate0_) / sweep;
  const double root = std::sqrt(std::max(rate0_ * rate0_ + 2.0 * m * s, 0.0));
  return std::min(2.0 * s / (rate0_ + root) / sweep, 1.0);
}

void PathSegment::spiralCurvature(double s, AxisValues& out) const {
  // x(f), f = phi / |sweep|: x'' = x_ff f'^2 + x_f f'' with f' = 1 / (|sweep| S) and
  // f'' = -m f' / S^2 (dS/ds = m / S).
  const double f = spiralFraction(s);
  const double sweep = std::abs(sweep_), m = (rate1_ - rate0_) / sweep;
  const double rate = rate0_ + m * sweep * f;
  const double f1 = 1.0 / (sweep * rate), f2 = -m * f1 / (rate * rate);
  const double dr = r1_ - r0_, r = r0_ + dr * f, theta = theta0_ + sweep_ * f;
  const double c = std::cos(theta), sn = std::sin(theta);
  out = AxisValues{};
  for (int i = 0; i < axis_count_; ++i) out[i] = delta_[i] * f2;
  const double x_f = dr * c - r * sweep_ * sn, y_f = dr * sn + r * sweep_ * c;
  const double x_ff = -2.0 * dr * sweep_ * sn - r * sweep_ * sweep_ * c;
  const double y_ff = 2.0 * dr * sweep_ * c - r * sweep_ * sweep_ * sn;
  out[axis1_] = x_ff * f1 * f1 + x_f * f2;
  out[axis2_] = y_ff * f1 * f1 + y_f * f2;
}

void PathSegment::geometricCurvature(double s, AxisValues& out) const {
  curvature(s, out);
  if (!isSpiral() && shape_ != Shape::Bow) return;
  AxisValues t;
  tangent(s, t);
  double along = 0.0;
  for (int i = 0; i < axis_count_; ++i) along += out[i] * t[i];
  double speed = 0.0;  // |dx/ds|
  if (shape_ == Shape::Bow) {
    AxisValues v;
    bowVelocity(s, v);
    for (int i = 0; i < axis_count_; ++i) speed += v[i] * v[i];
    speed = std::sqrt(speed);
  } else {  // G / S at the angle reached
    const double f = spiralFraction(s);
    speed = spiralTrueRate(r0_ + (r1_ - r0_) * f) / (rate0_ + (rate1_ - rate0_) * f);
  }
  for (int i = 0; i < axis_count_; ++i) out[i] = (out[i] - along * t[i]) / (speed * speed);
}

// With phi' = 1/S, phi'' = -m / S^3 and phi''' = 3 m^2 / S^5 (derivatives in s), and
// x_phi = (b e_r + r e_theta, Lambda), x_phiphi = 2 b e_theta - r e_r,
// x_phiphiphi = -3 b e_r - r e_theta (the plane's signs for a counter-clockwise turn):
//     x'   = x_phi / S                                  (|x'| = G / S <= 1)
//     x''  = x_phiphi / S^2 - m x_phi / S^3
//     x''' = x_phiphiphi / S^3 - 3 m x_phiphi / S^4 + 3 m^2 x_phi / S^5
// bounded with the largest r and G and the smallest S (S lies between its end values, G is
// largest at the larger radius). The part of x'' along the tangent is d|x'|/ds =
// (G' S - G m) / S^3, and G' S - G m = G' (S - G) + G (G' - m): G' = r b / G grows with phi,
// S - G is at most the chord's gap at the ends plus |G'_1 - G'_0| |sweep| / 4 (a convex
// function whose slope grows by that much sags at most this far below its chord).
PathSegment::SpiralBounds PathSegment::computeSpiralBounds() const {
  const double sweep = std::abs(sweep_);
  const double b = (r1_ - r0_) / sweep;
  const double r_max = std::max(r0_, r1_);
  const double g0 = spiralTrueRate(r0_), g1 = spiralTrueRate(r1_);
  const double g_max = std::max(g0, g1);
  const double rate = std::min(rate0_, rate1_);  // smallest S
  const double m = (rate1_ - rate0_) / sweep, am = std::abs(m);
  const double slope0 = r0_ * b / g0, slope1 = r1_ * b / g1;  // G' at the ends
  const double sag = std::max({rate0_ - g0, rate1_ - g1, 0.0}) + std::abs(slope1 - slope0) * sweep / 4.0;
  const double off_slope = std::max(std::abs(slope0 - m), std::abs(slope1 - m));
  const double along = (std::max(std::abs(slope0), std::abs(slope1)) * sag + g_max * off_slope) /
                       (rate * rate * rate);
  const double second = std::sqrt(4.0 * b * b + r_max * r_max);  // |x_phiphi|
  const double third = std::sqrt(9.0 * b * b + r_max * r_max);   // |x_phiphiphi|
  const double rate2 = rate * rate, rate3 = rate2 * rate;
  SpiralBounds out;
  // G / S <= G / G: the plane's share of G, largest at the larger radius.
  out.plane_speed = std::sqrt(b * b + r_max * r_max) / g_max;
  out.other_axis_tangent = 1.0 / (sweep * rate);
  out.curvature = second / rate2 + g_max * am / rate3;
  out.other_axis_curvature = am / (sweep * rate3);
  out.curvature_rate = third / rate3 + 3.0 * second * am / (rate3 * rate) +
                       3.0 * g_max * m * m / (rate3 * rate2);
  // (|a_t| + v^2 tau)^2 + (v^2 k)^2 <= (1 + eps)^2 (a_t^2 + (v^2 k)^2) for v^2 tau <= eps v^2 k.
  out.stretch = 1.0 + along / out.curvature;
  return out;
}

}  // namespace ncc::vm::motion
