#include "ncc/vm/motion/interpolator.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace ncc::vm::motion {

void Interpolator::startPiece(LookAhead& queue, bool closed) {
  ++pieces_changed_;
  Run& run = queue.frontRun();
  queue.setFrontRunStarted(true);
  running_ = true;
  per_axis_ = false;
  if (run.kind == MotionPrimitive::Kind::Dwell) {
    profile_ = SCurveProfile{};
    duration_ = run.dwell_seconds;
    piece_start_ = piece_end_ = 0.0;
    piece_ends_run_ = true;
    piece_lookahead_limited_ = false;
    return;
  }
  per_axis_ = queue.frontSegment().per_axis;
  if (per_axis_) {
    const QueuedSegment& seg = queue.frontSegment();
    rapid_ = rapidAheadFor(seg) ? rapid_ahead_
                                : AxisRapid::make(seg.path.from(), seg.path.to(), limits_);
    profile_ = SCurveProfile{};
    duration_ = rapid_.duration();
    piece_end_ = run.length;
    piece_ends_run_ = true;
    piece_lookahead_limited_ = false;
    return;
  }
  const PieceInputs in = pieceInputs(queue, 0, piece_start_, exit_velocity_, closed);
  const PiecePlan plan =
      ahead_[0].ready && in.sameAs(ahead_[0].inputs) ? ahead_[0].plan : planPiece(in);
  std::shift_left(ahead_.begin(), ahead_.end(), 1);  // the next one up is the front now
  ahead_.back().ready = false;
  profile_ = plan.profile;
  duration_ = profile_.duration;
  piece_end_ = plan.piece_end;
  piece_ends_run_ = plan.ends_run;
  piece_lookahead_limited_ = plan.lookahead_limited;
}

bool Interpolator::rapidAheadFor(const QueuedSegment& seg) const {
  // The limits are fixed while it is ready (rapidLimitsChanged): the end points decide.
  auto same = [](const AxisValues& a, const AxisValues& b) {
    return std::memcmp(a.data(), b.data(), sizeof(AxisValues)) == 0;
  };
  return rapid_ahead_ready_ && same(rapid_ahead_.from(), seg.path.from()) &&
         same(rapid_ahead_.to(), seg.path.to());
}

bool Interpolator::PieceInputs::sameAs(const PieceInputs& o) const {
  auto same = [](double a, double b) {
    return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b);
  };
  return same(limits.velocity, o.limits.velocity) &&
         same(limits.acceleration, o.limits.acceleration) && same(limits.jerk, o.limits.jerk) &&
         same(run_length, o.run_length) && same(piece_start, o.piece_start) && same(v0, o.v0) &&
         same(v1, o.v1) && open == o.open;
}

Interpolator::PieceInputs Interpolator::pieceInputs(const LookAhead& queue, std::size_t run,
                                                    double piece_start, double v0,
                                                    bool closed) const {
  const Run& r = queue.run(run);
  PieceInputs in;
  in.limits = r.limits;
  in.limits.velocity = queue.velocity(run);  // under a live feed override
  in.run_length = r.length;
  in.piece_start = piece_start;
  in.v0 = v0;
  in.open = run + 1 == queue.runCount() && !closed && !r.stop_after;
  in.v1 = in.open ? 0.0 : queue.runExit(run);
  return in;
}

