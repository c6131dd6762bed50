#include "ncc/vm/motion/path.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

namespace ncc::vm::motion {
namespace {

// A helix distance search stops at a Newton step below this (mm along the helix); the step
// after it, taken, is far shorter.
constexpr double kConvergedStep = 1e-9;

}  // namespace

PathSegment PathSegment::line(const AxisValues& from, const AxisValues& to, int axis_count) {
  PathSegment p;
  p.shape_ = Shape::Line;
  p.axis_count_ = axis_count;
  p.from_ = from;
  p.to_ = to;
  double sum = 0.0;
  for (int i = 0; i < axis_count; ++i) {
    p.delta_[i] = to[i] - from[i];
    sum += p.delta_[i] * p.delta_[i];
  }
  p.length_ = std::sqrt(sum);
  return p;
}

PathSegment PathSegment::arc(const AxisValues& from, const AxisValues& to, int axis_count,
                             int axis1, int axis2, double cx, double cy, bool cw,
                             uint32_t extra_turns) {
  PathSegment p;
  p.shape_ = Shape::Arc;
  p.axis_count_ = axis_count;
  p.from_ = from;
  p.to_ = to;
  p.axis1_ = axis1;
  p.axis2_ = axis2;
  p.cx_ = cx;
  p.cy_ = cy;
  const double x0 = from[axis1] - cx, y0 = from[axis2] - cy;
  const double x1 = to[axis1] - cx, y1 = to[axis2] - cy;
  p.r0_ = std::hypot(x0, y0);
  p.r1_ = std::hypot(x1, y1);
  if (p.r0_ == 0.0 || p.r1_ == 0.0) return line(from, to, axis_count);  // degenerate: no circle
  p.theta0_ = std::atan2(y0, x0);
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double sweep = std::atan2(y1, x1) - p.theta0_;
  // Counter-clockwise sweeps are in (0, 2pi], clockwise in [-2pi, 0): equal angles are a turn.
  if (cw) {
    if (sweep >= 0.0) sweep -= kTwoPi;
  } else {
    if (sweep <= 0.0) sweep += kTwoPi;
  }
  sweep += (cw ? -kTwoPi : kTwoPi) * static_cast<double>(extra_turns);
  p.sweep_ = sweep;
  double sum = 0.0;
  for (int i = 0; i < axis_count; ++i) {
    if (i == axis1 || i == axis2) continue;
    p.delta_[i] = to[i] - from[i];
    sum += p.delta_[i] * p.delta_[i];
  }
  if (p.r0_ != p.r1_) {
    p.setSpiralParameter();
    return p;
  }
  const double plane = 0.5 * (p.r0_ + p.r1_) * std::abs(sweep);
  p.length_ = std::sqrt(plane * plane + sum);
  p.plane_share_ = plane / p.length_;
  return p;
}

PathSegment PathSegment::blend(const AxisValues& from, const AxisValues& to,
                               const CornerBlend& curve, int axis_count) {
  PathSegment p;
  p.shape_ = Shape::Blend;
  p.axis_count_ = axis_count;
  p.from_ = from;
  p.to_ = to;
  p.blend_ = curve;
  p.length_ = curve.length();
  return p;
}

PathSegment PathSegment::dwell(const AxisValues& at, int axis_count) {
  PathSegment p;
  p.shape_ = Shape::Dwell;
  p.axis_count_ = axis_count;
  p.from_ = at;
  p.to_ = at;
  return p;
}

PathSegment PathSegment::part(double s0, double s1) const {
  if ((s0 <= 0.0 && s1 >= length_) || (shape_ != Shape::Line && shape_ != Shape::Arc)) return *this;
  PathSegment p = *this;
  position(s0, p.from_);
  position(s1, p.to_);
  if (shape_ == Shape::Line) return line(p.from_, p.to_, axis_count_);
  // An arc: the same angle and radius per unit of s (a spiral: see below).
  const double f0 = isSpiral() ? spiralFraction(s0) : s0 / length_;
  const double f1 = isSpiral() ? spiralFraction(s1) : s1 / length_;
  p.theta0_ = theta0_ + sweep_ * f0;
  p.sweep_ = sweep_ * (f1 - f0);
  p.r0_ = r0_ + (r1_ - r0_) * f0;
  p.r1_ = r0_ + (r1_ - r0_) * f1;
  for (int i = 0; i < axis_count_; ++i) p.delta_[i] = delta_[i] * (f1 - f0);
  if (isSpiral() && p.r0_ != p.r1_ && p.sweep_ != 0.0) {
    // A piece of a spiral is the spiral through the same points with its own parameter: unit
    // speed at its own ends, where corner blends join it. (With its parent's, its speed there
    // was below 1, and the axes' speed stepped where a blend joined it: 8.5x the jerk limit
    // where a blend joined a spiral shrinking from R 1 to R 0.5.)
    p.setSpiralParameter();
    return p;
  }
  p.length_ = isSpiral() ? s1 - s0 : length_ * (f1 - f0);  // (a spiral piece too short to be one)
  return p;
}

double PathSegment::distanceTo(const AxisValues& q) const {
  const auto distance = [&](const AxisValues& p) {
    double sum = 0.0;
    for (int i = 0; i < axis_count_; ++i) sum += (q[i] - p[i]) * (q[i] - p[i]);
    return std::sqrt(sum);
  };
  if (shape_ == Shape::Bow || shape_ == Shape::Blend || shape_ == Shape::Dwell)
    return std::numeric_limits<double>::infinity();
  if (shape_ == Shape::Line) {
    double along = 0.0;
    for (int i = 0; i < axis_count_; ++i) along += (q[i] - from_[i]) * delta_[i];
    const double f = length_ > 0.0 ? std::clamp(along / (length_ * length_), 0.0, 1.0) : 0.0;
    AxisValues p = from_;
    for (int i = 0; i < axis_count_; ++i) p[i] = from_[i] + delta_[i] * f;
    return distance(p);
  }
  if (!(std::abs(sweep_) < std::numbers::pi)) return std::numeric_limits<double>::infinity();
  // A helix (its plane share may round to 1 when it climbs by a hair: the plane's distance
  // would then under-estimate by up to that climb).
  for (int i = 0; i < axis_count_; ++i)
    if (delta_[i] != 0.0) return helixDistanceTo(q);
  double off_plane = 0.0;
  for (int i = 0; i < axis_count_; ++i)
    if (i != axis1_ && i != axis2_) off_plane += (q[i] - from_[i]) * (q[i] - from_[i]);
  // Within the arc's wedge (seen from the centre): the radial distance to the arc (to the
  // circle; on a spiral, to its radius at that angle, at least the true distance); else to
  // the nearer end.
  const double qx = q[axis1_] - cx_, qy = q[axis2_] - cy_;
  const double ax = from_[axis1_] - cx_, ay = from_[axis2_] - cy_;
  const double bx = to_[axis1_] - cx_, by = to_[axis2_] - cy_;
  const double side = sweep_ > 0.0 ? 1.0 : -1.0;
  if (side * (ax * qy - ay * qx) >= 0.0 && side * (qx * by - qy * bx) >= 0.0) {
    const double angle = std::atan2(std::abs(ax * qy - ay * qx), ax * qx + ay * qy);
    const double r = r0_ + (r1_ - r0_) * std::min(angle / std::abs(sweep_), 1.0);
    const double radial = std::hypot(qx, qy) - r;
    return std::sqrt(radial * radial + off_plane);
  }
  return std::min(distance(from_), distance(to_));
}

double PathSegment::helixDistanceTo(const AxisValues& q) const {
  // The point at f = s / length, and its first two derivatives in f.
  const double dr = r1_ - r0_;
  double best = std::numeric_limits<double>::infinity();
  auto squared = [&](double f, double& g, double& dg) {
    const double theta = theta0_ + sweep_ * f, r = r0_ + dr * f;
    const double c = std::cos(theta), sn = std::sin(theta);
    double sum = 0.0;
    g = dg = 0.0;
    for (int i = 0; i < axis_count_; ++i) {
      double p = from_[i] + delta_[i] * f, d1 = delta_[i], d2 = 0.0;
      if (i == axis1_) {
        p = cx_ + r * c;
        d1 = dr * c - r * sweep_ * sn;
        d2 = -2.0 * dr * sweep_ * sn - r * sweep_ * sweep_ * c;
      } else if (i == axis2_) {
        p = cy_ + r * sn;
        d1 = dr * sn + r * sweep_ * c;
        d2 = 2.0 * dr * sweep_ * c - r * sweep_ * sweep_ * sn;
      }
      const double e = p - q[i];
      sum += e * e;
      g += e * d1;
      dg += d1 * d1 + e * d2;
    }
    best = std::min(best, std::sqrt(sum));
    return sum;
  };
  // Every point tried is on the helix, so the nearest of them is never nearer than the true
  // distance: the result may only over-estimate it, by far less than the tolerances it is
  // checked against.
  if (dr == 0.0 && convexDistanceFrom(q)) {
    // One minimum: at an end where the slope points outwards, else where the slope changes
    // sign, found by Newton's method kept inside the bracket (bisection where it would leave).
    double g = 0.0, dg = 0.0;
    squared(0.0, g, dg);
    if (g >= 0.0) return best;
    const double g0 = g;
    squared(1.0, g, dg);
    if (g <= 0.0) return best;
    double lo = 0.0, hi = 1.0, f = g0 / (g0 - g);
    constexpr int kBracketSteps = 40;
    for (int k = 0; k < kBracketSteps; ++k) {
      squared(f, g, dg);
      if (g > 0.0) hi = f;
      else if (g < 0.0) lo = f;
      else break;
      double next = dg > 0.0 ? f - g / dg : 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      // Near the minimum the distance moves with the square of the step.
      if (std::abs(next - f) * length_ < kConvergedStep) {
        squared(next, g, dg);
        break;
      }
      f = next;
    }
    return best;
  }
  // Newton's method on the squared distance's slope from the best of a few samples.
  constexpr int kSamples = 16, kNewtonSteps = 8;
  double f = 0.0, g = 0.0, dg = 0.0, nearest = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= kSamples; ++k) {
    const double fk = static_cast<double>(k) / kSamples;
    const double d2 = squared(fk, g, dg);
    if (d2 < nearest) nearest = d2, f = fk;
  }
  for (int k = 0; k < kNewtonSteps; ++k) {
    squared(f, g, dg);
    if (!(dg > 0.0)) break;
    f = std::clamp(f - g / dg, 0.0, 1.0);
  }
  squared(f, g, dg);
  return best;
}

