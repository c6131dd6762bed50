#pragma once
// Per-segment and per-junction velocity/acceleration/jerk limits along the path, derived from
// the axis limits of the machine (docs/planner.md, "Limits").
//
// Budgets. The interpolator's setpoints are checked per axis by finite differences, so the
// path limits must keep every axis within its limit including what the path geometry adds.
// On a curve the axis acceleration is a_t t_i + v^2 k_i (tangential + centripetal) and the
// axis jerk j_t t_i + 3 v a_t k_i + v^3 r_i (r: the rate of the curvature vector):
//  - the path speed is capped so that v^2 k uses at most kCentripetalShare of the axis
//    acceleration and v^3 r a third of the smooth jerk share; a_t and j_t get what is left at
//    that speed, so a slow feed on a curve still accelerates at nearly the full limit, and
//    on arcs and chains more where the ramps allow it (ramp_envelope.h);
//  - lines use kSmoothJerkShare of each axis' jerk; the rest is for the velocity kink and
//    acceleration step a junction may cause within one IPO cycle (a move between stops,
//    which has none, uses kBetweenStopsJerkShare; one without a kink at either end,
//    kKinkFreeJerkShare);
//  - a line in a smooth chain (continuous_path.h) is planned as a curve of the chain's
//    curvature; the polygon's deviation from that curve (at most kWiggleJerkShare of the
//    jerk, see ChainShape) is taken off the budgets.
#include <array>

#include "ncc/machine/axes.h"
#include "ncc/machine/machine_config.h"
#include "ncc/vm/motion/path.h"

namespace ncc::vm::motion {

// Share of each axis' jerk the smooth part of the motion may use; the remainder covers
// junction steps (half each for the velocity kink and the curvature step).
inline constexpr double kSmoothJerkShare = 0.9;
// A move from rest to rest has no junction step at either end (both the kink v |dt| and the
// curvature step v^2 dk are 0 at v = 0), and a sampled jerk is a weighted mean of the jerk
// over its cycles: its smooth part may use the whole jerk (G61/G09 moves, moves between
// corners that stop, non-linear G00) but for 1e-4 of it, which the setpoints' rounding takes:
// of the position, and of the time within a long piece (v ulp(t)), up to 1e-5 of the jerk of
// a very soft axis (15 mm/s^3, a non-linear G00 held and released for 450 s).
inline constexpr double kBetweenStopsJerkShare = 1.0 - 1e-4;
// Direction change (radians) above which an unblended junction is a corner: the path stops
// there (G64 corners are blended first, continuous_path.h).
inline constexpr double kCornerAngle = 0.01;
// Slowest path speed anything is planned with (1 mm/min: F0, a tiny override, a crawl-limited
// curve): a zero speed would never end.
inline constexpr double kMinPathVelocity = 1.0 / 60.0;
// Share of the axis acceleration the centripetal part may take at the top speed of a curve.
inline constexpr double kCentripetalShare = 0.75;
// Largest share of the axis jerk and acceleration a chain's polygon wiggle may take: a
// deviation between 0 and delta from the smooth curve reads, centred, as +-delta/2 of noise,
// at most 2 delta / T^2 in a sampled acceleration and 4 delta / T^3 in a sampled jerk.
inline constexpr double kWiggleJerkShare = 0.2;
inline constexpr double kWiggleAccelerationShare = 0.01;
// Share of the axis jerk a junction's velocity kink, and its curvature step, may each use.
inline constexpr double kJunctionJerkShare = 0.5 * (1.0 - kSmoothJerkShare);
// A move whose ends are passed without a velocity kink (chain vertices, where the turn is
// planned as the chain's curvature; G2 blends; stops) keeps only the curvature step's share.
inline constexpr double kKinkFreeJerkShare = 1.0 - kJunctionJerkShare;
// The share of each axis' jerk a move's smooth motion may use, from the room its ends need:
// kBetweenStopsJerkShare at rest at both ends, else kSmoothJerkShare when an end is (or may
// be) a kink passed moving, else kKinkFreeJerkShare.
constexpr double smoothJerkShare(bool between_stops, bool kink_at_an_end) {
  return between_stops ? kBetweenStopsJerkShare : kink_at_an_end ? kSmoothJerkShare : kKinkFreeJerkShare;
}
// Share of the axis acceleration a junction's velocity kink may use, like its jerk share: a
// short chain may pass several kinks within one cycle. It binds only where the jerk is over
// 1 / T = 1000 times the acceleration per second (the jerk share binds first otherwise).
inline constexpr double kJunctionAccelerationShare = kJunctionJerkShare;

// The machine's axis limits in path units: mm/s, mm/s^2, mm/s^3 (deg for rotary axes).
struct AxisLimits {
  int count = 0;
  std::array<double, kMaxAxes> feed_velocity{};
  std::array<double, kMaxAxes> rapid_velocity{};
  std::array<double, kMaxAxes> acceleration{};
  std::array<double, kMaxAxes> jerk{};
  double ipo_cycle = 0.001;      // s
  double chord_tolerance = 0.001;  // mm
  double corner_tolerance = 0.0;   // mm, G64 blends (0: corners stop)

