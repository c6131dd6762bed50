#include "ncc/vm/motion/curve_corner.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ncc::vm::motion {
namespace {

// Deviation samples along the blend, and attempts at a smaller trim.
constexpr int kDeviationSamples = 64;
// Golden-section steps refining the largest samples (to 1e-8 of the sample spacing).
constexpr int kRefineSteps = 40;
constexpr int kAttempts = 12;
constexpr double kFirstTrimScale = 1.5;
// A fit below this share of the allowed deviation grows its trim, at most kGrowths times.
constexpr double kFillShare = 0.8;
constexpr int kGrowths = 3;

// The plane of the corner (the arc's, or both arcs'), when both segments lie in it.
struct Plane {
  int a1 = 0, a2 = 1;
};

// A line's travel off the plane below this (mm) is rounding: the blend keeps the corner's
// off-plane coordinates, a step far below any servo's resolution.
constexpr double kOffPlane = 1e-9;

bool liesIn(const PathSegment& seg, const Plane& plane, int axis_count) {
  if (seg.shape() == PathSegment::Shape::Arc) {
    const bool same_axes = (seg.planeAxis1() == plane.a1 && seg.planeAxis2() == plane.a2) ||
                           (seg.planeAxis1() == plane.a2 && seg.planeAxis2() == plane.a1);
    // In the plane (no helix); the end radius may differ from the start radius (a spiral:
    // rounded end points, a centre from R, a work offset).
    return seg.planeShare() == 1.0 && same_axes;
  }
  if (seg.shape() != PathSegment::Shape::Line) return false;
  for (int i = 0; i < axis_count; ++i)
    if (i != plane.a1 && i != plane.a2 && std::abs(seg.from()[i] - seg.to()[i]) > kOffPlane)
      return false;
  return true;
}

// Distance of the blend's point at path length s from the programmed path it replaces.
double deviationAt(const CornerBlend& curve, double s, const PathSegment& in_part,
                   const PathSegment& out_part) {
  AxisValues q;
  curve.position(s, q);
  return std::min(in_part.distanceTo(q), out_part.distanceTo(q));
}

// The largest deviation in [lo, hi] around a sampled local maximum, by golden-section search:
// the deviation peaks in a sharp ridge where the nearest side changes from the incoming to the
// outgoing move, which falls between samples (a 92 degree arc-arc corner sampled at 0.970 of
// the tolerance peaked at 1.006).
double refinedPeak(const CornerBlend& curve, double lo, double hi, const PathSegment& in_part,
                   const PathSegment& out_part) {
  constexpr double kGolden = 0.6180339887498949;
  double a = lo, b = hi;
  double x1 = b - kGolden * (b - a), x2 = a + kGolden * (b - a);
  double f1 = deviationAt(curve, x1, in_part, out_part), f2 = deviationAt(curve, x2, in_part, out_part);
  for (int i = 0; i < kRefineSteps; ++i) {
    if (f1 < f2) {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + kGolden * (b - a);
      f2 = deviationAt(curve, x2, in_part, out_part);
    } else {
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - kGolden * (b - a);
      f1 = deviationAt(curve, x1, in_part, out_part);
    }
  }
  return std::max(f1, f2);
}

// The segment's end state at path length s in the plane's coordinates (origin `corner`).
CornerBlend::PlaneEnd planeEnd(const PathSegment& seg, double s, const AxisValues& corner,
                               const Plane& plane) {
  AxisValues p, t, k;
  seg.position(s, p);
  seg.tangent(s, t);
  seg.curvature(s, k);
  CornerBlend::PlaneEnd e;
  e.x = p[plane.a1] - corner[plane.a1];
  e.y = p[plane.a2] - corner[plane.a2];
  e.tx = t[plane.a1];
  e.ty = t[plane.a2];
  e.curvature = e.tx * k[plane.a2] - e.ty * k[plane.a1];
  return e;
}

// Largest trim the side may give: half of it, and half a radian of an arc (beyond, the
// blend would replace a good part of the arc's turn).
double trimLimit(const PathSegment& seg) {
  const double half = 0.5 * seg.length();
  return seg.shape() == PathSegment::Shape::Arc ? std::min(half, 0.5 * seg.radius()) : half;
}

}  // namespace

