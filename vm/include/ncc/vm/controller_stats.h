#pragma once
// Run statistics of a Controller (what `ncc run` summarises), accumulated tick by tick with a
// fixed amount of work and no allocation. Definitions (docs/embedding.md, "Statistics"):
//
//  - program time: time of the last tick produced, k_last * T. The interpolator samples the
//    program's end point on the first tick at or after the planned end (docs/planner.md), so
//    this is the planned time rounded up to the IPO grid (plus one tick for the stop sample).
//  - path length: sum over ticks of |commanded_k - commanded_{k-1}| (all axes, as F counts
//    them), split by the run kind being interpolated (rapid / feed). Exact for lines up to
//    rounding; arcs are short by the chord/arc difference, relative (phi^2)/24 for an angle
//    phi per tick.
//  - max |following error| per axis: the servo model's position controller error.
//  - contour error: |e - (e.u)u|, e = actual - commanded (all axes), u the unit commanded
//    path direction at tick k from the backward difference 3c_k - 4c_{k-1} + c_{k-2} (exact
//    for a path sampled on a parabola, so arcs are not biased by the half-tick chord angle).
//    While the setpoint stands still the previous direction is kept. It is a local measure:
//    with a lag l along an arc of radius r it also contains the sagitta l^2/(2r), and at a
//    corner stop the lag still left along the previous segment counts once the next segment
//    starts. Only feed motion is a contour: ticks of a rapid (and the ticks at rest after one)
//    are left out. The worst tick's source block is kept with it.
//  - extents: per axis, the least and greatest commanded position over the ticks of feed
//    motion and, separately, of rapid motion (both ends of every chord that moves, the chord
//    belonging to the run as for the path length): the part's envelope in machine coordinates.
//  - limit violations: the servo model's counts of samples beyond travel, velocity and
//    acceleration limits (docs/servo.md, "Monitoring").
#include <array>
#include <cstdint>

#include "ncc/machine/axes.h"
#include "ncc/vm/events.h"
#include "ncc/vm/servo/servo_monitor.h"

namespace ncc::vm {

// The least and greatest commanded position of every axis over some of the motion.
struct AxisExtents {
  bool empty = true;  // no such motion: min and max are meaningless
  AxisValues min{};
  AxisValues max{};
};

struct RunStatistics {
  uint64_t ticks = 0;                  // ticks produced
  double program_time = 0.0;           // s
  double path_length = 0.0;            // mm, commanded: rapid + feed
  double rapid_length = 0.0;
  double feed_length = 0.0;
  AxisValues max_following_error{};    // |.|, per axis
  double max_contour_error = 0.0;      // mm
  uint64_t max_contour_error_tick = 0;
  SourcePosition max_contour_error_where;  // the block interpolated on that tick
  AxisExtents feed_extents;            // commanded positions over feed motion
  AxisExtents rapid_extents;           // commanded positions over rapid motion
  std::array<LimitViolations, kMaxAxes> violations{};  // per axis
  int64_t limit_violations = 0;        // sum over axes and kinds
  // Ticks on which the path ramped to a peak below its top speed, or braked to rest, because a
  // stop had to fit within what the look-ahead held while more of the program was to come:
  // its depth (lookahead_segments) or a late prepare() limited the speed.
  uint64_t lookahead_limited_ticks = 0;
};

class StatisticsAccumulator {
 public:
  explicit StatisticsAccumulator(int axis_count) : axis_count_(axis_count) {}

  // Tick k (k increases by one per call). `rapid`: the run being interpolated is a rapid;
  // `path_velocity` 0 marks a tick where a run starts or stops (or the path stands), which
  // still belongs to the previous moving tick's run. `where`: the block being interpolated.
  // The arrays are not the accumulator's own (__restrict: its loop over the axes vectorises
  // without checking that at run time).
  void add(uint64_t k, double time, const AxisValues& __restrict commanded,
           const AxisValues& __restrict actual, const AxisValues& __restrict following_error,
           bool rapid, double path_velocity, SourcePosition where);

  const RunStatistics& statistics() const { return stats_; }

 private:
  int axis_count_;
  RunStatistics stats_;
  bool started_ = false;
  bool previous_rapid_ = false;
  bool motion_rapid_ = false;    // the kind of the last tick that moved
  int extents_rapid_ = -1;       // the kind of the last moving chord (-1: none yet)
  AxisValues previous_{};        // c_{k-1}
  AxisValues before_previous_{}; // c_{k-2}
  // The unit commanded direction is directions_[direction_slot_] / sqrt(direction_norm2_) (zero
  // before the first move), divided out only on ticks that need it. The other slot takes
  // each tick's candidate, so that keeping it is a flip, not a copy.
  AxisValues directions_[2]{};
  int direction_slot_ = 0;
  double direction_norm2_ = 1.0;

  void widen(AxisExtents& extents, const AxisValues& point);
};

}  // namespace ncc::vm
