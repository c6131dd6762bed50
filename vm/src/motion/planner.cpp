#include "ncc/vm/motion/planner.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ncc/vm/motion/corner_blend.h"

namespace ncc::vm::motion {

MotionPlanner::MotionPlanner(const MachineConfig& machine, std::size_t window_capacity)
    : limits_(AxisLimits::from(machine)),
      rapid_limits_(limits_),
      queue_(std::max<std::size_t>(window_capacity, 2 * ContinuousPath::kSlotsPerMove),
             WindowReach::of(limits_)),
      path_(limits_, queue_),
      interpolator_(machine.start_position, rapid_limits_) {
  CornerBlend::prepareTables();  // at load, not in the first tick that blends a corner
}

void MotionPlanner::setOverrides(double feed, double rapid, double max_feed) {
  const double live = std::isfinite(feed) ? std::clamp(feed, kMinFeedOverride, kMaxFeedOverride) : 1.0;
  const double top =
      std::isfinite(max_feed) ? std::clamp(max_feed, kMinFeedOverride, kMaxFeedOverride) : live;
  feed_override_ = std::max(live, top);
  SpeedScales scales = queue_.scales();
  scales.feed = live / feed_override_;
  scales.rapid = std::isfinite(rapid) ? rapidOverrideWithin(rapid) : 1.0;
  changeScales(scales);
}

void MotionPlanner::setFeedOverride(double feed) {
  if (!std::isfinite(feed)) return;
  SpeedScales scales = queue_.scales();
  scales.feed = feedOverrideWithin(feed) / feed_override_;
  changeScales(scales);
}

void MotionPlanner::setRapidOverride(double rapid) {
  if (!std::isfinite(rapid)) return;
  SpeedScales scales = queue_.scales();
  scales.rapid = rapidOverrideWithin(rapid);
  changeScales(scales);
}

void MotionPlanner::setFeedHold(bool held) {
  SpeedScales scales = queue_.scales();
  scales.held = held;
  changeScales(scales);
}

void MotionPlanner::changeScales(const SpeedScales& scales) {
  if (scales.rapid != queue_.scales().rapid) {
    for (int i = 0; i < limits_.count; ++i)
      rapid_limits_.rapid_velocity[i] = scales.rapid * limits_.rapid_velocity[i];
    interpolator_.rapidLimitsChanged();
  }
  if (scales == queue_.scales()) return;
  queue_.setScales(scales, commitFor(scales));
}

Commitment MotionPlanner::commitFor(const SpeedScales& scales) {
  if (queue_.empty()) return interpolator_.commitForReplan(queue_, 0.0, 0.0);
  return interpolator_.commitForReplan(queue_, queue_.velocity(0), queue_.velocityWith(0, scales));
}

bool MotionPlanner::push(const MotionPrimitive& m) {
  if (spindle_alarm_) return true;  // input ends at the alarm
  if (!hasRoom()) return false;
  // One backward pass for the segments this move queues (lookahead.h).
  const DeferredBackwardPass pass(queue_);
  const int n = limits_.count;
  const bool per_rev = (m.kind == MotionPrimitive::Kind::Dwell && m.revolutions) ||
                       ((m.kind == MotionPrimitive::Kind::Line || m.kind == MotionPrimitive::Kind::Arc) &&
                        m.feed_per_rev);
  if (per_rev && (!(spindle_rpm_ > 0.0) || spindle_stopped_)) {
    spindle_alarm_ = true;
    spindle_alarm_where_ = m.where;
    endOfProgram();
    return true;
  }
  if (m.kind == MotionPrimitive::Kind::Dwell) {
    path_.flush(true);
    QueuedSegment seg;
    seg.where = m.where;
    seg.path = PathSegment::dwell(m.from, n);
    const double rev_per_s = spindle_rpm_ / 60.0;
    const double seconds = m.revolutions ? m.seconds / rev_per_s : m.seconds;
    queue_.stopAfterLast();
    queue_.push(seg, m.kind, SegmentLimits{}, 0.0, true, std::max(seconds, 0.0));
    return true;
  }
  if (m.kind == MotionPrimitive::Kind::Rapid) {
    pushRapid(m);
    return true;
  }
  // G63 (tapping without an encoder): the tap's pitch is F / S, so the feed runs at 100 %.
  const double override = m.fixed_override ? 1.0 : feed_override_;
  const double feed = std::max(
      (m.feed_per_rev ? m.feed * spindle_rpm_ / 60.0 : m.feed / 60.0) * override, kMinPathVelocity);
  // What a live feed override scales (setFeedOverride): not G63.
  const double feed_limit = m.fixed_override ? std::numeric_limits<double>::infinity() : feed;
  const PathSegment programmed =
      m.kind == MotionPrimitive::Kind::Line
          ? PathSegment::line(m.from, m.to, n)
          : PathSegment::arc(m.from, m.to, n, m.axis1, m.axis2, m.center[m.axis1],
                             m.center[m.axis2], m.cw, m.extra_turns);
  // A move that does not move counts only for its exact stop.
  if (!path_.move(programmed, feed, feed_limit, m.exact_stop, m.where) && m.exact_stop) stop();
  return true;
}

void MotionPlanner::pushRapid(const MotionPrimitive& m) {
  QueuedSegment seg;  // the feed override does not scale it: feed_limit stays infinite
  seg.where = m.where;
  seg.exact_stop = m.exact_stop;
  seg.path = PathSegment::line(m.from, m.to, limits_.count);
  const bool moves = seg.path.length() > 0.0;
  // The held move ends at rest before a rapid that moves.
  path_.flush(moves);
  if (!moves) {  // nothing moves: only its exact stop counts
    if (m.exact_stop) stop();
    return;
  }
  // Planned at the axes' full rapid speeds; the rapid override scales them (SpeedScales).
  // Non-linear positioning, and a linear one with exact stop that starts from rest, is at
  // rest at both ends; any other linear one is queued before its end is known (a G00 may
  // follow it moving, at a kink).
  const bool per_axis = m.per_axis && AxisRapid::possible(m.from, m.to, limits_);
  const bool joins_moving = path_.joinsMoving(m.kind);
  const SegmentLimits limits =
      segmentLimits(seg.path, limits_, true, 0.0, {},
                    smoothJerkShare(per_axis || (m.exact_stop && !joins_moving), true));
  if (per_axis) {
    // Non-linear positioning: its own piece, from rest to rest (interpolator.h).
    seg.per_axis = true;
    queue_.stopAfterLast();
    queue_.push(seg, m.kind, limits, 0.0, true, 0.0);
    return;
  }
  SegmentLimits linear = limits;
  linear.velocity = std::max(linear.velocity, kMinPathVelocity);
  const QueuedSegment* prev = queue_.lastSegment();
  const double vertex = prev != nullptr ? junctionVelocity(prev->path, seg.path, limits_) : 0.0;
  if (prev != nullptr && joins_moving) {
    // A kink passed while moving: room for its velocity step, as for feed moves (a chain of
    // rapids turning by 4e-5 rad shared a run and took 1.0245x the acceleration limit).
    AxisValues before, after;
    prev->path.tangent(prev->path.length(), before);
    seg.path.tangent(0.0, after);
    linear.acceleration = std::min(
        linear.acceleration,
        kinkAccelerationLimit(before, after, std::min(prev->path.length(), seg.path.length()),
                              std::min(vertex, linear.velocity), limits_));
  }
  path_.enqueue(seg, m.kind, linear, vertex, m.exact_stop);
}

bool MotionPlanner::accept(const Event& event) {
  if (event.kind == Event::Kind::Motion) return push(event.motion);
  switch (event.machine.kind) {
    case MachineEvent::Kind::SpindleSpeed:
      spindle_rpm_ = event.machine.value;
      break;
    case MachineEvent::Kind::SpindleCW:
    case MachineEvent::Kind::SpindleCCW:
      spindle_stopped_ = false;
      break;
    case MachineEvent::Kind::SpindleStop:
      spindle_stopped_ = true;
      break;
    case MachineEvent::Kind::ProgramStop:
    case MachineEvent::Kind::OptionalStop:
    case MachineEvent::Kind::ProgramEnd:
    case MachineEvent::Kind::ProgramEndRewind:
      if (!hasRoom()) return false;
      stop();
      break;
    default:
      break;
  }
  return true;
}

void MotionPlanner::stop() {
  path_.flush(true);
  queue_.stopAfterLast();
}

void MotionPlanner::endOfProgram() {
  ended_ = true;
  if (queue_.room() > 0) path_.flush(true);  // else on a later tick, when there is room
}

bool MotionPlanner::closeInput() {
  if (ended_ && path_.holding() && queue_.room() > 0) path_.flush(true);
  return ended_ && !path_.holding();
}

void MotionPlanner::planAhead() {
  interpolator_.planNextPiece(queue_, closeInput());
  queue_.prefetchFront(kSegmentsWarmed);
}

bool MotionPlanner::setpoint(uint64_t k, AxisValues& out, SetpointInfo& info) {
  const bool closed = closeInput();
  if (interpolator_.setpoint(k, queue_, closed, out, info)) return true;
  return !closed;
}

}  // namespace ncc::vm::motion
