#include "ncc/vm/motion/lookahead.h"

#include <algorithm>
#include <cmath>

#include "ncc/vm/motion/scurve.h"

namespace ncc::vm::motion {
namespace {

// Junction velocities and limits this close count as equal (rounding): a segment whose
// limits are this little below its run's joins without lowering them.
constexpr double kSameLimit = 1e-9;
// Limits this close join one run, which takes the lower of each. Along a chain of tiny
// segments passed as kinks the direction changes a little at every vertex, and with it each
// line's limits (A_i / |t_i| for an axis at 45 degrees moves by 1 % over a 0.01 rad turn;
// along a gentle wave by 1e-9 per vertex): split at every such step, a 10 um chain became
// runs of 0.2 mm, each ending at a = 0, braking through them took far longer than through one
// run, and the path crawled at half its feed.
constexpr double kJoinBand = 0.01;

bool close(double a, double b) { return std::abs(a - b) <= kJoinBand * std::max(a, b); }

// Whether `run` and a segment of `length` with `limits` are so short that a run boundary
// between them (a = 0 there) would cost more than running both at the lower limits: within
// their joint length, a profile with a = 0 at both ends could not gain more than
// kShortRunGain of the lower velocity limit. Short segments of different limits (a CAM feed
// that changes every 10 um, a chain whose curvature steps fast) otherwise make runs too short
// to accelerate in: alternating F5000 / F5100 on 10 um crawled at 15 mm/s.
constexpr double kShortRunGain = 0.1;
constexpr double kShortRunSpeedRatio = 0.8;
constexpr double kFasterTailShare = 1.0;
bool tooShortToSplit(const Run& run, const SegmentLimits& limits, double length) {
  const double v_lo = std::min(run.limits.velocity, limits.velocity);
  const double a = std::min(run.limits.acceleration, limits.acceleration);
  const double j = std::min(run.limits.jerk, limits.jerk);
  if (!(a > 0.0 && j > 0.0 && v_lo > 0.0)) return false;
  // Only near speeds: a short slow segment joined to fast ones slows them all (the corpus
  // program bear took 0.46 % longer than with no such joins; with this bound 0.07 % less).
  // A faster segment leaves the run's speed as it is and slows nobody but itself: it joins
  // whatever its speed while the faster segments at the run's end stay within
  // kFasterTailShare of the rest (bows among slower ones, where bowShape's two bounds
  // alternate), not beyond (a feed step up, whose fast stretch would crawl at the slow speed,
  // more so under a low feed override).
  const bool faster = limits.velocity > run.limits.velocity &&
                      run.faster_tail + length <= kFasterTailShare * (run.length - run.faster_tail);
  if (!faster && v_lo < kShortRunSpeedRatio * std::max(run.limits.velocity, limits.velocity))
    return false;
  return reachableGain(v_lo, run.length + length, a, j) <= kShortRunGain * v_lo;
}

// `limit` is below `run_limit` by more than rounding.
bool below(double limit, double run_limit) { return limit < (1.0 - kSameLimit) * run_limit; }

// `run` with a segment of `limits` and `feed_limit` joined that lowers them: the lowest of
// each, and a junction limit no higher than its speed limit.
void lowerTo(Run& run, const SegmentLimits& limits, double feed_limit) {
  run.limits.velocity = std::min(run.limits.velocity, limits.velocity);
  run.limits.acceleration = std::min(run.limits.acceleration, limits.acceleration);
  run.limits.jerk = std::min(run.limits.jerk, limits.jerk);
  run.feed_limit = std::min(run.feed_limit, feed_limit);
  run.entry_limit = std::min(run.entry_limit, run.limits.velocity);
}

// A feed move the feed override does not scale: G63 tapping.
bool isTap(const Run& run) {
  return run.kind != MotionPrimitive::Kind::Rapid && !std::isfinite(run.feed_limit);
}

}  // namespace

LookAhead::LookAhead(std::size_t capacity, const WindowReach& reach)
    : segments_(std::max<std::size_t>(capacity, 2)),
      runs_(std::max<std::size_t>(capacity, 2)),
      reach_machine_(reach) {}

const QueuedSegment* LookAhead::lastSegment() const {
  return segment_count_ == 0 ? nullptr : &segmentAt(segment_count_ - 1);
}

bool LookAhead::lowersLast(const QueuedSegment& segment, const SegmentLimits& limits) const {
  const Run& last = runAt(run_count_ - 1);
  return below(limits.velocity, last.limits.velocity) ||
         below(limits.acceleration, last.limits.acceleration) ||
         below(limits.jerk, last.limits.jerk) || segment.feed_limit < last.feed_limit;
}

bool LookAhead::joinsLast(const QueuedSegment& segment, MotionPrimitive::Kind kind,
                          const SegmentLimits& limits, double entry_limit) {
  const Run& last = runAt(run_count_ - 1);
  const double length = segment.path.length();
  if (last.kind != kind || last.stop_after || last.segments == 0) return false;
  // The junction must not bind.
  if (entry_limit < (1.0 - kSameLimit) * std::min(limits.velocity, last.limits.velocity))
    return false;
  // A G63 tap (the feed override does not scale it) never shares a run with a move it
  // scales. Scaled moves of different F do (their limits are equal: the axes cap both); the
  // run takes the lower F under the knob.
  if (std::isfinite(segment.feed_limit) != std::isfinite(last.feed_limit)) return false;
  const bool near = (close(limits.velocity, last.limits.velocity) &&
                     close(limits.acceleration, last.limits.acceleration) &&
                     close(limits.jerk, last.limits.jerk)) ||
                    tooShortToSplit(last, limits, length);
  if (!near) return false;
  if (!lowersLast(segment, limits)) return true;
  // Lowering the run's limits must not touch what the motion under way is committed to. A
  // piece running in it was planned with them: never while it is the front run and started.
  if (run_count_ == 1 && front_started_) return false;
  // Its planned entry (the exit a piece under way in the run before it may be committed to)
  // must stay within its new speed limit under the live scales, and a stop from there must
  // still fit within it: then the backward pass gives it no lower entry, and no earlier entry
  // changes.
  Run lowered = last;
  lowerTo(lowered, limits, segment.feed_limit);
  if (pass_pending_) backwardPass();  // the planned entry, as if no pass had been deferred
  const double entry = last.entry_planned;
  return entry <= speedLimit(lowered, scales_) &&
         reachableVelocity(0.0, last.length + length, lowered.limits.acceleration,
                           lowered.limits.jerk) >= entry;
}

void LookAhead::push(const QueuedSegment& segment, MotionPrimitive::Kind kind,
                     const SegmentLimits& limits, double entry_limit, bool stop_after,
                     double dwell_seconds) {
  if (full()) return;
  const double length = segment.path.length();
  if (segment_count_ > 0) queued_length_ += length;
  const bool dwell = kind == MotionPrimitive::Kind::Dwell;
  Run* last = run_count_ > 0 ? &runAt(run_count_ - 1) : nullptr;
  const bool join = last != nullptr && !dwell && joinsLast(segment, kind, limits, entry_limit);
  // A run that starts from rest cuts the window before it.
  if (!join && last != nullptr && !(entry_limit > 0.0)) cutWindowAfter(run_count_ - 1);
  QueuedSegment& slot = segmentAt(segment_count_);
  slot = segment;
  ++segment_count_;
  if (join) {
    slot.run_offset = last->length;
    last->length += length;
    ++last->segments;
    last->stop_after = stop_after;
    last->faster_tail = limits.velocity > last->limits.velocity ? last->faster_tail + length : 0.0;
    // Limits below the run's by rounding only leave it as it is (kSameLimit).
    if (lowersLast(segment, limits)) lowerTo(*last, limits, segment.feed_limit);
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
  // The window's tail (wantsMore). (A join never continues a run that ends at rest:
  // joinsLast.)
  tail_.length += length;
  if (!dwell) tail_.extremes.add(runAt(run_count_ - 1).limits);
  if (stop_after) cutWindowAfter(run_count_ - 1);
  stale_from_ = std::min(stale_from_, run_count_ - 1);  // the run pushed to
  pass_pending_ = true;
  if (!defer_pass_) backwardPass();
  ++version_;
  ++runs_changed_;
}

void LookAhead::runDeferredBackwardPass() {
  defer_pass_ = false;
  if (pass_pending_) backwardPass();
}

void LookAhead::stopAfterLast() {
  // Its exit is already 0 (it ends the window); later pushes read the flag.
  if (run_count_ > 0) {
    runAt(run_count_ - 1).stop_after = true;
    cutWindowAfter(run_count_ - 1);
  }
  ++version_;
  ++runs_changed_;
}

double LookAhead::velocity(std::size_t i) const { return velocityWith(i, scales_); }

double LookAhead::velocityWith(std::size_t i, const SpeedScales& scales) const {
  return speedLimit(runAt(i), scales);
}

double LookAhead::speedLimit(const Run& run, const SpeedScales& scales) {
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
  // The floor keeps a tiny override from stopping the path; it never lifts a run above its
  // own limit (a tiny arc's curvature cap).
  return std::max(std::min(run.limits.velocity, run.feed_limit * scales.feed),
                  std::min(kMinPathVelocity, run.limits.velocity));
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
    // The speed reachable over the run is at least its exit (reachableGain() >= 0): a limit
    // no higher than that binds without solving for it (a cube root; runs at the same speed,
    // as along a chain).
    const double limit = entryLimit(i);
    const double entry = std::max(
        run.entry_floor,
        limit <= exit ? limit
                      : std::min(limit, reachableVelocity(exit, run.length,
                                                          run.limits.acceleration,
                                                          run.limits.jerk)));
    // A run not pushed to since the last pass whose entry stays: earlier runs are unchanged.
    if (!full && i < stale_from_ && entry == run.entry_planned) break;
    run.entry_planned = entry;
    exit = entry;
  }
  stale_from_ = run_count_;
  pass_pending_ = false;
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
  ++runs_changed_;
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
  seg_head_ = wrap(seg_head_ + 1, segments_.size());
  --segment_count_;
  ++segments_popped_;
  ++version_;
  if (segment_count_ > 0) queued_length_ -= segmentAt(0).path.length();
  if (segment_count_ <= 1) queued_length_ = 0.0;  // no drift from the running sum
  if (run_count_ > 0 && runAt(0).segments > 0) --runAt(0).segments;
}

void LookAhead::popRun() {
  if (run_count_ == 0) return;
  const Run& front = runAt(0);
  if (front.window_cut) {
    // (If it was the last cut, every queued run is now the tail, which tail_ already holds.)
    --tail_.cuts;
  } else if (tail_.cuts == 0) {  // a run of the tail leaves
    const QueuedExtremes& q = tail_.extremes;
    const SegmentLimits& l = front.limits;
    if (tail_stale_pops_ > 0 ||
        (front.kind != MotionPrimitive::Kind::Dwell &&
         (l.velocity >= q.velocity || l.acceleration <= q.acceleration || l.jerk <= q.jerk)))
      ++tail_stale_pops_;
  }
  run_head_ = wrap(run_head_ + 1, runs_.size());
  ++runs_popped_;
  front_progress_ = 0.0;
  --run_count_;
  front_started_ = false;
  ++version_;
  ++runs_changed_;
}

}  // namespace ncc::vm::motion