bool PathSegment::convexDistanceFrom(const AxisValues& q) const {
  // On a circular helix the squared distance's second derivative in f is
  // 2 (L^2 + sweep^2 R rho cos(theta - phi)), with L the travel off the plane and (rho, phi)
  // q's polar coordinates around the centre: never negative while the helix stays within a
  // quarter turn either side of q's direction. Its ends do, and it turns less than half a
  // turn, so all of it does.
  const double qx = q[axis1_] - cx_, qy = q[axis2_] - cy_;
  const double start = (from_[axis1_] - cx_) * qx + (from_[axis2_] - cy_) * qy;
  const double end = (to_[axis1_] - cx_) * qx + (to_[axis2_] - cy_) * qy;
  return start >= 0.0 && end >= 0.0;
}

double turnAngle(const AxisValues& u1, const AxisValues& u2, int n) {
  double c = 0.0;
  for (int i = 0; i < n; ++i) c += u1[i] * u2[i];
  double s2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double d = u2[i] - c * u1[i];
    s2 += d * d;
  }
  return std::atan2(std::sqrt(s2), c);
}

void PathSegment::position(double s, AxisValues& out) const {
  if (shape_ == Shape::Dwell || s <= 0.0) {
    out = from_;
    return;
  }
  if (s >= length_) {
    out = to_;
    return;
  }
  if (shape_ == Shape::Blend) {
    blend_.position(s, out);
    return;
  }
  if (shape_ == Shape::Bow) {
    bowPosition(s, out);
    return;
  }
  const double f = isSpiral() ? spiralFraction(s) : s / length_;
  out = from_;
  for (int i = 0; i < axis_count_; ++i) out[i] = from_[i] + delta_[i] * f;
  if (shape_ == Shape::Arc) {
    const double theta = theta0_ + sweep_ * f;
    const double r = r0_ + (r1_ - r0_) * f;
    out[axis1_] = cx_ + r * std::cos(theta);
    out[axis2_] = cy_ + r * std::sin(theta);
  }
}

