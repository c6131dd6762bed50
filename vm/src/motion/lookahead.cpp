#include "ncc/vm/motion/lookahead.h"

#include <algorithm>
#include <cmath>

#include "ncc/vm/motion/scurve.h"

namespace ncc::vm::motion {
namespace {

// Limits this close count as equal for joining a run (direction rounding in long chains).
constexpr double kSameLimit = 1e-9;

bool close(double a, double b) { return std::abs(a - b) <= kSameLimit * std::max(a, b); }

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
                    close(limits.jerk, last->limits.jerk);
  QueuedSegment& slot = segmentAt(segment_count_);
  slot = segment;
  ++segment_count_;
  if (join) {
    slot.run_offset = last->length;
    last->length += length;
    ++last->segments;
    last->stop_after = stop_after;
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

void LookAhead::backwardPass() {
  const std::size_t first = front_started_ ? 1 : 0;
  double exit = 0.0;  // the window ends at rest
  for (std::size_t i = run_count_; i-- > first;) {
    Run& run = runAt(i);
    if (run.stop_after) exit = 0.0;
    const double entry = std::min(
        run.entry_limit, reachableVelocity(exit, run.length, run.limits.acceleration, run.limits.jerk));
    if (i + 1 < run_count_ && entry == run.entry_planned) break;  // earlier runs unchanged
    run.entry_planned = entry;
    exit = entry;
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