std::optional<CurveCorner> fitCurveCorner(const PathSegment& in, const PathSegment& out,
                                          double tolerance, int axis_count) {
  if (!(tolerance > 0.0)) return std::nullopt;
  const PathSegment& arc = in.shape() == PathSegment::Shape::Arc ? in : out;
  if (arc.shape() != PathSegment::Shape::Arc) return std::nullopt;
  const Plane plane{arc.planeAxis1(), arc.planeAxis2()};
  if (!liesIn(in, plane, axis_count) || !liesIn(out, plane, axis_count)) return std::nullopt;

  AxisValues t_in, t_out;
  in.tangent(in.length(), t_in);
  out.tangent(0.0, t_out);
  const double cos_t = t_in[plane.a1] * t_out[plane.a1] + t_in[plane.a2] * t_out[plane.a2];
  const double sin_t = std::abs(t_in[plane.a1] * t_out[plane.a2] - t_in[plane.a2] * t_out[plane.a1]);
  const double theta = std::atan2(sin_t, cos_t);
  if (!(theta > 0.0) || theta > CornerBlend::kMaxTurn) return std::nullopt;

  const AxisValues& corner = in.to();
  AxisValues e1{}, e2{};
  e1[plane.a1] = 1.0;
  e2[plane.a2] = 1.0;
  // Start above the two-line blend's trim for this turn (an arc bending towards the corner's
  // inside lets the blend come closer to it; one bending away costs attempts), within each
  // side's share.
  const double cap = std::min(trimLimit(in), trimLimit(out));
  double d = std::min(kFirstTrimScale * tolerance /
                          (CornerBlend::kDeviationFactor * std::sin(0.5 * theta)),
                      cap);
  std::optional<CurveCorner> fits;  // the largest trim found within the tolerance
  int growths = 0;
  for (int attempt = 0; attempt < kAttempts && d > 0.0; ++attempt) {
    CurveCorner c;
    c.trim = d;
    in.position(in.length() - d, c.from);
    out.position(d, c.to);
    const CornerBlend::PlaneEnd start = planeEnd(in, in.length() - d, corner, plane);
    const CornerBlend::PlaneEnd end = planeEnd(out, d, corner, plane);
    c.curve = CornerBlend::join(corner, e1, e2, start, end, 0.4 * d, 0.4 * d, axis_count);
    // The programmed path the blend replaces, and the blend's largest distance from it.
    const PathSegment in_part = in.part(in.length() - d, in.length());
    const PathSegment out_part = out.part(0.0, d);
    double worst = std::isfinite(c.curve.maxCurvatureRate()) ? 0.0 : tolerance * 1e3;
    const double step = c.curve.length() / kDeviationSamples;
    std::array<double, kDeviationSamples + 1> samples{};  // 0 at both ends, on the path
    for (int k = 1; k < kDeviationSamples && worst <= tolerance; ++k) {
      samples[k] = deviationAt(c.curve, step * k, in_part, out_part);
      worst = std::max(worst, samples[k]);
    }
    // The true peaks lie between samples: refine around every sampled local maximum within
    // reach of the tolerance.
    for (int k = 1; k < kDeviationSamples && worst <= tolerance; ++k) {
      if (samples[k] >= samples[k - 1] && samples[k] >= samples[k + 1] &&
          samples[k] > 0.5 * tolerance)
        worst = std::max(worst, refinedPeak(c.curve, step * (k - 1), step * (k + 1), in_part, out_part));
    }
    const double allowed = kCurveCornerToleranceShare * tolerance;
    // The deviation grows about in proportion to the trim.
    if (worst <= allowed) {
      fits = c;
      // Well inside the tolerance (large turns, where the start value, measured to the corner
      // point, is cautious): a larger trim cuts the corner as far as allowed.
      if (worst >= kFillShare * allowed || d >= cap || growths == kGrowths) return fits;
      d = std::min(cap, d * std::min(0.95 * allowed / std::max(worst, 1e-300), 2.0));
      ++growths;
      continue;
    }
    if (fits) return fits;  // grown too far: the last trim that fit
    d *= std::clamp(0.95 * allowed / worst, 0.25, 0.95);
  }
  return fits;
}

}  // namespace ncc::vm::motion
