#pragma once
// Tangential acceleration and jerk for a curve that hold along every ramp, not only at the
// curve's top speed (docs/planner.md, "Limits").
//
// TangentialBudget (limits.h) prices the centripetal part v^2 k, the cross term 3 v k a_t and
// the rotation v^3 rho at the top speed V together with the full a_t. But every S-curve
// profile planned with velocity limit V, acceleration a and jerk j (scurve.h) has, at every
// instant,
//     |a_t| <= alpha(v) = min(a, sqrt(2 j (V - v))):
// the rest of a ramp up still gains a_t^2 / 2j of speed, and a ramp down has already lost
// that much since its peak (<= V). The terms that grow with v therefore meet the full a_t
// only at lower speeds, and near V the tangential part is small. widen() searches the
// (a, j) with the shortest ramp over V, V/a + a/j, for which every axis stays within its
// limits at every (v, alpha(v), j) of that envelope. It checks the envelope on intervals of v
// with bounds that hold over the whole interval (alpha at the interval's start, the terms
// that grow with v at its end), so the result is safe between the checked speeds too. Where
// such a bound binds, the interval is halved (down to V / kFinestIntervals): the bound of a
// narrower interval is closer to the envelope itself, and the others need no more work.
#include <array>

#include "ncc/machine/axes.h"

namespace ncc::vm::motion {

class RampEnvelope {
 public:
  struct Axis {
    double tangent;       // t_i: bound of |dx_i/ds|
    double normal;        // q_i: bound of the axis' share of the unit normal
    double acceleration;  // what the axis may use (after any wiggle share)
    double jerk;          // likewise, of the smooth jerk share
  };
  // Speed intervals checked first, how often one that binds may be halved, and the search's
  // steps. 16 intervals alone gave up 10 % of the jerk on a fast small circle (r 10 at F6000).
  // The search takes its candidates at Coarse, then the best one again at Fine.
  static constexpr int kIntervals = 16;
  static constexpr int kHalvings = 4;
  static constexpr int kFinestIntervals = kIntervals << kHalvings;
  // jerkBound() halves an interval only while that may raise the bound by this share or more
  // (so it is at most this share below the bound over the finest intervals).
  static constexpr double kHalvingGain = 0.002;
  static constexpr int kCandidates = 8;
  static constexpr int kJerkSteps = 12;

  // A curve with top speed `top`, curvature bound `curvature` and curvature-rate bound
  // `rate` (|d3x/ds3|). `rotation_along_tangent`: the curve is a circle (a plane arc, or a
  // chain line planned as one), whose rotation term v^3 d3x/ds3 = -v^3 k^2 T combines with
  // the tangential jerk exactly: the norm form is then (j + v^3 rho)^2 + (3 v k a)^2 <= J^2
  // (the worst sign, j_t = -j), not sqrt(j^2 + (3 v k a)^2) <= J - v^3 rho. `rate_across`
  // (with rotation_along_tangent): the part of `rate` that is not along the tangent (a bow's
  // chain, limits.h ChainShape), taken off J in the norm form.
  RampEnvelope(double top, double curvature, double rate, bool rotation_along_tangent = false,
               double rate_across = 0.0)
      : top_(top), curvature_(curvature), rate_(rate), rate_across_(rate_across),
        along_tangent_(rotation_along_tangent) {}
  void add(const Axis& axis);

  // (acceleration, jerk) in: limits that already hold at the top speed (TangentialBudget's);
  // out: the pair with the shortest ramp over V among those and the envelope's candidates
  // that are at least as large in both (so no profile gets slower).
  void widen(double& acceleration, double& jerk) const;

  // How finely the envelope is checked: Coarse on kIntervals speed intervals, Fine halving
  // the intervals where the bound binds (see the top of this file).
  enum class Resolution { Coarse, Fine };
  // Whether every axis is within its limits on the whole envelope of (a, j).
  bool holds(double a, double j, Resolution resolution = Resolution::Fine) const;
  // The largest j for which holds(a, j) (up to rounding), in closed form per speed interval
  // and axis; 0 if none.
  double jerkBound(double a, Resolution resolution = Resolution::Fine) const;

 private:
  // Speed interval [u0, u1] of [0, V], as holds() and jerkBound() bound it: the room V - u0
  // that alpha is taken at, and the terms that grow with v at the interval's end. Given in
  // units of V / kFinestIntervals, so that halving is exact.
  struct Interval {
    double room;             // V - u0
    double centripetal;      // u1^2 k
    double cross_per_alpha;  // 3 u1 k (the cross term is this times a_t)
    double rotation;         // u1^3 rho
    double across;           // the part of it not along the tangent (along_tangent_ only)
  };
  Interval interval(int first, int end) const;
  // Whether every axis is within its limits over `iv` (its bounds only, no halving).
  bool holdsOn(const Interval& iv, double a, double j) const;
  // The largest j for which holdsOn(iv, a, j), in closed form; 0 if none.
  double jerkBoundOn(const Interval& iv, double a) const;
  // holds() and jerkBound() over the finest intervals within [first, end), halving only where
  // the bound binds. jerkBound: `finest` is the smallest bound of a finest interval found so
  // far (updated); an interval within kHalvingGain of it is not halved.
  bool holdsWithin(int first, int end, double a, double j) const;
  double jerkBoundWithin(int first, int end, double a, double& finest) const;
  // The largest j in [floor, cap] for which holds(a, j), given holds(a, floor): the closed
  // form of jerkBound when holds() confirms it, else a bisection.
  double largestJerk(double a, double floor, double cap, Resolution resolution) const;

  double top_, curvature_, rate_, rate_across_;
  bool along_tangent_;
  std::array<Axis, kMaxAxes> axes_{};
  int count_ = 0;
};

}  // namespace ncc::vm::motion