void PathSegment::tangent(double s, AxisValues& out) const {
  out = AxisValues{};
  if (shape_ == Shape::Dwell || length_ == 0.0) return;
  if (shape_ == Shape::Blend) {
    blend_.tangent(std::clamp(s, 0.0, length_), out);
    return;
  }
  if (shape_ == Shape::Bow) {
    bowVelocity(s, out);
    const double n = std::sqrt(std::inner_product(out.begin(), out.begin() + axis_count_,
                                                  out.begin(), 0.0));
    for (int i = 0; i < axis_count_; ++i) out[i] /= n;
    return;
  }
  for (int i = 0; i < axis_count_; ++i) out[i] = delta_[i] / length_;
  if (shape_ == Shape::Arc) {
    // The direction of dx/df (normalised below), whatever f's rate.
    const double f = isSpiral() ? spiralFraction(s) : std::clamp(s / length_, 0.0, 1.0);
    const double theta = theta0_ + sweep_ * f;
    const double r = r0_ + (r1_ - r0_) * f;
    const double dr = (r1_ - r0_) / length_, dtheta = sweep_ / length_;
    out[axis1_] = dr * std::cos(theta) - r * std::sin(theta) * dtheta;
    out[axis2_] = dr * std::sin(theta) + r * std::cos(theta) * dtheta;
    double n = 0.0;
    for (int i = 0; i < axis_count_; ++i) n += out[i] * out[i];
    n = std::sqrt(n);
    for (int i = 0; i < axis_count_; ++i) out[i] /= n;
  }
}

