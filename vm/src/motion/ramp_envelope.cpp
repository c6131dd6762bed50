#include "ncc/vm/motion/ramp_envelope.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "ncc/vm/motion/distinct_axes.h"

namespace ncc::vm::motion {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

void RampEnvelope::add(const Axis& axis) { addDistinctAxis(axes_, count_, axis); }

RampEnvelope::Interval RampEnvelope::interval(int first, int end) const {
  // Over [u0, u1]: alpha is largest at u0, the terms that grow with v at u1.
  const double u0 = top_ * first / kFinestIntervals;
  const double u1 = end == kFinestIntervals ? top_ : top_ * end / kFinestIntervals;
  return {top_ - u0, u1 * u1 * curvature_, 3.0 * u1 * curvature_,
          u1 * u1 * u1 * rate_, u1 * u1 * u1 * rate_across_};
}

bool RampEnvelope::holds(double a, double j, Resolution resolution) const {
  constexpr int kStep = kFinestIntervals / kIntervals;
  for (int m = 0; m < kIntervals; ++m) {
    const int first = m * kStep, end = first + kStep;
    const bool ok = resolution == Resolution::Fine ? holdsWithin(first, end, a, j)
                                                   : holdsOn(interval(first, end), a, j);
    if (!ok) return false;
  }
  return true;
}

bool RampEnvelope::holdsWithin(int first, int end, double a, double j) const {
  if (holdsOn(interval(first, end), a, j)) return true;
  if (end - first == 1) return false;
  const int mid = (first + end) / 2;
  return holdsWithin(first, mid, a, j) && holdsWithin(mid, end, a, j);
}

bool RampEnvelope::holdsOn(const Interval& iv, double a, double j) const {
  const double alpha = std::min(a, std::sqrt(2.0 * j * iv.room));
  const double centripetal = iv.centripetal;
  const double cross = iv.cross_per_alpha * alpha;
  const double rotation = iv.rotation;
  for (int i = 0; i < count_; ++i) {
    const Axis& x = axes_[i];
    // Each axis is within its limit if either bound holds (limits.h, TangentialBudget):
    // the sum of the parts' shares, or the norm of the vector on the curve's plane.
    const bool on_plane = x.normal > 0.0;
    const bool acceleration_ok =
        alpha * x.tangent + centripetal * x.normal <= x.acceleration ||
        (on_plane && alpha * alpha + centripetal * centripetal <= x.acceleration * x.acceleration);
    const bool norm_ok =
        on_plane && rotation <= x.jerk &&
        (along_tangent_ ? (j + rotation - iv.across) * (j + rotation - iv.across) + cross * cross <=
                              (x.jerk - iv.across) * (x.jerk - iv.across)
                        : j * j + cross * cross <= (x.jerk - rotation) * (x.jerk - rotation));
    const bool jerk_ok = j * x.tangent + (cross + rotation) * x.normal <= x.jerk || norm_ok;
    if (!acceleration_ok || !jerk_ok) return false;
  }
  return true;
}

double RampEnvelope::jerkBound(double a, Resolution resolution) const {
  constexpr int kStep = kFinestIntervals / kIntervals;
  std::array<std::pair<double, int>, kIntervals> coarse{};
  for (int m = 0; m < kIntervals; ++m)
    coarse[m] = {jerkBoundOn(interval(m * kStep, (m + 1) * kStep), a), m};
  if (resolution == Resolution::Coarse)
    return std::min_element(coarse.begin(), coarse.end())->first;
  // Branch and bound over the halvings. A narrower interval's bound is never below its
  // parent's, so an interval whose bound is above the smallest so far cannot lower it, and
  // one within kHalvingGain of the smallest finest-interval bound found so far is not worth
  // halving: the result is the minimum over a cover of [0, V] (so it holds everywhere), at
  // most that share below the minimum over the finest intervals. Taken in order of their
  // bounds, the binding intervals come first.
  std::sort(coarse.begin(), coarse.end());
  double bound = kInf, finest = kInf;
  for (const auto& [coarse_bound, m] : coarse) {
    if (!(coarse_bound < bound)) break;
    bound = std::min(bound, jerkBoundWithin(m * kStep, (m + 1) * kStep, a, finest));
  }
  return bound;
}

double RampEnvelope::jerkBoundWithin(int first, int end, double a, double& finest) const {
  const double bound = jerkBoundOn(interval(first, end), a);
  if (end - first == 1) {
    finest = std::min(finest, bound);
    return bound;
  }
  if (!(bound < finest * (1.0 - kHalvingGain))) return bound;
  const int mid = (first + end) / 2;
  const double left = jerkBoundWithin(first, mid, a, finest);
  return std::min(left, jerkBoundWithin(mid, end, a, finest));
}

double RampEnvelope::jerkBoundOn(const Interval& iv, double a) const {
  // Per axis, the largest j with the same bounds as holdsOn(). alpha(j) =
  // min(a, sqrt(2 j D)), D = V - u0: for j >= a^2 / 2D it is a and every bound is linear or
  // quadratic in j; below, it is sqrt(2 j D) and they are quadratic in sqrt(j) (sum form) or
  // in j (norm form). Each bound grows with j, so its largest j is a root, and an axis is
  // within its limit if either form is: the larger of the two.
  double bound = kInf;
  const double d = iv.room;
  const double j_switch = a * a / (2.0 * d);  // alpha reaches a here
  const double centripetal = iv.centripetal;
  const double c3 = iv.cross_per_alpha;
  const double rotation = iv.rotation;
  for (int i = 0; i < count_; ++i) {
    const Axis& x = axes_[i];
    const bool on_plane = x.normal > 0.0;
    // Acceleration: the largest alpha either form allows; above a it does not bind.
    double alpha_max = -kInf;
    if (x.tangent > 0.0) alpha_max = (x.acceleration - centripetal * x.normal) / x.tangent;
    else if (centripetal * x.normal <= x.acceleration) alpha_max = kInf;
    if (on_plane && centripetal <= x.acceleration)
      alpha_max = std::max(alpha_max, std::sqrt(x.acceleration * x.acceleration - centripetal * centripetal));
    if (alpha_max < a) {
      if (!(alpha_max > 0.0)) return 0.0;
      bound = std::min(bound, alpha_max * alpha_max / (2.0 * d));
    }
    // Jerk, sum form: j t + (c3 alpha + rotation) q <= J.
    double sum = -kInf;
    const double left = x.jerk - rotation * x.normal;
    if (c3 * a * x.normal <= left) {  // with alpha = a: j t <= left - c3 a q
      const double rest = left - c3 * a * x.normal;
      const double j1 = x.tangent > 0.0 ? rest / x.tangent : kInf;
      if (j1 >= j_switch) sum = j1;
    }
    if (sum == -kInf && left > 0.0) {
      // alpha = sqrt(2 j D): t s^2 + b s - left <= 0, s = sqrt(j), b = c3 q sqrt(2D).
      const double b = c3 * x.normal * std::sqrt(2.0 * d);
      const double s = x.tangent > 0.0
                           ? 2.0 * left / (b + std::sqrt(b * b + 4.0 * x.tangent * left))
                           : (b > 0.0 ? left / b : kInf);
      sum = std::min(s * s, j_switch);
    }
    // Norm form: (j + r)^2 + (c3 alpha)^2 <= (J - across)^2 with r the rotation along the
    // tangent, else j^2 + (c3 alpha)^2 <= (J - rotation)^2 (r = 0, J - rotation for J).
    double norm = -kInf;
    if (on_plane && rotation <= x.jerk) {
      const double r = along_tangent_ ? rotation - iv.across : 0.0;
      const double top = x.jerk - (along_tangent_ ? iv.across : rotation);
      const double c = top * top;
      if (c3 * a * c3 * a <= c && std::sqrt(c - c3 * a * c3 * a) - r >= j_switch) {
        norm = std::sqrt(c - c3 * a * c3 * a) - r;
      } else {
        // j^2 + (2r + e) j + r^2 - c <= 0 with e = 2 D c3^2 (alpha^2 = 2 j D).
        const double e = 2.0 * d * c3 * c3;
        const double b = 2.0 * r + e;
        const double g = c - r * r;
        norm = std::min(2.0 * g / (b + std::sqrt(b * b + 4.0 * g)), j_switch);
      }
    }
    const double best = std::max(sum, norm);
    if (!(best > 0.0)) return 0.0;
    bound = std::min(bound, best);
  }
  return bound;
}

double RampEnvelope::largestJerk(double a, double floor, double cap, Resolution resolution) const {
  if (holds(a, cap, resolution)) return cap;
  // The closed form, confirmed by holds() (a rounding step below it if needed).
  const double closed = std::min(cap, jerkBound(a, resolution));
  for (double shrink : {0.0, 1e-12, 1e-9, 1e-6}) {
    const double j = closed * (1.0 - shrink);
    if (j >= floor && holds(a, j, resolution)) return j;
  }
  double lo = floor, hi = cap;
  for (int k = 0; k < kJerkSteps; ++k) {
    const double mid = 0.5 * (lo + hi);
    (holds(a, mid, resolution) ? lo : hi) = mid;
  }
  return lo;
}

void RampEnvelope::widen(double& acceleration, double& jerk) const {
  const double a0 = acceleration, j0 = jerk;
  if (!(top_ > 0.0 && a0 > 0.0 && j0 > 0.0 && std::isfinite(a0) && std::isfinite(j0))) return;
  // What any axis allows at rest (no centripetal part): bounds of the search.
  double a_cap = kInf, j_cap = kInf;
  for (int i = 0; i < count_; ++i) {
    const Axis& x = axes_[i];
    if (!(x.tangent > 0.0)) continue;
    const double on_plane = x.normal > 0.0 ? 1.0 : 0.0;
    a_cap = std::min(a_cap, std::max(x.acceleration / x.tangent, on_plane * x.acceleration));
    j_cap = std::min(j_cap, std::max(x.jerk / x.tangent, on_plane * x.jerk));
  }
  if (!std::isfinite(a_cap) || !std::isfinite(j_cap)) return;
  a_cap = std::max(a_cap, a0);
  j_cap = std::max(j_cap, j0);
  double best_a = a0, best_j = j0, best_time = top_ / a0 + a0 / j0;
  // Candidates spaced geometrically from the top-speed choice to the rest limit; at each,
  // the largest jerk the envelope allows. Only pairs that raise neither limit less than the
  // budget's are taken: a profile is never slower with higher limits, so no move (a short one
  // that never reaches V included) loses time.
  // Whether candidate c's pair is faster than the best so far (it becomes the best).
  auto improves = [&](int c, Resolution resolution) {
    const double a = a0 * std::pow(a_cap / a0, static_cast<double>(c) / kCandidates);
    // Its time with the largest jerk anywhere, j_cap, is a bound no search at this a beats
    // (largestJerk() returns at most j_cap, and a rounded quotient and sum are monotone):
    // where it is no better than the best so far, the searches are left out.
    if (!(top_ / a + a / j_cap < best_time)) return false;
    if (!holds(a, j0, resolution)) return false;  // not even the budget's jerk at this a
    const double j = largestJerk(a, j0, j_cap, resolution);
    const double time = top_ / a + a / j;
    if (!(time < best_time)) return false;
    best_time = time, best_a = a, best_j = j;
    return true;
  };
  // Every candidate: their times are not unimodal in c (the largest jerk is piecewise
  // constant in a), and stopping at the first that gained nothing chose a pair up to 20 %
  // slower in 1 of 10,000 random curves (review 12).
  int best_c = 0;
  for (int c = 0; c <= kCandidates; ++c)
    if (improves(c, Resolution::Coarse)) best_c = c;
  // Fine bounds raise every candidate's jerk by a similar share, so the best coarse candidate
  // is where the fine search pays (trying its neighbours too changed no result, at 25 % more
  // cost).
  improves(best_c, Resolution::Fine);
  acceleration = best_a;
  jerk = best_j;
}

}  // namespace ncc::vm::motion
