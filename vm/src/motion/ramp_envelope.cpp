#include "ncc/vm/motion/ramp_envelope.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncc::vm::motion {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

void RampEnvelope::add(const Axis& axis) {
  if (count_ >= kMaxAxes) return;
  axes_[count_++] = axis;
}

bool RampEnvelope::holds(double a, double j) const {
  for (int m = 0; m < kIntervals; ++m) {
    // Over [u0, u1]: alpha is largest at u0, the terms that grow with v at u1.
    const double u0 = top_ * m / kIntervals;
    const double u1 = m + 1 == kIntervals ? top_ : top_ * (m + 1) / kIntervals;
    const double alpha = std::min(a, std::sqrt(2.0 * j * (top_ - u0)));
    const double centripetal = u1 * u1 * curvature_;
    const double cross = 3.0 * u1 * curvature_ * alpha;
    const double rotation = u1 * u1 * u1 * rate_;
    for (int i = 0; i < count_; ++i) {
      const Axis& x = axes_[i];
      // Each axis is within its limit if either bound holds (limits.h, TangentialBudget):
      // the sum of the parts' shares, or the norm of the vector on the curve's plane.
      const bool on_plane = x.normal > 0.0;
      const bool acceleration_ok =
          alpha * x.tangent + centripetal * x.normal <= x.acceleration ||
          (on_plane && alpha * alpha + centripetal * centripetal <= x.acceleration * x.acceleration);
      const bool jerk_ok =
          j * x.tangent + (cross + rotation) * x.normal <= x.jerk ||
          (on_plane && rotation <= x.jerk &&
           j * j + cross * cross <= (x.jerk - rotation) * (x.jerk - rotation));
      if (!acceleration_ok || !jerk_ok) return false;
    }
  }
  return true;
}

double RampEnvelope::largestJerk(double a, double floor, double cap) const {
  if (holds(a, cap)) return cap;
  double lo = floor, hi = cap;
  for (int k = 0; k < kJerkSteps; ++k) {
    const double mid = 0.5 * (lo + hi);
    (holds(a, mid) ? lo : hi) = mid;
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
  for (int c = 0; c <= kCandidates; ++c) {
    const double a = a0 * std::pow(a_cap / a0, static_cast<double>(c) / kCandidates);
    if (!holds(a, j0)) continue;  // not even the budget's jerk at this acceleration
    const double j = largestJerk(a, j0, j_cap);
    const double time = top_ / a + a / j;
    if (time < best_time) best_time = time, best_a = a, best_j = j;
  }
  acceleration = best_a;
  jerk = best_j;
}

}  // namespace ncc::vm::motion
