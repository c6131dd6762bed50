#include "ncc/vm/motion/interpolator.h"

#include <algorithm>
#include <cmath>

namespace ncc::vm::motion {

void Interpolator::startPiece(LookAhead& queue, bool closed) {
  Run& run = queue.frontRun();
  queue.setFrontRunStarted(true);
  running_ = true;
  per_axis_ = false;
  if (run.kind == MotionPrimitive::Kind::Dwell) {
    profile_ = SCurveProfile{};
    duration_ = run.dwell_seconds;
    piece_start_ = piece_end_ = 0.0;
    piece_ends_run_ = true;
    return;
  }
  per_axis_ = queue.frontSegment().per_axis;
  if (per_axis_) {
    const QueuedSegment& seg = queue.frontSegment();
    rapid_ = AxisRapid::make(seg.path.from(), seg.path.to(), limits_);
    profile_ = SCurveProfile{};
    duration_ = rapid_.duration();
    piece_end_ = run.length;
    piece_ends_run_ = true;
    return;
  }
  const SegmentLimits& l = run.limits;
  const double v0 = exit_velocity_;
  const double rest = run.length - piece_start_;
  const bool open = queue.frontRunIsLast() && !closed && !run.stop_after;
  if (open) {
    const double top = l.velocity;
    const double brake = rampDistance(0.0, top, l.acceleration, l.jerk);
    const double chunk = rest - brake;
    // Room to reach top speed and hold it for at least one cycle before the braking zone.
    if (chunk >= rampDistance(v0, top, l.acceleration, l.jerk) + top * cycle_) {
      profile_ = planProfile(chunk, v0, top, top, l.acceleration, l.jerk);
      duration_ = profile_.duration;
      piece_end_ = piece_start_ + chunk;
      piece_ends_run_ = false;
      return;
    }
  }
  const double v1 = open ? 0.0 : queue.frontRunExit();
  profile_ = planProfile(rest, v0, v1, l.velocity, l.acceleration, l.jerk);
  duration_ = profile_.duration;
  piece_end_ = run.length;
  piece_ends_run_ = true;
}

bool Interpolator::setpoint(uint64_t k, LookAhead& queue, bool closed, AxisValues& out,
                            SetpointInfo& info) {
  info = SetpointInfo{};
  // Bounded: every iteration finishes a segment or a piece; pieces cover at least one
  // cycle of travel unless they end a run.
  for (std::size_t guard = 2 * queue.size() + 4; guard > 0 && !queue.empty(); --guard) {
    if (!running_) {
      if (resync_) {  // after a stop or starvation: start on this tick
        start_tick_ = k;
        phase_ = 0.0;
        exit_velocity_ = 0.0;
        resync_ = false;
      }
      startPiece(queue, closed);
    }
    Run& run = queue.frontRun();
    const double tau = static_cast<double>(k - start_tick_) * cycle_ - phase_;
    const bool piece_done = tau > duration_;
    const PathState st = profile_.at(piece_done ? duration_ : tau);
    // Run offset reached: the piece's end exactly at its end. (The open last run may have
    // grown since the piece was planned, so its end is piece_end_, not the run's length.)
    const bool at_piece_end = st.s >= profile_.length;
    const double s = at_piece_end ? piece_end_ : piece_start_ + st.s;
    const bool at_run_end = at_piece_end && piece_end_ == run.length;
    // Walk past finished segments of this run.
    while (run.segments > 1) {
      const QueuedSegment& seg = queue.frontSegment();
      if (s <= seg.run_offset + seg.path.length()) break;
      position_ = seg.path.to();
      queue.popSegment();
      ++info.segments_finished;
    }
    if (per_axis_ && !piece_done) {
      rapid_.position(tau, out);
      const AxisRapidMotion motion = rapid_.pathMotion(tau);
      info.velocity = motion.velocity;
      info.acceleration = motion.acceleration;
      info.jerk = motion.jerk;
      info.kind = run.kind;
      info.where = queue.frontSegment().where;
      info.idle = false;
      return true;
    }
    if (!piece_done) {
      const QueuedSegment& seg = queue.frontSegment();
      if (at_run_end && run.segments == 1) out = seg.path.to();
      else seg.path.position(s - seg.run_offset, out);
      info.velocity = st.v;
      info.acceleration = st.a;
      info.jerk = st.j;
      info.kind = run.kind;
      info.where = seg.where;
      info.idle = false;
      return true;
    }
    // The piece ended before this tick: move the clock to its end and continue.
    running_ = false;
    exit_velocity_ = profile_.v_end;
    if (exit_velocity_ == 0.0) {
      resync_ = true;  // at rest: the next piece starts on a tick (exact stop sample)
    } else {
      const double end = phase_ + duration_;
      double whole = std::floor(end / cycle_);
      double frac = end - whole * cycle_;
      if (frac < 0.0) { whole -= 1.0; frac += cycle_; }
      if (frac >= cycle_) { whole += 1.0; frac -= cycle_; }
      start_tick_ += static_cast<uint64_t>(whole);
      phase_ = frac;
    }
    piece_start_ = piece_end_;
    bool positioning = false;  // an exact stop or a rapid's end: the axes must get there
    if (piece_ends_run_ && piece_end_ == run.length) {
      const QueuedSegment& last = queue.frontSegment();
      positioning = exit_velocity_ == 0.0 &&
                    (last.exact_stop || run.kind == MotionPrimitive::Kind::Rapid);
      info.where = last.where;
      position_ = last.path.to();
      queue.popSegment();
      ++info.segments_finished;
      queue.popRun();
      piece_start_ = 0.0;
    } else {
      queue.setFrontRunStarted(true);
    }
    if (queue.empty() || positioning) {
      // Sample the stop: the end point on this tick. After an exact stop or a rapid the next
      // piece starts on a later tick, when the caller has done its in-position check.
      out = position_;
      info.idle = true;
      info.in_position_check = positioning && !queue.empty();
      return true;
    }
  }
  resync_ = true;
  out = position_;
  return false;
}

}  // namespace ncc::vm::motion