void PathSegment::curvature(double s, AxisValues& out) const {
  out = AxisValues{};
  if (shape_ == Shape::Blend) {
    blend_.curvature(std::clamp(s, 0.0, length_), out);
    return;
  }
  if (shape_ == Shape::Bow) {
    bowCurvature(s, out);
    return;
  }
  if (shape_ != Shape::Arc) return;
  if (isSpiral()) {
    spiralCurvature(s, out);
    return;
  }
  // A circle or helix, x = c + r (cos, sin)(theta) with theta linear in s: x'' = -r w^2 e_r.
  const double theta = theta0_ + sweep_ * std::clamp(s / length_, 0.0, 1.0);
  const double w = sweep_ / length_, radial = -r0_ * w * w;
  out[axis1_] = radial * std::cos(theta);
  out[axis2_] = radial * std::sin(theta);
}

void PathSegment::maxTangent(AxisValues& out) const {
  out = AxisValues{};
  if (shape_ == Shape::Dwell || length_ == 0.0) return;
  if (shape_ == Shape::Blend) {  // the tangent turns in the blend's plane
    for (int i = 0; i < axis_count_; ++i) out[i] = blend_.planeShare(i);
    return;
  }
  if (shape_ == Shape::Bow) {
    out = bow_bounds_.tangent;
    return;
  }
  if (isSpiral()) {
    const SpiralBounds& bounds = spiralBounds();
    for (int i = 0; i < axis_count_; ++i) out[i] = std::abs(delta_[i]) * bounds.other_axis_tangent;
    out[axis1_] = bounds.plane_speed;
    out[axis2_] = bounds.plane_speed;
    return;
  }
  for (int i = 0; i < axis_count_; ++i) out[i] = std::abs(delta_[i]) / length_;
  if (shape_ == Shape::Arc) {
    // The plane tangent turns: bound each plane axis by the whole plane speed.
    out[axis1_] = plane_share_;
    out[axis2_] = plane_share_;
  }
}

