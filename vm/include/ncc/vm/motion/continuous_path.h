#pragma once
// G64 continuous-path mode: how consecutive feed moves meet (docs/planner.md, "Corners").
//
// A feed move (a line or an arc) is held back until the next primitive shows what happens at
// its end (turning angle theta between the end tangent and the next move's start tangent):
//  - chain (lines only, turns up to kChainMaxTurn): the lines are chords of a smooth curve (a
//    CAM-tessellated circle or spline), planned as that curve (curvature from the circle
//    through the vertices, limits.h ChainShape). With a corner tolerance, each chord is
//    bowed (path.h PathSegment::bow): the vertex gets one tangent (the turn split between
//    its chords in proportion to their lengths) and one curvature vector, so the path passes
//    it with continuous velocity and acceleration; a bow stays within the tolerance of its
//    chord, and noisy chains (the polygon's curvature varying from vertex to vertex by more
//    than kSmoothChange in its second difference; kSmoothKeep once bowed) are not bowed.
//    Without a bow, the polygon itself is followed where it stays
//    within a few nanometres of the curve, its deviation budgeted as "wiggle" in the sampled
//    acceleration and jerk (docs/planner.md, "Chains").
//  - blend: the corner is replaced by a curvature-continuous CornerBlend that stays within
//    the machine's corner tolerance, trimming at most half of each move, when passing the
//    blend is faster than stopping (with a small tolerance and a low jerk limit a blend is
//    passed at a crawl, and a jerk-limited stop is quicker). Between two lines its trim has a
//    closed form (CornerBlend::make); where an arc meets a line or an arc, in the arc's plane,
//    it is fitted (curve_corner.h);
//  - kink: a small turn (<= kCornerAngle), or a tangent junction with a curvature step, passed
//    at the junction velocity of limits.h when that is faster than a blend;
//  - stop: reversals, a zero corner tolerance, or a turn too large to blend.
// Held moves never reach the look-ahead half-decided: each one is queued exactly once, when
// its end is known or nothing can follow (flush).
#include <array>
#include <cstddef>
#include <optional>

#include "ncc/vm/events.h"
#include "ncc/vm/motion/grid_cell.h"
#include "ncc/vm/motion/limits.h"
#include "ncc/vm/motion/lookahead.h"
#include "ncc/vm/motion/path.h"

namespace ncc::vm::motion {

class ContinuousPath {
 public:
  // Queue slots one move() may fill: the held move, a blend, and the new move if it stops.
  static constexpr std::size_t kSlotsPerMove = 3;

  ContinuousPath(const AxisLimits& limits, LookAhead& queue) : limits_(limits), queue_(queue) {}

  // A feed move, `programmed` a line or an arc, at `feed` mm/s (caller checks the queue has
  // kSlotsPerMove free slots). `feed_limit`: what a live feed override scales
  // (QueuedSegment::feed_limit). False, taking nothing, when it does not move.
  bool move(const PathSegment& programmed, double feed, double feed_limit, bool exact_stop,
            const SourcePosition& where);
  // Something other than a feed move follows (or nothing will): queue the held move up to its
  // programmed end point. `at_rest`: the path stops there (a stop, a dwell, a rapid or the
  // program's end follows).
  void flush(bool at_rest);
  bool holding() const { return held_.active; }

  // Queues any segment behind what is queued, with the junction rule: from rest after a stop,
  // a dwell or a change between feed and rapid; else at most both segments' speed limits and
  // `vertex_limit`.
  void enqueue(const QueuedSegment& segment, MotionPrimitive::Kind kind,
               const SegmentLimits& limits, double vertex_limit, bool stop_after);

  // Whether a segment of `kind` queued now joins the path while it moves (else it starts from
  // rest: nothing queued, or a stop, a dwell or a change between feed and rapid before it).
  bool joinsMoving(MotionPrimitive::Kind kind) const;

