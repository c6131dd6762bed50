#pragma once
// Path geometry of one motion segment, parametrised by path length s in [0, length].
//
// A line moves every axis in proportion. An arc moves the two plane axes on a circle around
// the centre (a spiral when the end radius differs slightly from the start radius, so the end
// point is met exactly: the radius linear in the angle) while every other axis moves linearly
// with the angle: a helix. The parametrisation is exact for circles and helices (constant
// speed in s). A spiral's is exact at its ends and within a hair of it between
// (path_spiral.cpp, parameterStretch()). A blend is the
// G64 corner blend between two lines (corner_blend.h). A bow is a chord of a smooth chain
// (continuous_path.h) drawn as the quintic through its ends with the chain's tangents and
// curvatures there (path_bow.cpp): s is the chord's length fraction, |dx/ds| is 1 and
// d2x/ds2 the given curvature at both ends.
#include <array>
#include <cstdint>

#include "ncc/machine/axes.h"
#include "ncc/vm/motion/corner_blend.h"

namespace ncc::vm::motion {

class PathSegment {
 public:
  enum class Shape : uint8_t { Line, Arc, Blend, Bow, Dwell };

  // Straight move over the first `axis_count` axes.
  static PathSegment line(const AxisValues& from, const AxisValues& to, int axis_count);
  // Arc/helix in the plane (axis1, axis2) around (cx, cy); counter-clockwise unless `cw`;
  // start == end on the plane axes is a full turn. Plus `extra_turns` full turns.
  static PathSegment arc(const AxisValues& from, const AxisValues& to, int axis_count,
                         int axis1, int axis2, double cx, double cy, bool cw,
                         uint32_t extra_turns);
  // The corner blend `curve`, from `from` to `to` (its end points, exactly where the trimmed
  // lines end and start).
  static PathSegment blend(const AxisValues& from, const AxisValues& to, const CornerBlend& curve,
                           int axis_count);
  // The chord from `from` to `to` bowed so that its unit tangents at the ends are
  // `start_tangent` and `end_tangent` and its curvature vectors (normal to them)
  // `start_curvature` and `end_curvature` (path_bow.cpp); a line where the tangents are its
  // direction and the curvatures zero. Without `bounds`, only its position, tangent and
  // curvature may be asked for (the bounds cost a microsecond to compute).
  static PathSegment bow(const AxisValues& from, const AxisValues& to,
                         const AxisValues& start_tangent, const AxisValues& end_tangent,
                         const AxisValues& start_curvature, const AxisValues& end_curvature,
                         int axis_count, bool bounds = true);
  // Standing still at `at` (a dwell).
  static PathSegment dwell(const AxisValues& at, int axis_count);

  // The piece between path lengths s0 < s1 of a line or an arc, parametrised like this
  // segment (an arc keeps its centre, so a piece of a circle is a circle; a piece of a spiral
  // is the spiral between the same points with its own parameter: its length is within a
  // hair of its arc length, which s1 - s0 matches only as nearly as the parent's s matches
  // the parent's, 3e-6 on a 2 % spiral); the whole segment for (0, length). Its ends are
  // position(s0) and position(s1).
  PathSegment part(double s0, double s1) const;
  // Distance from q to a line, or to an arc of less than half a turn (a spiral: the radial
  // distance, at least the true one; a helix: the distance to its nearest point found, likewise
  // never less than the true one; infinite for other shapes): what checks a blend against the
  // programmed path.
  double distanceTo(const AxisValues& q) const;

  Shape shape() const { return shape_; }
  double length() const { return length_; }
  int axisCount() const { return axis_count_; }
  const AxisValues& from() const { return from_; }
  const AxisValues& to() const { return to_; }

