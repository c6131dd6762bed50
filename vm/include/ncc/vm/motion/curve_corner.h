#pragma once
// The G64 blend of a corner where an arc meets a line or another arc (continuous_path.h).
//
// Both sides lose the same path length d (the trim); a CornerBlend::join() runs from the end of
// what is left of the incoming segment to the start of what is left of the outgoing one,
// matching position, tangent and curvature at both ends, so the path stays curvature
// continuous. A corner between two lines has a closed form for the largest d the corner
// tolerance allows (CornerBlend::make); here the arcs' curvature bends the blend, so d starts
// from that closed form and shrinks until the blend, sampled, stays within the tolerance of
// the programmed corner (with a margin for the curve between samples).
//
// The blend is made in the coordinates of the axes either side moves, at most three: a plane
// contour, but also a helix (its plane axes and the axis it climbs along), a line leaving the
// arc's plane, or arcs of two planes. A corner that moves more axes keeps its corner (nullopt);
// so does a line's travel below 1 nm along an axis, which counts as rounding (the blend keeps
// the corner's coordinate there).
#include <optional>

#include "ncc/machine/axes.h"
#include "ncc/vm/motion/corner_blend.h"
#include "ncc/vm/motion/path.h"

namespace ncc::vm::motion {

struct CurveCorner {
  double trim = 0.0;       // path length taken off the end of `in` and the start of `out`
  AxisValues from{}, to{};  // the blend's ends: in.position(in.length() - trim), out.position(trim)
  CornerBlend curve;
};

// Share of the corner tolerance the sampled blend may use.
inline constexpr double kCurveCornerToleranceShare = 0.97;

// The blend of the corner between the end of `in` and the start of `out` (lines or arcs, at
// least one an arc), within `tolerance` of them, trimming at most half of either and at most
// half a radian of an arc. nullopt when the corner cannot be blended that way.
std::optional<CurveCorner> fitCurveCorner(const PathSegment& in, const PathSegment& out,
                                          double tolerance, int axis_count);

}  // namespace ncc::vm::motion