 private:
  // A bowed chain vertex: the unit tangent and the curvature vector (normal to it) both its
  // bows take there.
  struct BowVertex {
    AxisValues tangent{};
    AxisValues curvature{};
  };
  struct HeldMove {
    bool active = false;
    bool arc = false;        // an arc (its geometry: held_arc_), else a line
    AxisValues from{};       // programmed start point
    AxisValues start{};      // where its queued part starts (after a blend: the blend's end)
    double start_trim = 0.0; // path length a blend took off its start
    AxisValues end{};        // programmed end point
    AxisValues direction{};  // unit tangent at its start (a line's direction)
    AxisValues end_direction{};  // unit tangent at its end
    double length = 0.0;     // programmed length
    double feed = 0.0;       // mm/s
    double feed_limit = 0.0; // QueuedSegment::feed_limit
    SourcePosition where;
    bool exact_stop = false;       // G09/G61
    double start_limit = 0.0;      // junction velocity limit at `start`
    double start_curvature = 0.0;  // chain curvature at its start vertex (0: not a chain vertex)
    // Its start vertex is a bowed chain vertex (BowVertex).
    bool start_bowed = false;
    BowVertex start_bow{};
    // The polygon's curvature vector (c_b - c_a) / mean length at its start vertex and at the
    // vertex before, where those join two lines: what tells a smooth chain from noise.
    int polygon_curvatures = 0;  // how many of these are known (0..2)
    AxisValues start_polygon_curvature{}, polygon_curvature_before{};
    bool start_smooth = true;    // smoothPolygon() at its start vertex (or nothing known)
    AxisValues start_wiggle{};     // the polygon's deviation from the chain's curve there,
                                   // per axis (ChainShape::wiggle)
    AxisValues previous_direction{};  // end tangent of the move before it (zero if none)
    // Its start vertex is a kink passed while moving (from previous_direction to direction),
    // and the previous move's programmed length.
    bool start_kinked = false;
    double previous_length = 0.0;
  };
  // How the held move meets what follows it at its end.
  struct EndVertex {
    AxisValues next_direction{};  // the next move's start tangent (zero if none)
    double next_length = 0.0;     // the next move's programmed length
    double curvature = 0.0;       // chain curvature there (0: not a chain vertex)
    AxisValues wiggle{};          // the chain's wiggle there (ChainShape::wiggle)
    double kink_velocity = 0.0;   // a kink passed at this speed (0: not a kink)
    bool unknown = false;         // what follows is not known yet: it may join at a kink
    bool bowed = false;           // a bowed chain vertex (HeldMove::start_bowed)
    BowVertex bow{};
  };