  // Position at path length s; s <= 0 gives `from` and s >= length gives `to` bit-for-bit.
  void position(double s, AxisValues& out) const;
  // Unit tangent dx/ds at s (a bow: the direction of dx/ds, whose length is a hair over 1
  // between its ends).
  void tangent(double s, AxisValues& out) const;
  // Curvature vector d2x/ds2 at s (zero on lines).
  void curvature(double s, AxisValues& out) const;
  // The geometry's curvature vector at s, what a corner blend joining there must match:
  // curvature() except inside a spiral or a bow, whose speed |dx/ds| is a hair off 1 there, so
  // that d2x/ds2 is this times |dx/ds|^2 plus a part along the tangent.
  void geometricCurvature(double s, AxisValues& out) const;

  // Upper bound of |dx_i/ds| over the whole segment, per axis: what projects the path
  // velocity, acceleration and jerk onto axis i (on a spiral possibly a little over 1).
  void maxTangent(AxisValues& out) const;
  // How far this segment is from being parametrised by arc length, as a factor >= 1 the
  // planner divides its limits by: 1 except on a spiral, whose speed |dx/ds| <= 1 varies a
  // little, so d2x/ds2 has a part tau along the tangent: with eps = max tau / k,
  // |a_t dx/ds + v^2 d2x/ds2| <= (1 + eps) sqrt(a_t^2 + (v^2 k)^2), and likewise for the
  // jerk, so the unit-speed bounds hold with the axis limits divided by 1 + eps.
  double parameterStretch() const;
  // The largest curvature |d2x/ds2| on the segment and the largest |d3x/ds3| of the path
  // geometry (the curvature vector's rate of change); 0 on lines.
  double maxCurvature() const;
  double maxCurvatureRate() const;
  // Per axis: bound of the axis' component of the unit normal (0 for axes that only move
  // linearly, or do not move).
  void normalShare(AxisValues& out) const;
  // Arcs: the smallest radius of curvature in the plane (a circle's radius), and the largest
  // speed of the plane axes |d(x1, x2)/ds| (r * sweep / length: 1 for a plain arc, < 1 for a
  // helix; on a spiral at its larger radius). Lines: 0.
  double radius() const;
  double maxPlaneSpeed() const;
  // Arcs: the plane's axes.
  int planeAxis1() const { return axis1_; }
  int planeAxis2() const { return axis2_; }
  // The largest distance of the bow PathSegment::bow(...) would make from its chord, at most.
  static double bowOffset(const AxisValues& from, const AxisValues& to,
                          const AxisValues& start_tangent, const AxisValues& end_tangent,
                          const AxisValues& start_curvature, const AxisValues& end_curvature,
                          int axis_count);
  // Bows: the largest |dx/ds| (1 at the ends; a hair over between). 1 on other shapes.
  double maxSpeed() const;
  // Bows: the chain's reference curvature G (docs/planner.md, "Chains"), linear from the
  // curvature vector at the start to the one at the end: the part of its rate G' along the
  // chord's direction, and the rest plus what the tangent's turn from the chord adds to it (a
  // circle's G' lies along its tangent: limits.h ChainShape); and the largest distance of
  // d2x/ds2 from G.
  double bowReferenceRateAlongChord() const;
  double bowReferenceRateAcrossChord() const;
  double bowResidualCurvature() const;
  // Bows: the same two parts of d3x/ds3 itself.
  double bowRateAlongChord() const;
  double bowRateAcrossChord() const;
  // An arc whose end radius differs from its start radius.
  bool isSpiral() const { return shape_ == Shape::Arc && r0_ != r1_; }
  // A circle in its plane (an arc without helix or spiral part): its rotation term,
  // d3x/ds3 = -k^2 T, lies along the tangent.
  bool isPlaneCircle() const {
    return shape_ == Shape::Arc && plane_share_ == 1.0 && r0_ == r1_;
  }

 private:
  // distanceTo() of a helix.
  double helixDistanceTo(const AxisValues& q) const;
  // Whether a circular helix's squared distance from q has a single minimum (is convex).
  bool convexDistanceFrom(const AxisValues& q) const;

