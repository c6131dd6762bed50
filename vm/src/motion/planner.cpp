#include "ncc/vm/motion/planner.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncc::vm::motion {
namespace {

// Slowest path speed a feed move is planned with (F0, or G95 with the spindle stopped): a
// zero speed would never end. 1 mm/min.
constexpr double kMinFeed = 1.0 / 60.0;

bool isFeed(MotionPrimitive::Kind k) {
  return k == MotionPrimitive::Kind::Line || k == MotionPrimitive::Kind::Arc;
}

}  // namespace

double windowLength(const AxisLimits& l) {
  double v = 0.0, a = std::numeric_limits<double>::infinity(), j = a;
  double sum = 0.0;
  for (int i = 0; i < l.count; ++i) {
    const double top = std::max(l.rapid_velocity[i], l.feed_velocity[i]);
    sum += top * top;
    a = std::min(a, l.acceleration[i]);
    j = std::min(j, l.jerk[i]);
  }
  v = std::sqrt(sum);
  if (l.count == 0 || v == 0.0) return 0.0;
  // An open run accelerates to top speed and must still be able to brake: twice the braking
  // distance, plus a few cycles of travel so the interpolator's pieces stay long.
  return 2.0 * rampDistance(0.0, v, a, kSmoothJerkShare * j) + 4.0 * v * l.ipo_cycle;
}

MotionPlanner::MotionPlanner(const MachineConfig& machine, std::size_t window_capacity)
    : limits_(AxisLimits::from(machine)),
      queue_(window_capacity, windowLength(limits_)),
      interpolator_(machine.start_position, machine.ipo_cycle_seconds) {}

bool MotionPlanner::push(const MotionPrimitive& m) {
  if (queue_.full()) return false;
  const int n = limits_.count;
  QueuedSegment seg;
  seg.where = m.where;
  if (m.kind == MotionPrimitive::Kind::Dwell) {
    seg.path = PathSegment::dwell(m.from, n);
    const double rev_per_s = spindle_rpm_ / 60.0;
    double seconds = m.revolutions ? (rev_per_s > 0.0 ? m.seconds / rev_per_s : 0.0) : m.seconds;
    queue_.stopAfterLast();
    queue_.push(seg, m.kind, SegmentLimits{}, 0.0, true, std::max(seconds, 0.0));
    return true;
  }
  if (m.kind == MotionPrimitive::Kind::Arc) {
    seg.path = PathSegment::arc(m.from, m.to, n, m.axis1, m.axis2, m.center[m.axis1],
                                m.center[m.axis2], m.cw, m.extra_turns);
  } else {
    seg.path = PathSegment::line(m.from, m.to, n);
  }
  if (!(seg.path.length() > 0.0)) {  // nothing moves: only its exact stop counts
    if (m.exact_stop) stop();
    return true;
  }
  const bool rapid = m.kind == MotionPrimitive::Kind::Rapid;
  double feed = m.feed_per_rev ? m.feed * spindle_rpm_ / 60.0 : m.feed / 60.0;
  if (!rapid) feed = std::max(feed, kMinFeed);
  SegmentLimits limits = segmentLimits(seg.path, limits_, rapid, feed);
  limits.velocity = std::max(limits.velocity, kMinFeed);

  // Junction with the previous queued segment (none queued: it ended at rest).
  double entry_limit = 0.0;
  const QueuedSegment* prev = queue_.lastSegment();
  if (prev != nullptr && !queue_.lastStops() && queue_.lastKind() != MotionPrimitive::Kind::Dwell &&
      isFeed(queue_.lastKind()) == isFeed(m.kind)) {
    entry_limit = std::min({queue_.lastLimits().velocity, limits.velocity,
                            junctionVelocity(prev->path, seg.path, limits_)});
  }
  queue_.push(seg, m.kind, limits, entry_limit, m.exact_stop, 0.0);
  return true;
}

bool MotionPlanner::accept(const Event& event) {
  if (event.kind == Event::Kind::Motion) return push(event.motion);
  switch (event.machine.kind) {
    case MachineEvent::Kind::SpindleSpeed:
      spindle_rpm_ = event.machine.value;
      break;
    case MachineEvent::Kind::ProgramStop:
    case MachineEvent::Kind::OptionalStop:
    case MachineEvent::Kind::ProgramEnd:
    case MachineEvent::Kind::ProgramEndRewind:
      stop();
      break;
    default:
      break;
  }
  return true;
}

void MotionPlanner::stop() { queue_.stopAfterLast(); }

bool MotionPlanner::setpoint(uint64_t k, AxisValues& out, SetpointInfo& info) {
  if (interpolator_.setpoint(k, queue_, ended_, out, info)) return true;
  return !ended_;
}

}  // namespace ncc::vm::motion
