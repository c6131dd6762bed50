#include "ncc/vm/controller_stats.h"

#include <algorithm>
#include <cmath>

namespace ncc::vm {
namespace {

// Below this the backward difference is rounding noise: keep the previous direction.
constexpr double kMinDirectionNorm = 1e-12;  // mm
// Relative margin on |e|^2 as a bound of the squared contour error (its rounding: ~1e-14).
constexpr double kErrorBoundSlack = 1e-6;

}  // namespace

void StatisticsAccumulator::widen(AxisExtents& extents, const AxisValues& point) {
  if (extents.empty) {
    extents.min = point;
    extents.max = point;
    extents.empty = false;
  }
  for (int i = 0; i < axis_count_; ++i) {
    extents.min[i] = std::min(extents.min[i], point[i]);
    extents.max[i] = std::max(extents.max[i], point[i]);
  }
}

void StatisticsAccumulator::add(uint64_t k, double time, const AxisValues& __restrict commanded,
                                const AxisValues& __restrict actual,
                                const AxisValues& __restrict following_error, bool rapid,
                                double path_velocity, SourcePosition where) {
  const int n = axis_count_;
  if (!started_) {  // the first tick: no previous setpoint, so no motion yet
    previous_ = commanded;
    before_previous_ = commanded;
    started_ = true;
  }

  // One loop over the axes for every per-axis quantity (each sum still in axis order; as
  // separate loops, their set-up costs more than the work on a few axes): the chord from
  // the previous setpoint, the commanded direction d (second-order backward difference of
  // the setpoints), the following error, and e = actual - commanded. d goes straight into the
  // spare direction slot (taken below if it is a direction), e is recomputed on the rare
  // ticks that need it: neither is copied.
  double chord2 = 0.0, norm2 = 0.0, error2 = 0.0;
  AxisValues& d = directions_[1 - direction_slot_];
  for (int i = 0; i < n; ++i) {
    const double step = commanded[i] - previous_[i];
    chord2 += step * step;
    d[i] = 3.0 * commanded[i] - 4.0 * previous_[i] + before_previous_[i];
    norm2 += d[i] * d[i];
    stats_.max_following_error[i] =
        std::max(stats_.max_following_error[i], std::abs(following_error[i]));
    const double e = actual[i] - commanded[i];
    error2 += e * e;
  }

  // Path length.
  const double chord = std::sqrt(chord2);
  stats_.path_length += chord;
  // At rest on this tick (a stop sample, or the first sample of the next run): the chord is
  // the end of the previous tick's run.
  const bool chord_rapid = path_velocity == 0.0 ? previous_rapid_ : rapid;
  (chord_rapid ? stats_.rapid_length : stats_.feed_length) += chord;
  previous_rapid_ = rapid;
  // Extents: both ends of a chord that moves. Its start is in already when the previous
  // moving chord was of the same kind; else it is the other kind's end point, which this
  // kind's path also passes.
  if (chord2 > 0.0) {
    AxisExtents& extents = chord_rapid ? stats_.rapid_extents : stats_.feed_extents;
    if (extents_rapid_ != static_cast<int>(chord_rapid)) widen(extents, previous_);
    widen(extents, commanded);
    extents_rapid_ = chord_rapid;
  }

  // The motion this tick belongs to for the contour error: a tick at rest (a stop sample, a
  // dwell, a feed hold, the wait for the in-position window) belongs to the last run that
  // moved, so the servo settling after a rapid is not taken for a contour error.
  const bool tick_rapid = path_velocity == 0.0 ? motion_rapid_ : rapid;
  if (path_velocity != 0.0) motion_rapid_ = rapid;

  // Commanded direction (its norm is taken on the ticks that use it: a root a tick was a fifth
  // of this function's time).
  if (chord2 > 0.0 && norm2 > kMinDirectionNorm * kMinDirectionNorm) {
    direction_slot_ = 1 - direction_slot_;
    direction_norm2_ = norm2;
  }

  // Contour error, of feed motion only (a rapid is no contour). It is a part of e:
  // |e - (e.u)u| <= |e| for |u| = 1 (or u = 0), and rounding adds about 1e-14 of it, far
  // inside kErrorBoundSlack. A tick whose whole error is below the largest contour error so
  // far cannot raise it: the unit direction and the projection, two dependent sums and a
  // division per axis, are left out.
  const double max2 = stats_.max_contour_error * stats_.max_contour_error;
  if (!tick_rapid && !(error2 * (1.0 + kErrorBoundSlack) < max2)) {
    const AxisValues& direction = directions_[direction_slot_];
    AxisValues u{}, e{};
    const double direction_norm = std::sqrt(direction_norm2_);
    double along = 0.0;
    for (int i = 0; i < n; ++i) {
      u[i] = direction[i] / direction_norm;
      e[i] = actual[i] - commanded[i];
      along += e[i] * u[i];
    }
    double perpendicular2 = 0.0;
    for (int i = 0; i < n; ++i) {
      const double p = e[i] - along * u[i];
      perpendicular2 += p * p;
    }
    // Compared squared: the root only for a new largest value.
    if (perpendicular2 > max2) {
      stats_.max_contour_error = std::sqrt(perpendicular2);
      stats_.max_contour_error_tick = k;
      stats_.max_contour_error_where = where;
    }
  }

  stats_.ticks = k + 1;
  stats_.program_time = time;
  before_previous_ = previous_;
  previous_ = commanded;
}

}  // namespace ncc::vm
