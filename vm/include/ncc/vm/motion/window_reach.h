#pragma once
// How far ahead the look-ahead reads (docs/planner.md, "Window by braking distance"): the
// queued length after which more input cannot change the plan, from the fastest speed limit
// among the queued runs.
#include <algorithm>
#include <cmath>
#include <limits>

#include "ncc/vm/motion/limits.h"
#include "ncc/vm/motion/scurve.h"

namespace ncc::vm::motion {

struct WindowReach {
  double acceleration = 0.0;  // the weakest axis'
  double jerk = 0.0;          // its smooth share
  double cycle = 0.0;         // T, s

  // From the machine's weakest axis (a run on any path has at least its limits along the
  // path, up to the share a curve's turning takes).
  static WindowReach of(const AxisLimits& limits) {
    WindowReach reach;
    reach.acceleration = std::numeric_limits<double>::infinity();
    reach.jerk = reach.acceleration;
    for (int i = 0; i < limits.count; ++i) {
      reach.acceleration = std::min(reach.acceleration, limits.acceleration[i]);
      reach.jerk = std::min(reach.jerk, kSmoothJerkShare * limits.jerk[i]);
    }
    reach.cycle = limits.ipo_cycle;
    return reach;
  }

  // For runs of speed limit at most v, acceleration at least a and jerk at least j (those of
  // the machine's weakest axis at most): an open run accelerates to v and must still be able
  // to brake to whatever its exit turns out to be, so twice the braking reserve, plus a few
  // cycles of travel so that the interpolator's pieces stay long.
  double lengthFor(double v, double a, double j) const {
    a = std::min(a, acceleration);
    j = std::min(j, jerk);
    if (!(v > 0.0) || !(a > 0.0) || !(j > 0.0) || !std::isfinite(a) || !std::isfinite(j))
      return 0.0;
    return 2.0 * brakingReserve(v, a, j) + 4.0 * v * cycle;
  }
};

}  // namespace ncc::vm::motion
