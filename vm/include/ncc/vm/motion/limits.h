#pragma once
// Per-segment and per-junction velocity/acceleration/jerk limits along the path, derived from
// the axis limits of the machine (docs/planner.md, "Limits").
//
// Budgets. The interpolator's setpoints are checked per axis by finite differences, so the
// path limits must keep every axis within its limit including what the path geometry adds:
//  - lines: the path jerk uses kSmoothJerkShare of each axis' jerk; the rest is for the
//    velocity kink and acceleration step a junction may cause within one IPO cycle;
//  - arcs: the axis acceleration is a_t * t_i + v^2 * k_i (tangential + centripetal) and the
//    jerk j_t * t_i + 3 v a_t k_i + v^3 k'_i; each term gets a fixed share.
#include <array>

#include "ncc/machine/axes.h"
#include "ncc/machine/machine_config.h"
#include "ncc/vm/motion/path.h"

namespace ncc::vm::motion {

// Share of each axis' jerk the smooth part of the motion may use; the remainder covers
// junction steps (half each for the velocity kink and the curvature step).
inline constexpr double kSmoothJerkShare = 0.9;
// Direction change (radians) above which a junction is a corner: the path stops there (no G64
// blending in this version).
inline constexpr double kCornerAngle = 0.01;

// The machine's axis limits in path units: mm/s, mm/s^2, mm/s^3 (deg for rotary axes).
struct AxisLimits {
  int count = 0;
  std::array<double, kMaxAxes> feed_velocity{};
  std::array<double, kMaxAxes> rapid_velocity{};
  std::array<double, kMaxAxes> acceleration{};
  std::array<double, kMaxAxes> jerk{};
  double ipo_cycle = 0.001;      // s
  double chord_tolerance = 0.001;  // mm

  static AxisLimits from(const MachineConfig& machine);
};

// Limits along the path of one segment.
struct SegmentLimits {
  double velocity = 0.0;      // mm/s
  double acceleration = 0.0;  // mm/s^2, tangential
  double jerk = 0.0;          // mm/s^3, tangential
};

// `feed` is the programmed path speed in mm/s (ignored for rapids, which run at the axes'
// rapid speeds).
SegmentLimits segmentLimits(const PathSegment& path, const AxisLimits& axes, bool rapid,
                            double feed);

// Highest velocity at which the path may pass from the end of `a` into the start of `b`
// (both moving segments of the same kind): 0 at a corner (direction change above
// kCornerAngle), else limited so the velocity kink and the curvature step stay within the
// junction share of the axis jerk over one IPO cycle. Not included: both segments' own
// velocity limits (the look-ahead takes the minimum).
double junctionVelocity(const PathSegment& a, const PathSegment& b, const AxisLimits& axes);

}  // namespace ncc::vm::motion