  // Spirals (path_spiral.cpp): s is the integral of ds/dphi = rate0_ + m phi over the angle
  // phi travelled, m = (rate1_ - rate0_) / |sweep|: the line through the spiral's true
  // |dx/dphi| at both ends, so its speed is 1 there and just under 1 between.
  // rate0_, rate1_, length_, the bounds and plane_share_ from the ends, the sweep and the
  // other axes' travel.
  void setSpiralParameter();
  // The true |dx/dphi| where the radius is r: sqrt(b^2 + r^2 + the other axes' per radian).
  double spiralTrueRate(double r) const;
  // The fraction of the sweep (and of the other axes' travel) at path length s.
  double spiralFraction(double s) const;
  // d2x/ds2 at s.
  void spiralCurvature(double s, AxisValues& out) const;
  struct SpiralBounds {
    double plane_speed;           // of |d(x1, x2)/ds|
    double other_axis_tangent;    // |dx_i/ds| <= |delta_i| times this (off the plane)
    double curvature;             // of |d2x/ds2|
    double other_axis_curvature;  // |d2x_i/ds2| <= |delta_i| times this (off the plane)
    double curvature_rate;        // of |d3x/ds3|
    double stretch;               // parameterStretch()
  };
  SpiralBounds computeSpiralBounds() const;
  const SpiralBounds& spiralBounds() const { return spiral_bounds_; }

  // Bows (path_bow.cpp): x(u) = from + u (to - from) + the quintic Hermite weights times
  // bow_ = {S t0 - D, S t1 - D, S^2 k0, S^2 k1}, u = s / S, S = length_. The bounds from
  // them, set with them.
  void setBowBounds();
  // A bow's length in s (path_bow.cpp): its chord `delta` stretched for its end tangents.
  static double bowLength(const AxisValues& delta, const AxisValues& start_tangent,
                          const AxisValues& end_tangent, int axis_count);
  void bowPosition(double s, AxisValues& out) const;
  void bowVelocity(double s, AxisValues& out) const;   // dx/ds
  void bowCurvature(double s, AxisValues& out) const;  // d2x/ds2
  struct BowBounds {
    double speed = 0.0;              // of |dx/ds|
    AxisValues tangent{};            // of |dx_i/ds|
    double curvature = 0.0;          // of |d2x/ds2|
    AxisValues axis_curvature{};     // of |d2x_i/ds2|
    double rate = 0.0;               // of |d3x/ds3|
    double rate_along = 0.0;         // of its part along the chord
    double rate_across = 0.0;        // of the rest
    double off_chord = 0.0;          // of the sine of the tangent's angle to the chord
    double reference_rate = 0.0;     // |G'| (bowReferenceRateAlongChord)
    double reference_along = 0.0, reference_across = 0.0;
    double residual = 0.0;           // of |d2x/ds2 - G|
    double stretch = 1.0;            // parameterStretch()
  };

  Shape shape_ = Shape::Dwell;
  int axis_count_ = 0;
  AxisValues from_{};
  AxisValues to_{};
  AxisValues delta_{};  // to - from (arcs: the non-plane axes only)
  double length_ = 0.0;
  int axis1_ = 0, axis2_ = 1;
  double cx_ = 0.0, cy_ = 0.0;
  double r0_ = 0.0, r1_ = 0.0;
  double theta0_ = 0.0, sweep_ = 0.0;  // radians, signed (negative: clockwise)
  double plane_share_ = 0.0;
  double rate0_ = 0.0, rate1_ = 0.0;  // spirals: ds/dphi at the ends (mm/rad)
  SpiralBounds spiral_bounds_{};      // spirals: computeSpiralBounds(), set with the parameter
  std::array<AxisValues, 4> bow_{};  // bows
  BowBounds bow_bounds_{};
  CornerBlend blend_;  // Blend only
};

// Turning angle (radians) from unit direction u1 to unit direction u2 over the first n axes,
// accurate for tiny and for large angles.
double turnAngle(const AxisValues& u1, const AxisValues& u2, int n);

}  // namespace ncc::vm::motion
