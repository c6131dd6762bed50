#pragma once
// The G64 corner blend: a curvature-continuous (G2) curve that replaces a corner between two
// lines, or where an arc meets a line or another arc, parametrised by its own path length.
//
// A quintic Bezier in the plane of the two lines. Its control points sit on the lines at
// distances d, 0.6 d and 0.2 d from the corner P (three on the incoming line, three on the
// outgoing one), so at both ends the tangent is the line's direction and the curvature is 0:
// position, tangent and curvature are continuous where the blend meets the lines. By symmetry
// the curve comes closest to P at its middle, at distance kDeviationFactor * d * sin(theta/2)
// (theta: the turning angle); that is the largest distance between the blend and the
// programmed lines, so choosing d from the corner tolerance bounds the contour error
// (tests/motion/corner_blend_test.cpp checks it on samples). The control point spacing was
// chosen for the lowest peak curvature and curvature rate at a given deviation
// (docs/planner.md, "Corner blending").
//
// A corner with an arc (join()) is the same kind of quintic, no longer symmetric: at each end
// the handle runs along the tangent, and the third control point leaves it sideways by what
// gives the curve that end's curvature vector (curve_corner.h chooses the trim and checks the
// deviation). Its curvature bounds are sampled for each blend instead of tabulated. A corner
// with a helix, or with a line leaving the arc's plane, is not planar: join() makes the curve
// in a three-dimensional basis (the curve's third coordinate stays 0 for plane corners and
// costs nothing there).
//
// Arc length: a table of s at 32 equal steps of the Bezier parameter (5-point Gauss-Legendre
// per step; make()'s blend is mirror-symmetric, so only its first half is integrated),
// inverted by quintic Hermite interpolation (and, for turns above 0.1 rad, a Newton step);
// exact to about 1e-13 of the blend's length. Curvature bounds come from a table over the
// turning angle, computed once per process. Everything is a pure function of the construction
// arguments: no allocation, no throw.
#include <array>
#include <numbers>

#include "ncc/machine/axes.h"

namespace ncc::vm::motion {

class CornerBlend {
 public:
  // Distance of the blend's middle from the corner per unit of d, divided by sin(theta/2).
  static constexpr double kDeviationFactor = 0.375;
  // Control points on each line, as fractions of d from the corner.
  static constexpr double kOuter = 1.0, kMiddle = 0.6, kInner = 0.2;
  static constexpr int kTableSteps = 32;
  // Largest turning angle a blend is made for (150 degrees): beyond it a blend is a tight
  // loop passed at a crawl, and the arc-length table would need finer steps.
  static constexpr double kMaxTurn = 150.0 * std::numbers::pi / 180.0;

  // Fills the curvature-bound table shared by all blends (a few ms, once per process); the
  // motion planner calls it on construction so that no tick pays for it. make() fills it on
  // first use otherwise.
  static void prepareTables();

  // The blend of the corner `corner` between unit directions `u_in` and `u_out` (not
  // opposite), trimming `d` > 0 off both lines. Starts at corner - d u_in, ends at
  // corner + d u_out.
  static CornerBlend make(const AxisValues& corner, const AxisValues& u_in,
                          const AxisValues& u_out, double d, int axis_count);

  // One end of a blend made by join(), in the basis' coordinates (origin at `origin`):
  // position, unit tangent, and curvature vector d2x/ds2 (orthogonal to the tangent).
  struct End {
    std::array<double, 3> position{}, tangent{}, curvature{};
  };
  // The blend from `start` to `end` in the space through `origin` spanned by the orthonormal
  // `e1`, `e2`, `e3` (`e3` may be 0 for a plane corner), matching position, tangent and
  // curvature at both ends. `handle_start` and `handle_end` (> 0): the tangent handles'
  // lengths, 0.4 of each end's distance from the corner in make()'s shape.
  //
  // Sampling the curvature bounds costs most of a join(): a fit that tries several trims
  // (curve_corner.cpp) asks for Bounds::Deferred, which leaves them infinite (a blend nothing
  // may be planned on at speed), and calls sampleBounds() on the one it keeps.
  enum class Bounds { Sampled, Deferred };
  static CornerBlend join(const AxisValues& origin, const AxisValues& e1, const AxisValues& e2,
                          const AxisValues& e3, const End& start, const End& end,
                          double handle_start, double handle_end, int axis_count,
                          Bounds bounds = Bounds::Sampled);
  // A join()'s curvature bounds, sampled (Bounds::Deferred).
  void sampleBounds();

  double length() const { return s_table_[kTableSteps]; }
  // At path length s in (0, length): position, unit tangent, curvature vector d2x/ds2.
  void position(double s, AxisValues& out) const;
  void tangent(double s, AxisValues& out) const;
  void curvature(double s, AxisValues& out) const;

  // Bounds over the whole blend (sampled densely, with a small margin): the largest curvature
  // |d2x/ds2| and the largest |d3x/ds3| (the rate of the curvature vector: sqrt(k'^2 + k^4)).
  double maxCurvature() const { return max_curvature_; }
  double maxCurvatureRate() const { return max_curvature_rate_; }
  // Per axis: the length of the axis' projection onto the blend's plane (or space), which
  // bounds that axis' share of any vector in it (tangent, curvature).
  double planeShare(int axis) const { return plane_share_[axis]; }

 private:
  // The derivatives and the arc-length tables of the curve px_, py_, pz_ (make(), join());
  // `mirror_symmetric`: the curve is its own mirror image run backwards (make()).
  void buildTables(bool mirror_symmetric);
  // Bezier parameter t at path length s.
  double parameterAt(double s) const;
  // Derivative of the curve at t, and its norm.
  void derivative(double t, double& dx, double& dy, double& dz) const;
  double speed(double t) const;
  // Integral of the speed over [t0, t1] (5-point Gauss-Legendre).
  double arcLength(double t0, double t1) const;

  int axis_count_ = 0;
  AxisValues corner_{};
  AxisValues e1_{};  // the incoming direction
  AxisValues e2_{};  // in the plane, orthogonal to e1, towards the outgoing direction
  AxisValues e3_{};  // join() of a corner that is not planar; else 0
  std::array<double, kMaxAxes> plane_share_{};
  // The curve in the (e1, e2, e3) basis, origin at the corner, as power-basis coefficients
  // (sum c_k t^k, evaluated by Horner: far cheaper per tick than de Casteljau): position
  // (degree 5), first and second derivative. The third coordinate only where `spatial_`.
  std::array<double, 6> px_{}, py_{}, pz_{};
  std::array<double, 5> vx_{}, vy_{}, vz_{};
  std::array<double, 4> ax_{}, ay_{}, az_{};
  bool spatial_ = false;
  std::array<double, kTableSteps + 1> s_table_{};      // path length at t = k / kTableSteps
  std::array<double, kTableSteps + 1> speed_table_{};  // |dc/dt| there
  std::array<double, kTableSteps + 1> dtds2_table_{};  // d2t/ds2 there
  // Turns up to this angle: the quintic Hermite interpolation of t(s) is exact without a Newton
  // step, to 1.4e-13 of the blend's length (3.5e-14 at 0.05 rad; the error grows as the turn
  // squared). Most blends of a dense chain turn less: the step costs a tick 5 Gauss points.
  static constexpr double kInterpolationExactTurn = 0.1;
  bool interpolation_exact_ = false;
  double max_curvature_ = 0.0;
  double max_curvature_rate_ = 0.0;
};

}  // namespace ncc::vm::motion
