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

// The axes of the corner: those either side moves (an arc's plane axes, a helix's linear
// axes, a line's axes), at most three. The blend is made in their coordinates.
struct CornerAxes {
  std::array<int, 3> axis{};
  int count = 0;
};

// A line's travel along an axis below this (mm) is rounding: the blend keeps the corner's
// coordinate there, a step far below any servo's resolution.
constexpr double kOffPlane = 1e-9;

// Adds the axes `seg` moves; false if that makes more than three.
bool addAxes(const PathSegment& seg, int axis_count, CornerAxes& axes) {
  for (int i = 0; i < axis_count; ++i) {
    const bool plane = seg.shape() == PathSegment::Shape::Arc &&
                       (i == seg.planeAxis1() || i == seg.planeAxis2());
    if (!plane && !(std::abs(seg.from()[i] - seg.to()[i]) > kOffPlane)) continue;
    if (std::find(axes.axis.begin(), axes.axis.begin() + axes.count, i) !=
        axes.axis.begin() + axes.count)
      continue;
    if (axes.count == 3) return false;
    axes.axis[axes.count++] = i;
  }
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

// The segment's end state at path length s in the corner axes' coordinates (origin `corner`).
CornerBlend::End endState(const PathSegment& seg, double s, const AxisValues& corner,
                          const CornerAxes& axes) {
  AxisValues p, t, k;
  seg.position(s, p);
  seg.tangent(s, t);
  seg.geometricCurvature(s, k);
  CornerBlend::End e;
  for (int j = 0; j < axes.count; ++j) {
    const int i = axes.axis[j];
    e.position[j] = p[i] - corner[i];
    e.tangent[j] = t[i];
    e.curvature[j] = k[i];
  }
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
  if (in.shape() != PathSegment::Shape::Arc && out.shape() != PathSegment::Shape::Arc)
    return std::nullopt;
  CornerAxes axes;
  if (!addAxes(in, axis_count, axes) || !addAxes(out, axis_count, axes)) return std::nullopt;

  AxisValues t_in, t_out;
  in.tangent(in.length(), t_in);
  out.tangent(0.0, t_out);
  const double theta = turnAngle(t_in, t_out, axis_count);
  if (!(theta > 0.0) || theta > CornerBlend::kMaxTurn) return std::nullopt;

  const AxisValues& corner = in.to();
  std::array<AxisValues, 3> basis{};  // the corner axes' unit vectors (0 where fewer)
  for (int j = 0; j < axes.count; ++j) basis[j][axes.axis[j]] = 1.0;
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
    const CornerBlend::End start = endState(in, in.length() - d, corner, axes);
    const CornerBlend::End end = endState(out, d, corner, axes);
    c.curve = CornerBlend::join(corner, basis[0], basis[1], basis[2], start, end, 0.4 * d,
                                0.4 * d, axis_count, CornerBlend::Bounds::Deferred);
    // The programmed path the blend replaces, and the blend's largest distance from it.
    const PathSegment in_part = in.part(in.length() - d, in.length());
    const PathSegment out_part = out.part(0.0, d);
    double worst = 0.0;
    const double step = c.curve.length() / kDeviationSamples;
    std::array<double, kDeviationSamples + 1> samples{};  // 0 at both ends, on the path
    // Every sample, also past the tolerance: the largest is what the next trim is scaled by
    // (stopped at the first sample past it, a miss by far read as a near one, and the trim
    // shrank by 5 % an attempt).
    for (int k = 1; k < kDeviationSamples; ++k) {
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
    // Bounds only for a blend within the tolerance; one without finite bounds (a cusp) is a
    // miss, by far.
    if (worst <= allowed) {
      c.curve.sampleBounds();
      if (!std::isfinite(c.curve.maxCurvatureRate())) worst = tolerance * 1e3;
    }
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