double PathSegment::maxPlaneSpeed() const {
  if (shape_ != Shape::Arc) return 0.0;
  return isSpiral() ? spiralBounds().plane_speed : plane_share_;
}

double PathSegment::parameterStretch() const {
  if (shape_ == Shape::Bow) return bow_bounds_.stretch;
  return isSpiral() ? spiralBounds().stretch : 1.0;
}

double PathSegment::maxSpeed() const { return shape_ == Shape::Bow ? bow_bounds_.speed : 1.0; }

double PathSegment::bowReferenceRateAlongChord() const { return bow_bounds_.reference_along; }

double PathSegment::bowReferenceRateAcrossChord() const {
  return bow_bounds_.reference_across + bow_bounds_.off_chord * bow_bounds_.reference_rate;
}

double PathSegment::bowResidualCurvature() const { return bow_bounds_.residual; }

double PathSegment::bowRateAlongChord() const { return bow_bounds_.rate_along; }

double PathSegment::bowRateAcrossChord() const {
  return bow_bounds_.rate_across + bow_bounds_.off_chord * bow_bounds_.rate;
}

double PathSegment::radius() const {
  if (!isSpiral()) return r0_;
  // A spiral r = r0 + b phi has the radius of curvature (r^2 + b^2)^(3/2) / (r^2 + 2 b^2),
  // which grows with r: the smallest is at the smaller end.
  const double b = (r1_ - r0_) / sweep_, r = std::min(r0_, r1_);
  const double r2 = r * r, b2 = b * b;
  return (r2 + b2) * std::sqrt(r2 + b2) / (r2 + 2.0 * b2);
}

// A circle's |d2x/ds2| and |d3x/ds3| are r w^2 and r |w|^3, with w = plane share / r.
double PathSegment::maxCurvature() const {
  if (shape_ == Shape::Blend) return blend_.maxCurvature();
  if (shape_ == Shape::Bow) return bow_bounds_.curvature;
  if (shape_ != Shape::Arc) return 0.0;
  if (isSpiral()) return spiralBounds().curvature;
  return plane_share_ * plane_share_ / r0_;
}

double PathSegment::maxCurvatureRate() const {
  if (shape_ == Shape::Blend) return blend_.maxCurvatureRate();
  if (shape_ == Shape::Bow) return bow_bounds_.rate;
  if (shape_ != Shape::Arc) return 0.0;
  if (isSpiral()) return spiralBounds().curvature_rate;
  return plane_share_ * plane_share_ * plane_share_ / (r0_ * r0_);
}

void PathSegment::normalShare(AxisValues& out) const {
  out = AxisValues{};
  if (shape_ == Shape::Blend) {
    for (int i = 0; i < axis_count_; ++i) out[i] = blend_.planeShare(i);
  } else if (shape_ == Shape::Bow) {
    const double k = bow_bounds_.curvature;
    for (int i = 0; i < axis_count_; ++i)
      out[i] = k > 0.0 ? bow_bounds_.axis_curvature[i] / k : 0.0;
  } else if (shape_ == Shape::Arc) {
    if (isSpiral()) {
      // The other axes speed up and slow down a little with the spiral's speed.
      const SpiralBounds& bounds = spiralBounds();
      for (int i = 0; i < axis_count_; ++i)
        out[i] = std::abs(delta_[i]) * bounds.other_axis_curvature / bounds.curvature;
    }
    out[axis1_] = 1.0;
    out[axis2_] = 1.0;
  }
}

}  // namespace ncc::vm::motion