  static AxisLimits from(const MachineConfig& machine);
};

// The choice of tangential acceleration a_t and jerk j_t on a segment. The axis jerk on a
// curve is the i-th component of j_t T + 3 v k a_t N + v^3 R (T, N orthogonal unit vectors,
// |R| = rho). Two bounds on it hold, and the axis is within its limit if either is:
//  - sum form: j_t t_i + c_i a_t <= J'_i, with c_i = 3 v k q_i and J'_i what is left after
//    the rotation v^3 rho q_i;
//  - norm form (axes on the curve's plane): sqrt(j_t^2 + (3 v k a_t)^2) <= J''_i, with J''_i
//    what is left after v^3 rho.
// split() picks the a_t (and with it the largest j_t) that makes a ramp over the top speed v
// shortest, v/a + a/j (docs/planner.md, "Limits").
class TangentialBudget {
 public:
  struct Axis {
    double tangent;         // t_i
    double cross;           // c_i (sum form)
    double jerk_left;       // J'_i
    double norm_cross;      // 3 v k (0: no norm form for this axis)
    double norm_jerk_left;  // J''_i
    // Rotation along the tangent (a circle, RampEnvelope): the norm form is then
    // sqrt(j_t^2 ...) + this <= J''_i, i.e. (j_t + r)^2 + (3 v k a_t)^2 <= J''_i^2 with J''_i
    // the whole smooth share. 0 otherwise (J''_i already has v^3 rho taken off).
    double norm_rotation = 0.0;
  };
  // Golden-section steps of split(): a_t's bracket shrinks to 0.618^14, about 1e-3 of the
  // axis bound. The ramp time is flat at its minimum (its error is second order in a_t's), so
  // 24 steps planned every contour of bench/optimum_bench to the same millisecond; the search
  // was an eighth of a six-axis chain's planning at 24.
  static constexpr int kSplitSteps = 14;

  void add(const Axis& axis);
  // `acceleration` in: the bound from the axis accelerations; out: the chosen a_t. `jerk` in:
  // any bound already set; out: j_t.
  void split(double v, double& acceleration, double& jerk) const;

 private:
  // The largest j_t every axis allows when a_t = a.
  double jerkAt(double a) const;
  std::array<Axis, kMaxAxes> axes_{};
  int count_ = 0;
};

// Limits along the path of one segment.
struct SegmentLimits {
  double velocity = 0.0;      // mm/s
  double acceleration = 0.0;  // mm/s^2, tangential
  double jerk = 0.0;          // mm/s^3, tangential
};

// A line or bow that is part of a smooth chain of short lines (continuous_path.h), planned as
// a curve:
//  - curvature: bound of |d2x/ds2| on it (the chain's curvature);
//  - rate_along, rate_across: bound of the rate of change of the curvature vector (d3x/ds3,
//    or of the smooth reference a bow's is measured against, continuous_path.cpp), split
//    into its part along the tangent (a circle's rotation, -k^2 T, which combines exactly
//    with the tangential jerk) and the rest;
//  - speed: bound of |dx/ds| (1 on a line; a hair over on a bow), and the stretch (path.h
//    parameterStretch; 1 on a line);
//  - wiggle, per axis: on a polygon's line, its largest distance from the curve along the
//    axis (mm: the sagitta on the axes its vertices turn, 0 on the others); 0 on a bow;
//  - involved, per axis: 1 if the axis moves on it or on a neighbour across a chain vertex
//    (the curve's tangent and normal may point along it), else 0;
//  - ramp_envelope: whether its limits may be widened by a search of the ramp envelope
//    (ramp_envelope.h; several microseconds, worth it where the shape repeats).
struct ChainShape {
  double curvature = 0.0;
  double rate_along = 0.0, rate_across = 0.0;
  double speed = 1.0, stretch = 1.0;
  AxisValues wiggle{};
  AxisValues involved{};
  bool ramp_envelope = true;
  bool operator==(const ChainShape&) const = default;
};

// `feed` is the programmed path speed in mm/s (ignored for rapids, which run at the axes'
// rapid speeds). `chain`: set for a line in a smooth chain. `jerk_share`: of each axis' jerk,
// what the smooth motion may use (kSmoothJerkShare; more where the segment's ends need less
// room: kKinkFreeJerkShare, kBetweenStopsJerkShare).
SegmentLimits segmentLimits(const PathSegment& path, const AxisLimits& axes, bool rapid,
                            double feed, const ChainShape& chain = {},
                            double jerk_share = kSmoothJerkShare);

// Highest velocity at which the path may pass from the end of `a` into the start of `b`
// (both moving segments of the same kind): 0 at a corner (direction change above
// kCornerAngle), else limited so the velocity kink and the curvature step stay within the
// junction share of the axis jerk over one IPO cycle, and the kink within
// kJunctionAccelerationShare of the axis acceleration. Not included: both segments' own
// velocity limits (the look-ahead takes the minimum).
// Kinks closer together than v T fall several within one cycle (about v T / L of them for moves
// of length L), and their velocity steps add up to v^2 |dt_i| / L, like a curvature
// |dt_i| / L: that is kept within the same shares (a circle of r 50 in 2.5 um chords at
// F15000, every vertex a kink, took 1.69x the acceleration limit).
double junctionVelocity(const PathSegment& a, const PathSegment& b, const AxisLimits& axes);

// The tangential acceleration a move may use where it meets the move before it at a kink
// passed at `velocity` (unit tangents `before` and `after`; `length`, the shorter of the two
// moves): the kink steps axis i's velocity by v |dt_i| within one cycle, about
// 1 + v T / length such steps fall within one cycle, and they come on top of the path's
// a_t |t_i| (two moves of close limits share a run, which may pass the kink accelerating).
// Infinite where nothing kinks or at rest.
double kinkAccelerationLimit(const AxisValues& before, const AxisValues& after, double length,
                             double velocity, const AxisLimits& axes);

}  // namespace ncc::vm::motion
