#include "ncc/machine/travel.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "absl/strings/str_cat.h"

namespace ncc {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Outside [low, high] by more than the tolerance; NaN is outside.
std::optional<TravelViolation> rangeViolation(const AxisConfig& a, int axis, double low,
                                              double high) {
  if (!(low >= a.min_travel - kTravelTolerance))
    return TravelViolation{axis, false, low, a.min_travel};
  if (!(high <= a.max_travel + kTravelTolerance))
    return TravelViolation{axis, true, high, a.max_travel};
  return std::nullopt;
}

// One row per dialect: the alarm numbers are data.
struct DialectTravelAlarms {
  Dialect dialect;
  TravelAlarmCodes codes;
};
constexpr DialectTravelAlarms kTravelAlarms[] = {
    {Dialect::FanucM, {"OT0500", "OT0501"}},
    {Dialect::FanucT, {"OT0500", "OT0501"}},
    {Dialect::MazakM, {"NCC7210", "NCC7210"}},
    {Dialect::SiemensIsoM, {"10720", "10720"}},
    {Dialect::SiemensDin, {"10720", "10720"}},
};

}  // namespace

std::optional<TravelViolation> travelViolation(std::span<const AxisConfig> axes,
                                               const AxisValues& position) {
  const std::size_t n = std::min<std::size_t>(axes.size(), position.size());
  for (std::size_t i = 0; i < n; ++i)
    if (auto v = rangeViolation(axes[i], static_cast<int>(i), position[i], position[i])) return v;
  return std::nullopt;
}

double arcSweep(const ArcMove& arc) {
  const double x0 = arc.from[arc.axis1] - arc.center1, y0 = arc.from[arc.axis2] - arc.center2;
  const double x1 = arc.to[arc.axis1] - arc.center1, y1 = arc.to[arc.axis2] - arc.center2;
  if (std::hypot(x0, y0) == 0.0 || std::hypot(x1, y1) == 0.0) return 0.0;
  // As PathSegment::arc computes it, so the box is the path's.
  double sweep = std::atan2(y1, x1) - std::atan2(y0, x0);
  if (arc.cw) {
    if (sweep >= 0.0) sweep -= kTwoPi;
  } else {
    if (sweep <= 0.0) sweep += kTwoPi;
  }
  return sweep + (arc.cw ? -kTwoPi : kTwoPi) * static_cast<double>(arc.extra_turns);
}

AxisBox arcExtent(const ArcMove& arc, int axis_count) {
  AxisBox box;
  const int n = std::clamp(axis_count, 0, kMaxAxes);
  for (int i = 0; i < n; ++i) {
    box.low[i] = std::min(arc.from[i], arc.to[i]);
    box.high[i] = std::max(arc.from[i], arc.to[i]);
  }
  const int a1 = arc.axis1, a2 = arc.axis2;
  if (a1 < 0 || a2 < 0 || a1 >= n || a2 >= n || a1 == a2) return box;
  const double sweep = arcSweep(arc);
  if (sweep == 0.0 || !std::isfinite(sweep)) return box;  // a line (or garbage: ends only)
  const double x0 = arc.from[a1] - arc.center1, y0 = arc.from[a2] - arc.center2;
  const double x1 = arc.to[a1] - arc.center1, y1 = arc.to[a2] - arc.center2;
  const double r0 = std::hypot(x0, y0), r1 = std::hypot(x1, y1);
  const double theta0 = std::atan2(y0, x0);
  // The angles the arc passes, as [lo, hi] with theta0 at one end.
  const double lo = sweep > 0.0 ? theta0 : theta0 + sweep;
  const double hi = sweep > 0.0 ? theta0 + sweep : theta0;
  // The radius is linear in the angle, so among the passes of one quadrant direction the
  // first and the last hold the extremes: two evaluations per direction, whatever the turns.
  const auto radiusAt = [&](double theta) {
    const double f = std::clamp((theta - theta0) / sweep, 0.0, 1.0);
    return r0 + (r1 - r0) * f;
  };
  struct Direction {
    double angle;  // of the quadrant point
    int axis;      // the axis it is extreme on
    double sign;   // +1: high side, -1: low side
  };
  const Direction directions[] = {{0.0, a1, 1.0},
                                  {0.5 * std::numbers::pi, a2, 1.0},
                                  {std::numbers::pi, a1, -1.0},
                                  {1.5 * std::numbers::pi, a2, -1.0}};
  for (const Direction& d : directions) {
    const double first = d.angle + kTwoPi * std::ceil((lo - d.angle) / kTwoPi);
    const double last = d.angle + kTwoPi * std::floor((hi - d.angle) / kTwoPi);
    if (!(first <= hi)) continue;  // not passed
    const double centre = d.axis == a1 ? arc.center1 : arc.center2;
    for (const double theta : {first, std::max(first, last)}) {
      const double at = centre + d.sign * radiusAt(theta);
      box.low[d.axis] = std::min(box.low[d.axis], at);
      box.high[d.axis] = std::max(box.high[d.axis], at);
    }
  }
  return box;
}

std::optional<TravelViolation> arcTravelViolation(std::span<const AxisConfig> axes,
                                                  const ArcMove& arc) {
  const int n = static_cast<int>(std::min<std::size_t>(axes.size(), kMaxAxes));
  const AxisBox box = arcExtent(arc, n);
  for (int i = 0; i < n; ++i)
    if (auto v = rangeViolation(axes[static_cast<std::size_t>(i)], i, box.low[i], box.high[i]))
      return v;
  return std::nullopt;
}

TravelAlarmCodes travelAlarmCodes(Dialect dialect) {
  for (const DialectTravelAlarms& row : kTravelAlarms)
    if (row.dialect == dialect) return row.codes;
  return kTravelAlarms[0].codes;
}

std::string travelMessage(const TravelViolation& v, std::span<const AxisConfig> axes) {
  const std::string axis =
      static_cast<std::size_t>(v.axis) < axes.size() ? axes[v.axis].name : std::string("?");
  return absl::StrCat(v.above ? "+" : "-", " overtravel (stored stroke limit): axis ", axis,
                      " would reach ", v.position, ", beyond ",
                      v.above ? "max_travel " : "min_travel ", v.limit);
}

}  // namespace ncc