  // Queues the held move from its start to `end` (an arc: to `end_trim` before its programmed
  // end), a line planned with the chain curvature and wiggle of its two vertices, each move
  // with room for the kinks at its ends. `end_at_rest`: the path stops at `end` (stop_after,
  // or what follows starts from rest).
  void queueHeld(const AxisValues& end, double end_trim, const EndVertex& vertex,
                 bool stop_after, bool end_at_rest = false);
  // Queues `seg`, the held line bowed at one end or both, planned as its chain's curve
  // (bowShape).
  void queueBow(QueuedSegment& seg, const EndVertex& vertex, double jerk_share, bool stop_after,
                bool end_at_rest);
  // `line`, a chain's first or last line bowed at its other end only, bowed at its end where
  // the path rests too (at its start if `at_start`), where the tolerance allows.
  void bowRestingEnd(PathSegment& line, bool at_start) const;
  // What is left of the held move from its start to `end_trim` before its programmed end
  // (a line: to `end`, bowed where its start is a bowed vertex, or to `end_bow`; a bow with
  // its bounds only if `bounds`, PathSegment::bow).
  PathSegment heldPart(const AxisValues& end, double end_trim, const BowVertex* end_bow = nullptr,
                       bool bounds = true) const;
  // The bow of a chain vertex between the held line and the line `next` turning by `theta`
  // (the polygon's curvature vector there `chain`, `smooth` there: smoothPolygon), if the
  // corner tolerance allows one (the bows of both lines within it) and the polygon is smooth
  // there and at the vertex before.
  std::optional<BowVertex> bowVertex(const HeldMove& next, double theta, const AxisValues& chain,
                                     bool smooth) const;
  // Whether the polygon is smooth (not noisy) at the held line's end vertex, where its
  // curvature vector is `k`.
  bool smoothPolygon(const AxisValues& k) const;
  // The bounds a bowed chain line `bow` is planned with, on grids, into `chain` (whose
  // involved axes are set), and the residual curvature its speed is capped for (0: none).
  void bowShape(const PathSegment& bow, ChainShape& chain, double& residual) const;
  // The involved axes and the wiggle of the held line's chain shape, ending at `vertex`.
  void setChainAxes(ChainShape& chain, const EndVertex& vertex) const;
  // Queues `seg`, a chain line or bow with `limits`: rounded down to a grid so that its
  // neighbours join one run (the speed only below `feed_cap`), with the kinks' room.
  void enqueueChainLine(QueuedSegment& seg, SegmentLimits limits, double feed_cap,
                        const EndVertex& vertex, bool stop_after);
  // The held move as programmed.
  PathSegment heldProgrammed() const;
  // The axes the held move or `next` (programmed as `next_path`) moves (1), and those it
  // does not (0).
  AxisValues involvedAxes(const HeldMove& next, const PathSegment& next_path) const;
  // The blend of the held move's corner with `next` (programmed as `next_path`), queued with
  // the held move up to it when it is faster than `unblended`; the blend's end is where `next`
  // then starts.
  bool blendCorner(HeldMove& next, const PathSegment& next_path, double theta, double unblended,
                   double chain_end);
  // The lowest acceleration and jerk limits among the axes in `involved` (infinite if none):
  // what a path through those axes may use.
  struct Weakest {
    double acceleration, jerk;
  };
  Weakest weakest(const AxisValues& involved) const;
  // Highest speed at which the curvature may change by `step` (1/mm) within one cycle: the
  // acceleration step v^2 step reads as a jerk v^2 step / T on the axes in `involved`.
  double curvatureStepLimit(double step, const AxisValues& involved) const;
  // Time a corner costs against passing it at the feeds of the moves on either side
  // (`speed_in`, `speed_out`; path acceleration `accel`, jerk `jerk`): stopping there, or
  // slowing to `blend_speed` for a blend of `blend_length` that replaces `trim` of each move.
  // Decides between the two.
  static double stopCost(double speed_in, double speed_out, double accel, double jerk);
  static double blendCost(double speed_in, double speed_out, double accel, double jerk,
                          double blend_speed, double blend_length, double trim);
  // What a ramp from `from` up to `to` loses against cruising at `to`.
  static double rampCost(double from, double to, double accel, double jerk);
  // The tangential acceleration the held move may use at its kinks, at its start and at its
  // end `vertex`, at most at `velocity` (limits.h kinkAccelerationLimit).
  // Both sides keep room: with a large jerk the acceleration of the move before a kink falls
  // to 0 within a fraction of a cycle, so a sample across the vertex sees nearly all of it.
  double kinkAcceleration(double velocity, const EndVertex& vertex) const;
  // Whether a chain's polygon may deviate from its curve by `wiggle` (per axis, mm): within
  // kWiggleJerkShare of each axis' jerk and kWiggleAccelerationShare of its acceleration.
  bool wiggleFits(const AxisValues& wiggle) const;
  // segmentLimits of a chain line, kept for later lines of the same shape: on fast curves
  // they take a search over the ramp envelope (ramp_envelope.h), several microseconds, and a
  // chain's lines share curvature and wiggle (rounded up to a grid).
  SegmentLimits chainLimits(const PathSegment& line, double feed, const ChainShape& chain,
                            double jerk_share);
  // The cached limits of that shape, if any.
  const SegmentLimits* cachedChainLimits(double feed, const ChainShape& chain,
                                         double jerk_share) const;
  // Its limits computed and cached, for a shape known not to be cached.
  SegmentLimits newChainLimits(const PathSegment& line, double feed, const ChainShape& chain,
                               double jerk_share);

  const AxisLimits& limits_;
  LookAhead& queue_;
  HeldMove held_;
  // The held arc as programmed. Apart from held_: a PathSegment is large (a blend's tables),
  // and copying one per line would cost a fifth of the planning rate.
  PathSegment held_arc_;
  struct ChainLimits {
    bool valid = false;
    double feed = 0.0, jerk_share = 0.0;
    ChainShape shape;
    SegmentLimits limits;
  };
  ChainShape last_bow_shape_;  // the shape of the last bow queued (queueBow)
  std::array<ChainLimits, 32> chain_cache_{};  // the last shapes seen, replaced in turn
  std::size_t chain_cache_next_ = 0;
  // The grids a chain's shape and limits are rounded to, each quantity with its last cell.
  // A chain line's limits are rounded down to a 4.4 % grid, so that neighbouring lines have
  // equal limits and join one run. Its shape is rounded up, so that its lines share one shape
  // and their limits are computed once: the curvature on a 1.1 % grid; the wiggle (the
  // polygon's deviation from the curve, at most a fifth of the jerk) on a 19 % grid, since
  // it changes with every chord length. A cell changes no result, only what it costs: it is
  // mutable, so that the const steps that round a shape keep theirs.
  struct Grids {
    static constexpr int kLimitSteps = 16, kCurvatureSteps = 64, kWiggleSteps = 4;
    GridCell<kLimitSteps, false> velocity, acceleration, jerk;
    GridCell<kCurvatureSteps, true> curvature, polygon_curvature, rate_along;
    GridCell<kWiggleSteps, true> rate_across;
    GridCell<1, true> speed, stretch;
    std::array<GridCell<kWiggleSteps, true>, kMaxAxes> wiggle;
  };
  mutable Grids grids_;
};

}  // namespace ncc::vm::motion