Interpolator::PiecePlan Interpolator::planPiece(const PieceInputs& in) const {
  const SegmentLimits& l = in.limits;
  const double rest = in.run_length - in.piece_start;
  PiecePlan plan;
  if (in.v0 > l.velocity) {
    // Entered above its speed limit (a live feed override turned down): brake to the limit
    // first, ending the piece there (a = 0), if the rest still reaches the exit (at rest for an
    // open run) from the limit; else the profile below cruises on and brakes to the exit.
    const double target = in.open ? l.velocity : std::max(l.velocity, in.v1);
    const double brake = rampDistance(target, in.v0, l.acceleration, l.jerk);
    const double after = rest - brake;
    const double exit = in.open ? 0.0 : in.v1;
    if (target < in.v0 && after > target * cycle_ &&
        reachableVelocity(exit, after, l.acceleration, l.jerk) >= target) {
      plan.profile = planProfile(brake, in.v0, target, target, l.acceleration, l.jerk);
      plan.piece_end = in.piece_start + brake;
      plan.ends_run = false;
      return plan;
    }
  }
  if (in.open) {
    const double top = l.velocity;
    const double brake = rampDistance(0.0, top, l.acceleration, l.jerk);
    const double chunk = rest - brake;
    // Room to reach top speed and hold it for at least one cycle before the braking zone.
    if (chunk >= rampDistance(in.v0, top, l.acceleration, l.jerk) + top * cycle_) {
      plan.profile = planProfile(chunk, in.v0, top, top, l.acceleration, l.jerk);
      plan.piece_end = in.piece_start + chunk;
      plan.ends_run = false;
      return plan;
    }
    // Top speed is out of reach within what is queued. Ramp up only to the highest speed from
    // which a stop still fits, ending the piece there (a = 0, where the ramps would meet):
    // input that arrives meanwhile lets the next piece go on accelerating, where a piece that
    // also braked would be committed to stopping.
    const SCurveProfile whole = planProfile(rest, in.v0, 0.0, top, l.acceleration, l.jerk);
    if (whole.v_peak > in.v0 && whole.accel.duration >= cycle_) {
      plan.profile = planProfile(whole.accel.distance, in.v0, whole.v_peak, whole.v_peak,
                                 l.acceleration, l.jerk);
      plan.piece_end = in.piece_start + whole.accel.distance;
      plan.ends_run = false;
      plan.lookahead_limited = whole.v_peak < top;
      return plan;
    }
  }
  plan.profile = planProfile(rest, in.v0, in.v1, l.velocity, l.acceleration, l.jerk);
  plan.piece_end = in.run_length;
  plan.ends_run = true;
  plan.lookahead_limited = in.open;
  return plan;
}

void Interpolator::planNextPiece(const LookAhead& queue, bool closed) {
  if (queue.empty()) return;
  if (queue.version() == planned_queue_version_ &&
      pieces_changed_ == planned_pieces_changed_ && closed == planned_closed_)
    return;  // nothing it depends on has changed since the last call
  planned_queue_version_ = queue.version();
  planned_pieces_changed_ = pieces_changed_;
  planned_closed_ = closed;
  // Where the next piece starts: after the running one (at its exit velocity), or, at rest or
  // between pieces, at the front run where the last one ended.
  std::size_t run = 0;
  double piece_start = piece_start_;
  double v0 = resync_ ? 0.0 : exit_velocity_;
  if (running_) {
    // A rapid or a dwell is its own run and ends at rest.
    const bool whole_run = per_axis_ || queue.run(0).kind == MotionPrimitive::Kind::Dwell;
    run = whole_run || piece_ends_run_ ? 1 : 0;
    piece_start = whole_run || piece_ends_run_ ? 0.0 : piece_end_;
    v0 = whole_run ? 0.0 : profile_.v_end;
  }
  for (PlannedPiece& slot : ahead_) {
    if (run >= queue.runCount()) return;
    const Run& r = queue.run(run);
    // The run's first queued segment: after the remaining segments of the runs before it.
    std::size_t first = 0;
    for (std::size_t i = 0; i < run; ++i) first += queue.run(i).segments;
    if (r.kind == MotionPrimitive::Kind::Dwell || first >= queue.size()) return;
    if (queue.segment(first).per_axis) {
      const QueuedSegment& seg = queue.segment(first);
      if (!rapidAheadFor(seg)) {
        rapid_ahead_ = AxisRapid::make(seg.path.from(), seg.path.to(), limits_);
        rapid_ahead_ready_ = true;
      }
      return;  // it ends at rest: nothing after it depends on it
    }
    const PieceInputs in = pieceInputs(queue, run, piece_start, v0, closed);
    if (!(slot.ready && in.sameAs(slot.inputs))) slot = {true, in, planPiece(in)};
    // The piece after it (a piece that ends at rest hands over from rest: v = 0 either way).
    if (slot.plan.ends_run) {
      ++run;
      piece_start = 0.0;
    } else {
      piece_start = slot.plan.piece_end;
    }
    v0 = slot.plan.profile.v_end;
  }
}

