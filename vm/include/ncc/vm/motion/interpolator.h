#pragma once
// The interpolator: the setpoint of IPO tick k at time t = k * T.
//
// Time is kept as integers plus a small fraction: the running profile started `phase`
// seconds after tick `start_tick` (0 <= phase < T), so its local time at tick k is
// (k - start_tick) * T - phase from the integer tick difference; nothing accumulates t += T
// and precision does not decay over long programs. A tick walks through as many segments and
// profiles as end before it (no one-segment-per-cycle cap). A profile that ends at rest hands
// over on the next tick, so every stop is sampled exactly at its programmed end point.
//
// Forward pass, one profile ("piece") at a time over the front run, from the actual velocity:
//  - a closed run (something follows it, or it stops): one profile to its planned exit;
//  - the open last run: if the known rest allows accelerating to the run's top speed and
//    still braking to rest, the piece ends at top speed (a = 0) where braking from top speed
//    still fits; the next piece continues at top speed with whatever has been queued since.
//    Otherwise the piece ramps up only to the highest speed from which a stop still fits
//    and ends there (a = 0); a piece that starts at that speed brakes to rest at the end of
//    the window. (A braking piece is committed once started; ending at the peak lets input
//    that arrives meanwhile carry the path on.)
//  - a non-linear rapid (QueuedSegment::per_axis) is one piece from rest to rest in which
//    every axis follows its own profile (axis_rapid.h);
//  - a run entered above its speed limit (a live feed override turned down) first gets a
//    piece that brakes to that limit, where the rest of the run still leaves room to reach
//    its exit.
// A live feed override or a feed hold (commitForReplan) cuts the running piece where it next
// cruises, so that the rest is planned with the new speed limits. While the queue is held
// (LookAhead::held) no piece starts from rest: the path stands where it stopped.
#include <array>
#include <cstddef>
#include <cstdint>

#include "ncc/machine/axes.h"
#include "ncc/vm/events.h"
#include "ncc/vm/motion/axis_rapid.h"
#include "ncc/vm/motion/limits.h"
#include "ncc/vm/motion/lookahead.h"
#include "ncc/vm/motion/scurve.h"

namespace ncc::vm::motion {

struct SetpointInfo {
  double velocity = 0.0;      // path velocity, mm/s
  double acceleration = 0.0;  // path (tangential) acceleration, mm/s^2
  double jerk = 0.0;          // mm/s^3
  MotionPrimitive::Kind kind = MotionPrimitive::Kind::Dwell;  // run evaluated
  SourcePosition where;       // source of the segment evaluated
  uint32_t segments_finished = 0;  // segments that ended since the previous tick
  bool idle = true;  // no segment running (waiting for input, or done), or standing under hold
  // This tick samples the end of an exact stop (G09/G61) or of a rapid, and more follows:
  // the next piece starts on the next call, so a caller with a servo model can hold the
  // setpoint there until the axes are in position (vm::Controller does).
  bool in_position_check = false;
  // The running piece ramps up to a peak below the run's top speed, or brakes to rest, because
  // a stop must fit within what is queued although more input may follow: the look-ahead (its
  // depth, or a preparation that fell behind) limits the speed.
  bool lookahead_limited = false;
};

class Interpolator {
 public:
  // `limits` (kept by reference) are the axis limits non-linear rapids run with.
  Interpolator(const AxisValues& start, const AxisLimits& limits)
      : position_(start), cycle_(limits.ipo_cycle), limits_(limits) {}

  // Setpoint of tick k (k increases by one per call). `closed`: no more input will come (the
  // last run is final). Returns false when nothing is left to run; `out` then holds the last
  // position. The tick on which the queue runs empty still returns true with the end point.
  bool setpoint(uint64_t k, LookAhead& queue, bool closed, AxisValues& out, SetpointInfo& info);

  // Plans the next kPlannedAhead pieces after the running one (or from rest) from what is
  // queued now, so that setpoint() finds them ready: the preparation's share of the forward
  // pass, done outside the real-time tick (vm::Controller::prepare). Two, because a tick may
  // finish one piece and start the next two. setpoint() takes a plan only if everything it
  // depends on is still bit for bit the same, so the setpoints do not depend on whether or
  // when this is called.
  static constexpr int kPlannedAhead = 2;
  void planNextPiece(const LookAhead& queue, bool closed);

