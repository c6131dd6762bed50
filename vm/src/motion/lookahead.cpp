#include "ncc/vm/motion/lookahead.h"

#include <algorithm>
#include <cmath>

#include "ncc/vm/motion/scurve.h"

namespace ncc::vm::motion {
namespace {

// Limits this close count as equal for joining a run (direction rounding in long chains).
constexpr double kSameLimit = 1e-9;

bool close(double a, double b) { return std::abs(a - b) <= kSameLimit * std::max(a, b); }

// A feed move the feed override does not scale: G63 tapping.
bool isTap(const Run& run) {
  return run.kind != MotionPrimitive::Kind::Rapid && !std::isfinite(run.feed_limit);
}

}  // namespace

LookAhead::LookAhead(std::size_t capacity, double window_length)
    : segments_(std::max<std::size_t>(capacity, 2)),
      runs_(std::max<std::size_t>(capacity, 2)),
      window_length_(window_length) {}

const QueuedSegment* LookAhead::lastSegment() const {
  return segment_count_ == 0 ? nullptr : &segmentAt(segment_count_ - 1);
}

void LookAhead::push(const QueuedSegment& segment, MotionPrimitive::Kind kind,
                     const SegmentLimits& limits, double entry_limit, bool stop_after,
                     double dwell_seconds) {
  if (full()) return;
  const double length = segment.path.length();
  if (segment_count_ > 0) queued_length_ += length;
  const bool dwell = kind == MotionPrimitive::Kind::Dwell;
  Run* last = run_count_ > 0 ? &runAt(run_count_ - 1) : nullptr;
  const bool join = last != nullptr && !dwell && last->kind == kind && !last->stop_after &&
                    last->segments > 0 &&
                    entry_limit >= (1.0 - kSameLimit) * std::min(limits.velocity, last->limits.velocity) &&
                    close(limits.velocity, last->limits.velocity) &&
                    close(limits.acceleration, last->limits.acceleration) &&
                    close(limits.jerk, last->limits.jerk) &&
                    // A G63 tap (the feed override does not scale it) never shares a run
                    // with a move it scales. Scaled moves of different F do (their limits are
                    // equal: the axes cap both); the run takes the lower F under the knob.
                    std::isfinite(segment.feed_limit) == std::isfinite(last->feed_limit);
  QueuedSegment& slot = segmentAt(segment_count_);
  slot = segment;
  ++segment_count_;
  if (join) {
    slot.run_offset = last->length;
    last->length += length;
    ++last->segments;
    last->stop_after = stop_after;
    last->feed_limit = std::min(last->feed_limit, segment.feed_limit);
  } else {
    Run& run = runAt(run_count_);
    run = Run{};
    run.limits = limits;
    run.kind = kind;
    run.length = length;
    run.segments = 1;
    run.dwell_seconds = dwell_seconds;
    run.entry_limit = entry_limit;
    run.stop_after = stop_after;
    run.feed_limit = segment.feed_limit;
    ++run_count_;
    slot.run_offset = 0.0;
  }
  backwardPass();
  ++version_;
}

void LookAhead::stopAfterLast() {
  // Its exit is already 0 (it ends the window); later pushes read the flag.
  if (run_count_ > 0) runAt(run_count_ - 1).stop_after = true;
  ++version_;
}

double LookAhead::velocity(std::size_t i) const { return velocityWith(i, scales_); }

double LookAhead::velocityWith(std::size_t i, const SpeedScales& scales) const {
  const Run& run = runAt(i);
  // Feed hold stops everything but a G63 tap, which must not stop mid-thread while the
  // spindle turns (Mazak G63: no feed hold; Siemens ISO G63: a block stop); the hold acts
  // after it.
  if (scales.held && !isTap(run)) return 0.0;
  if (run.kind == MotionPrimitive::Kind::Rapid) {
    // A rapid's limits are a line's: only its speed depends on the rapid override.
    if (scales.rapid == 1.0) return run.limits.velocity;
    return std::max(run.limits.velocity * scales.rapid, kMinPathVelocity);
  }
  if (scales.feed == 1.0) return run.limits.velocity;
  return std::max(std::min(run.limits.velocity, run.feed_limit * scales.feed), kMinPathVelocity);
}

double LookAhead::entryLimit(std::size_t i) const {
  const Run& run = runAt(i);
  if (scales_ == SpeedScales{}) return run.entry_limit;
  double limit = std::min(run.entry_limit, velocity(i));
  if (i > 0) limit = std::min(limit, velocity(i - 1));
  return limit;
}

void LookAhead::backwardPass(bool full) {
  const std::size_t first = front_started_ ? 1 : 0;
  double exit = 0.0;  // the window ends at rest
  for (std::size_t i = run_count_; i-- > first;) {
    Run& run = runAt(i);
    if (run.stop_after) exit = 0.0;
    const double entry = std::max(
        run.entry_floor,
        std::min(entryLimit(i),
                 reachableVelocity(exit, run.length, run.limits.acceleration, run.limits.jerk)));
    if (!full && i + 1 < run_count_ && entry == run.entry_planned) break;  // earlier runs unchanged
    run.entry_planned = entry;
    exit = entry;
  }
}

void LookAhead::setScales(const SpeedScales& scales, const Commitment& committed) {
  scales_ = scales;
  replan(committed);
}

void LookAhead::replan(const Commitment& committed) {
  for (std::size_t i = 0; i < run_count_; ++i) {
    Run& run = runAt(i);
    run.entry_floor = 0.0;
    run.entry_before = run.entry_planned;
  }
  backwardPass(true);
  ++version_;
  if (run_count_ == 0) return;
  // From the committed state on, brake as hard as the limits allow: where that cannot reach a
  // junction's new entry, the entry is raised to what it can reach. The previous plan got
  // from the same state to each of those junctions at no less than that (with the same
  // acceleration and jerk), so a floor never exceeds the previous entry. Computed forwards,
  // braking through many short runs is ill-conditioned (each run's error grows in the next),
  // so each floor is capped at the previous entry: from there the previous plan, made
  // backwards, is exactly feasible.
  // (The front run's own entry needs none: the interpolator starts it from the actual speed.)
  double v = committed.velocity;
  double rest = runAt(0).length - committed.offset;
  for (std::size_t i = 0; i + 1 < run_count_ && v > 0.0; ++i) {
    const Run& run = runAt(i);
    Run& next = runAt(i + 1);
    const double floor =
        run.stop_after ? 0.0
                       : std::min(next.entry_before,
                                  lowestReachableVelocity(v, std::max(rest, 0.0),
                                                          run.limits.acceleration, run.limits.jerk));
    if (!(floor > next.entry_planned)) break;  // the new plan is reachable from here on
    next.entry_floor = floor;
    next.entry_planned = floor;
    v = floor;
    rest = next.length;
  }
}

double LookAhead::runExit(std::size_t i) const {
  if (i + 1 >= run_count_ || runAt(i).stop_after) return 0.0;
  return runAt(i + 1).entry_planned;
}

void LookAhead::prefetchFront(std::size_t count) {
  constexpr std::size_t kCacheLine = 64;
  const uint64_t end = segments_popped_ + std::min(count, segment_count_);
  const uint64_t from = std::max(prefetched_until_, segments_popped_);
  prefetched_until_ = std::max(prefetched_until_, end);
  for (std::size_t i = from - segments_popped_; i < end - segments_popped_; ++i) {
    const char* bytes = reinterpret_cast<const char*>(&segmentAt(i));
    for (std::size_t b = 0; b < sizeof(QueuedSegment); b += kCacheLine) __builtin_prefetch(bytes + b);
  }
}

void LookAhead::popSegment() {
  if (segment_count_ == 0) return;
  seg_head_ = (seg_head_ + 1) % segments_.size();
  --segment_count_;
  ++segments_popped_;
  ++version_;
  if (segment_count_ > 0) queued_length_ -= segmentAt(0).path.length();
  if (segment_count_ <= 1) queued_length_ = 0.0;  // no drift from the running sum
  if (run_count_ > 0 && runAt(0).segments > 0) --runAt(0).segments;
}

void LookAhead::popRun() {
  if (run_count_ == 0) return;
  run_head_ = (run_head_ + 1) % runs_.size();
  --run_count_;
  front_started_ = false;
  ++version_;
}

}  // namespace ncc::vm::motion