void Interpolator::passFinishedSegments(LookAhead& queue, double s, SetpointInfo& info) {
  const Run& run = queue.frontRun();
  while (run.segments > 1) {
    const QueuedSegment& seg = queue.frontSegment();
    if (s <= seg.run_offset + seg.path.length()) break;
    position_ = seg.path.to();
    queue.popSegment();
    ++info.segments_finished;
  }
}

Commitment Interpolator::commitForReplan(const LookAhead& queue, double old_limit,
                                         double new_limit) {
  if (!running_) return {piece_start_, resync_ ? 0.0 : exit_velocity_};
  const Run& run = queue.run(0);
  // Local time of the next tick.
  const double next = static_cast<double>(last_tick_ + 1 - start_tick_) * cycle_ - phase_;
  if (per_axis_) {
    // A non-linear G00 re-plans its own axis profiles (a live rapid override, feed hold: a
    // limit of 0); it ends at rest on its run's end either way.
    if (new_limit != old_limit) {
      rapid_.replan(next, limits_, !(new_limit > 0.0));
      duration_ = rapid_.duration();
      ++pieces_changed_;
    }
    return {run.length, 0.0};
  }
  if (run.kind == MotionPrimitive::Kind::Dwell) return {run.length, 0.0};
  SCurveProfile& p = profile_;
  // Its speed limit stays (a rapid under a feed override, a G63 tap): it runs on as planned.
  if (new_limit == old_limit) return {piece_end_, p.v_end};
  // A ramp up under way ends early when the new limit is below its peak, so that it does not
  // first run up to a speed it must brake from (a feed hold pressed while a G00 accelerates
  // would otherwise travel on to top speed); a cruise is cut.
  if (!cutProfile(p, next, new_limit)) return {piece_end_, p.v_end};  // braking: runs on
  duration_ = p.duration;
  piece_end_ = piece_start_ + p.length;
  piece_ends_run_ = false;
  ++pieces_changed_;
  return {piece_end_, p.v_peak};
}

bool Interpolator::setpoint(uint64_t k, LookAhead& queue, bool closed, AxisValues& out,
                            SetpointInfo& info) {
  info = SetpointInfo{};
  last_tick_ = k;
  // Bounded: every iteration finishes a segment or a piece; pieces cover at least one
  // cycle of travel unless they end a run.
  for (std::size_t guard = 2 * queue.size() + 4; guard > 0 && !queue.empty(); --guard) {
    if (!running_ && resync_ && queue.held()) {
      // Feed hold, at rest: stand where the path stopped (run offset piece_start_) until it is
      // released.
      passFinishedSegments(queue, piece_start_, info);
      const QueuedSegment& seg = queue.frontSegment();
      seg.path.position(piece_start_ - seg.run_offset, out);
      info.kind = queue.frontRun().kind;
      info.where = seg.where;
      return true;
    }
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
    passFinishedSegments(queue, s, info);
    // How far the path is in the run (a non-linear rapid: its share of the time; the
    // division only there, the tick's common case is a line or an arc).
    queue.setFrontProgress(
        !per_axis_ ? s
                   : run.length * (duration_ > 0.0 ? std::clamp(tau / duration_, 0.0, 1.0) : 1.0));
    if (per_axis_ && !piece_done) {
      rapid_.position(tau, out);
      const AxisRapidMotion motion = rapid_.pathMotion(tau);
      info.velocity = motion.velocity;
      info.acceleration = motion.acceleration;
      info.jerk = motion.jerk;
      info.kind = run.kind;
      info.where = queue.frontSegment().where;
      // Standing under a feed hold, like a held line; else moving.
      info.idle = queue.held() && motion.velocity == 0.0;
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
      info.lookahead_limited = piece_lookahead_limited_;
      return true;
    }
    // The piece ended before this tick: move the clock to its end and continue.
    running_ = false;
    ++pieces_changed_;
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
  ++pieces_changed_;
  out = position_;
  return false;
}

}  // namespace ncc::vm::motion
