// LookAhead's window (docs/planner.md, "Window by braking distance"): how much input it wants
// queued before more could not change the plan of the runs about to start.
#include <algorithm>

#include "ncc/vm/motion/lookahead.h"

namespace ncc::vm::motion {

void LookAhead::QueuedExtremes::add(const SegmentLimits& l) {
  velocity = std::max(velocity, l.velocity);
  acceleration = std::min(acceleration, l.acceleration);
  jerk = std::min(jerk, l.jerk);
}

bool LookAhead::wantsMore() const {
  if (full()) return false;
  // Between changes of the runs (a push, a run's end, a re-plan), only the path's progress
  // moves.
  if (window_.version != runs_changed_) window_ = windowNeeds();
  if (window_.always) return true;
  // After a cut, the path ahead counts from where the path is, so that the tail fills as the
  // path comes nearer to it, at the path's pace, not all at once when the cut is queued (a
  // long rapid before a chain). Without one, from the running segment's end.
  double ahead = queued_length_;
  if (window_.cut && segment_count_ > 0) {
    const QueuedSegment& front = segmentAt(0);
    ahead += std::max(front.run_offset + front.path.length() - front_progress_, 0.0);
  }
  if (ahead < window_.starting + window_.reach) return true;
  // Long enough for braking in one S-curve; but runs end at a = 0 each, so braking through
  // short ones needs more path. Enough once the starting runs' plan is cut off from the end
  // (after a cut, asked once the path is within reach of it).
  if (window_.cut && ahead - tail_.length > window_.reach) return false;
  return !window_.settled;
}

LookAhead::WindowNeeds LookAhead::windowNeeds() const {
  WindowNeeds needs;
  needs.version = runs_changed_;
  // A run that held an extreme has left (no run ending at rest is queued: the tail is every
  // run). Until they are found again the old ones hold (a longer reach); found again once a
  // quarter of the runs has left since the last time, so that the walk costs O(1) a run.
  if (tail_stale_pops_ > 0 && 4 * tail_stale_pops_ > run_count_) {
    tail_.extremes = QueuedExtremes{};
    for (std::size_t i = 0; i < run_count_; ++i)
      if (runAt(i).kind != MotionPrimitive::Kind::Dwell) tail_.extremes.add(runAt(i).limits);
    tail_stale_pops_ = 0;
  }
  QueuedExtremes q = tail_.extremes;
  needs.cut = tail_.cuts > 0;
  // Nothing moving after the last cut: the last queued run ends there, and what follows it
  // is wanted once the path is within that run's reach of the end (a zigzag that stops at
  // every corner would else be read to the ring's end). Nothing moving queued: wanted now.
  const bool tail_empty = !(q.velocity > 0.0);
  if (tail_empty) {
    const Run* last = run_count_ > 0 ? &runAt(run_count_ - 1) : nullptr;
    needs.always = last == nullptr || last->kind == MotionPrimitive::Kind::Dwell ||
                   !(last->limits.velocity > 0.0);
    if (needs.always) return needs;
    q = QueuedExtremes{};
    q.add(last->limits);
  }
  // (The ramps take a few hundred instructions: kept while the extremes are the same.)
  if (!(q == reach_for_)) {
    reach_for_ = q;
    reach_for_length_ = reach_machine_.lengthFor(q.velocity, q.acceleration, q.jerk);
  }
  needs.reach = reach_for_length_;
  if (tail_empty) {
    needs.settled = true;  // no run after the cut to start
    return needs;
  }
  const StartingRuns starting = startingRuns(
      needs.cut ? static_cast<std::size_t>(tail_.last_cut + 1 - runs_popped_) : 0, q.velocity);
  needs.starting = starting.length;
  // Settled once a run after those about to start is queued (the last queued run, still
  // open, must not be one of them: a segment that lowers its limits could no longer join it
  // once it runs, joinsLast, and would make a run of its own), and it is cut off from the
  // window's end.
  needs.settled = starting.end + 1 < run_count_ && cutOffFromEnd(starting.end);
  return needs;
}

LookAhead::StartingRuns LookAhead::startingRuns(std::size_t first, double v) const {
  StartingRuns starting{first, 0.0};
  double after_first = 0.0;  // from the first's end to the start of run i
  for (std::size_t i = first; i + 1 < run_count_; ++i) {
    if (i > first + 1 && after_first >= 2.0 * v * reach_machine_.cycle) break;
    starting.length += runAt(i).length;
    starting.end = i + 1;
    if (i > first) after_first += runAt(i).length;
  }
  return starting;
}

bool LookAhead::cutOffFromEnd(std::size_t run) const {
  for (std::size_t i = run; i < run_count_ && i < run + kCutOffScan; ++i)
    if (runAt(i).entry_planned >= entryLimit(i)) return true;
  return false;
}

void LookAhead::cutWindowAfter(std::size_t i) {
  Run& run = runAt(i);
  if (run.window_cut) return;
  run.window_cut = true;
  const std::size_t cuts = tail_.cuts + 1;
  tail_ = Tail{};
  tail_.cuts = cuts;
  tail_.last_cut = runs_popped_ + i;
  tail_stale_pops_ = 0;
}

}  // namespace ncc::vm::motion