  // The speed limits of what is queued are about to change (a live feed override, a feed
  // hold): the front run's goes from `old_limit` to `new_limit`. Unchanged, the running piece
  // runs on. Else it is shortened: a cruise ends at the next tick, and when the new limit is
  // below the piece's peak, a ramp up under way ends as early as a = 0 allows (its jerk-down
  // phase starts at the next tick); a piece that brakes, or is in its last jerk phase, runs
  // to its end. Returns where the next piece will start, whatever the new plan is.
  // Deterministic: it depends on the ticks taken so far.
  Commitment commitForReplan(const LookAhead& queue, double old_limit, double new_limit);

  const AxisValues& position() const { return position_; }
  // The rapid limits (kept by reference) were changed: a rapid planned ahead is stale.
  void rapidLimitsChanged() { rapid_ahead_ready_ = false; }

 private:
  // Everything a line/arc piece's plan depends on (dwells and non-linear rapids are planned
  // directly: they are cheap or rare).
  struct PieceInputs {
    SegmentLimits limits;
    double run_length = 0.0;
    double piece_start = 0.0;  // run offset
    double v0 = 0.0;           // entry velocity
    double v1 = 0.0;           // planned exit of the run (0 for an open run)
    bool open = false;         // the last run, more may be queued behind it
    bool sameAs(const PieceInputs& o) const;
  };
  struct PiecePlan {
    SCurveProfile profile;
    double piece_end = 0.0;
    bool ends_run = false;
    bool lookahead_limited = false;  // an open run too short to reach top speed and brake
  };
  PieceInputs pieceInputs(const LookAhead& queue, std::size_t run, double piece_start, double v0,
                          bool closed) const;
  PiecePlan planPiece(const PieceInputs& in) const;
  // Whether rapid_ahead_ is the non-linear rapid of `seg` (bit-identical end points).
  bool rapidAheadFor(const QueuedSegment& seg) const;
  void startPiece(LookAhead& queue, bool closed);
  // Pops the front run's segments that end before run offset s (its last one stays).
  void passFinishedSegments(LookAhead& queue, double s, SetpointInfo& info);

  AxisValues position_;  // end of the last finished segment
  double cycle_;
  const AxisLimits& limits_;
  // The running piece.
  bool running_ = false;
  SCurveProfile profile_;
  double duration_ = 0.0;
  double piece_start_ = 0.0;  // run offset where the piece starts
  double piece_end_ = 0.0;    // run offset where it ends
  bool piece_ends_run_ = false;
  bool piece_lookahead_limited_ = false;
  bool per_axis_ = false;  // the piece is a non-linear rapid: axes evaluated by rapid_
  AxisRapid rapid_;
  // Its clock.
  uint64_t start_tick_ = 0;
  double phase_ = 0.0;
  double exit_velocity_ = 0.0;  // of the last finished piece
  uint64_t last_tick_ = 0;      // k of the last setpoint() call
  bool resync_ = true;          // the next piece starts on the tick it is first evaluated
  // planNextPiece()'s results in the order the pieces will run, each valid for exactly its
  // inputs.
  struct PlannedPiece {
    bool ready = false;
    PieceInputs inputs;
    PiecePlan plan;
  };
  std::array<PlannedPiece, kPlannedAhead> ahead_{};
  // The next non-linear rapid, made by planNextPiece when it is the next piece up.
  bool rapid_ahead_ready_ = false;
  AxisRapid rapid_ahead_;
  // What ahead_ was last planned from: the queue's version, the pieces started or finished
  // so far, and `closed`. While all three stand, planNextPiece() has nothing to redo. (No
  // queue reaches the initial version: the first call always plans.)
  uint64_t pieces_changed_ = 0;
  uint64_t planned_queue_version_ = UINT64_MAX;
  uint64_t planned_pieces_changed_ = 0;
  bool planned_closed_ = false;
};

}  // namespace ncc::vm::motion
