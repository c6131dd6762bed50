#pragma once
// Look-ahead over queued segments, grouped into runs.
//
// A run is a chain of consecutive segments of the same kind (a G63 tap apart from moves the
// feed override scales) whose junctions do not bind (tangent or collinear, junction limit >=
// the run's velocity limit) and whose limits are within 1 %, or whose speeds are within 20 %
// and which are too short together to change speed much (docs/planner.md, "Look-ahead"); the
// run takes the lowest of each limit: a 10 um G01 chain along a line, an arc split into
// pieces. The S-curve is planned over a run as one 1-D path, so a chain of tiny segments
// accelerates like one long segment; profiles start and end at zero acceleration only at run
// boundaries. A junction between runs passes at a velocity limit (0 at corners and exact
// stops).
//
// Backward pass (on every push): each run's entry velocity is the highest from which it and
// every later known run can still brake to v = 0 at the end of the window (the future is
// unknown, so the window always ends at rest). New input only raises these velocities and the
// pass stops at the first entry that does not change (earlier ones depend only on it).
//
// Forward pass: the interpolator plans one profile ("piece") at a time from the actual
// velocity (see Interpolator). Two fixed-capacity rings hold segments and runs, allocated in
// the constructor; nothing allocates or throws afterwards.
//
// Window: it wants input (wantsMore) until more could not change the plan of the runs about
// to start: the braking reach of what is queued, from the last run that ends at rest.
//
// The operator's live controls (setScales): under the feed override every run's speed limit
// is its planned limit, at most its programmed feed times the feed scale; a rapid run's is its
// planned limit times the rapid scale; under feed hold every speed limit is 0. A change
// re-plans the whole window; entries may fall, but never below what the motion already under
// way can brake to (entry floors).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "ncc/vm/events.h"
#include "ncc/vm/motion/limits.h"
#include "ncc/vm/motion/path.h"
#include "ncc/vm/motion/window_reach.h"

namespace ncc::vm::motion {

// The operator's live controls as factors on the planned speed limits.
struct SpeedScales {
  double feed = 1.0;   // on each run's feed_limit: the live feed override over the planned one
  double rapid = 1.0;  // on each rapid run's limit: the live rapid override over the planned one
  bool held = false;   // feed hold: every speed limit 0 (a G63 tap's apart)
  bool operator==(const SpeedScales&) const = default;
};

struct QueuedSegment {
  PathSegment path;
  SourcePosition where;
  double run_offset = 0.0;  // path length of its run before it
  bool per_axis = false;    // a non-linear rapid (axis_rapid.h): its own run, at rest both ends
  bool exact_stop = false;  // G09/G61: the path stops at its end with an in-position check
  // The programmed path speed (mm/s, at the planning feed override) a live feed override
  // scales; infinite where it does not apply (rapids, G63 tapping).
  double feed_limit = std::numeric_limits<double>::infinity();
};

struct Run {
  SegmentLimits limits;
  MotionPrimitive::Kind kind = MotionPrimitive::Kind::Line;
  double length = 0.0;         // sum of its segments' lengths
  uint32_t segments = 0;       // its segments still queued
  double dwell_seconds = 0.0;  // Dwell runs: one segment of length 0
  double entry_limit = 0.0;    // junction velocity limit at its start (0: from rest)
  double entry_planned = 0.0;  // backward pass result
  bool stop_after = false;     // ends at rest whatever follows (G09/G61, M00, dwell...)
  // It ends at rest (stop_after, or the next run starts from rest): more input after it cannot
  // change its plan or any before it (LookAhead::wantsMore).
  bool window_cut = false;
  double feed_limit = std::numeric_limits<double>::infinity();  // lowest of its segments'
  // Lowest entry the motion under way can brake to (set by setScales, 0 otherwise).
  double entry_floor = 0.0;
  double entry_before = 0.0;  // entry_planned before the last setScales
  // Length of the segments at its end that are faster than it (joined as short ones,
  // tooShortToSplit, they run at its speed).
  double faster_tail = 0.0;
};

// Where the motion under way is committed to when the speed limits change: at run offset
// `offset` of the front run it moves at `velocity` with zero acceleration, whatever the new
// plan (Interpolator::commitForReplan).
struct Commitment {
  double offset = 0.0;
  double velocity = 0.0;
};

class LookAhead {
 public:
  // `reach`: the machine's braking reach (wantsMore).
  LookAhead(std::size_t capacity, const WindowReach& reach);

  bool empty() const { return segment_count_ == 0; }
  bool full() const { return segment_count_ == segments_.size(); }
  std::size_t room() const { return segments_.size() - segment_count_; }
  std::size_t size() const { return segment_count_; }
  // Whether more input could still change the plan: the ring has room, and either the path
  // queued is shorter than the reach (WindowReach) for the runs it holds or the plan of the
  // runs about to start still depends on where the window ends (cutOffFromEnd). A run that
  // ends at rest cuts the window (Run::window_cut): only the runs after the last such run
  // count, and the path from where the path is; without one, the path after the running
  // segment. The runs about to start (startingRuns) are planned to their exits when they
  // start, so the reach counts from their end, and none of them may be the last queued run
  // (a segment that lowers its limits could no longer join it once it runs). Not in the
  // tick: it may walk runs.
  bool wantsMore() const;
  // Where the path is in the front run (its run offset; for a non-linear rapid, its share of
  // the time times the run's length), set by the interpolator each tick: how much of the
  // queued path is still ahead, for the reach after a cut (wantsMore).
  void setFrontProgress(double offset) { front_progress_ = offset; }

  // Appends a segment (caller checks !full()). `entry_limit` is the junction limit with the
  // previous segment; the segment joins the last run when the junction does not bind and
  // the limits are close or both are short and of near speed (see the top), else starts a
  // run. A join that lowers the run's limits is refused where it would lower what the motion
  // under way is committed to: in the started front run, or below the run's planned entry.
  // Runs the backward pass.
  void push(const QueuedSegment& segment, MotionPrimitive::Kind kind, const SegmentLimits& limits,
            double entry_limit, bool stop_after, double dwell_seconds);
  // The last queued segment ends at rest.
  void stopAfterLast();
  // Last queued segment, or nullptr.
  const QueuedSegment* lastSegment() const;
  MotionPrimitive::Kind lastKind() const { return runAt(run_count_ - 1).kind; }
  bool lastStops() const { return runAt(run_count_ - 1).stop_after; }
  const SegmentLimits& lastLimits() const { return runAt(run_count_ - 1).limits; }
  // Run i's speed limit under the live scales (its planned limit under SpeedScales{});
  // velocityWith: under the given ones.
  double velocity(std::size_t i) const;
  double velocityWith(std::size_t i, const SpeedScales& scales) const;
  // The operator's live controls. Re-plans the whole window from `committed` on: each later
  // junction gets a floor, the lowest velocity braking as hard as the limits allow reaches
  // from there (all of them at most what the previous plan had, so every geometric and
  // junction limit still holds). O(queued runs). Under feed hold the path brakes to rest as
  // the limits allow (through as many runs as that takes) and stays there; released, the
  // window is planned as before.
  void setScales(const SpeedScales& scales, const Commitment& committed);
  const SpeedScales& scales() const { return scales_; }
  double feedScale() const { return scales_.feed; }
  bool held() const { return scales_.held; }

  Run& frontRun() { return runAt(0); }
  QueuedSegment& frontSegment() { return segmentAt(0); }
  bool frontRunIsLast() const { return run_count_ == 1; }
  // Planned entry velocity of the run after the front run (0 when there is none or the front
  // run stops).
  double frontRunExit() const { return runExit(0); }
  // Read access by position from the front, for planning ahead (Interpolator).
  std::size_t runCount() const { return run_count_; }
  const Run& run(std::size_t i) const { return runAt(i); }
  const QueuedSegment& segment(std::size_t i) const { return segmentAt(i); }
  // Planned velocity at the end of run i: the next run's entry, 0 when none follows or run i
  // stops.
  double runExit(std::size_t i) const;
  // Changes with every push, pop and stop flag: what is queued (and planned) is the same as
  // long as it is.
  uint64_t version() const { return version_; }
  // Asks the CPU to bring the first `count` queued segments into cache. A segment is large
  // (a blend carries its arc-length tables) and was written when it entered the window, long
  // enough ago to have left the cache; reading it cold costs a tick several hundred ns, so
  // the preparation calls this for the segments the next tick will read. Segments already
  // prefetched by an earlier call are skipped.
  void prefetchFront(std::size_t count);
  // While deferred, push() leaves the backward pass to runDeferredBackwardPass(), which runs
  // one pass over everything pushed since (DeferredBackwardPass below). The entries it plans
  // are the same, bit for bit: a pass only stops at a run it did not touch whose entry comes
  // out unchanged. Meanwhile the entries of the runs pushed are stale: nothing but the pushes
  // may read them.
  void deferBackwardPass() { defer_pass_ = true; }
  void runDeferredBackwardPass();
  // Drop the front segment / the (empty) front run.
  void popSegment();
  void popRun();
  // The front run is running: the backward pass leaves it alone.
  void setFrontRunStarted(bool started) { front_started_ = started; }

 private:
  // index % size. The rings' indices are head + i with both below size, so one subtraction
  // does it: a 64-bit division costs tens of cycles, and a tick reads the rings many times.
  static std::size_t wrap(std::size_t index, std::size_t size) {
    if (index >= size) index -= size;
    return index < size ? index : index % size;
  }
  QueuedSegment& segmentAt(std::size_t i) { return segments_[wrap(seg_head_ + i, segments_.size())]; }
  const QueuedSegment& segmentAt(std::size_t i) const {
    return segments_[wrap(seg_head_ + i, segments_.size())];
  }
  Run& runAt(std::size_t i) { return runs_[wrap(run_head_ + i, runs_.size())]; }
  const Run& runAt(std::size_t i) const { return runs_[wrap(run_head_ + i, runs_.size())]; }
  // Whether a segment pushed with these arguments joins the last run (see push), and whether
  // it lowers that run's limits (beyond rounding) or its programmed feed.
  // (Not const: it may run a deferred backward pass for the last run's planned entry.)
  bool joinsLast(const QueuedSegment& segment, MotionPrimitive::Kind kind,
                 const SegmentLimits& limits, double entry_limit);
  bool lowersLast(const QueuedSegment& segment, const SegmentLimits& limits) const;
  // A run's speed limit under `scales`.
  static double speedLimit(const Run& run, const SpeedScales& scales);
  // After a change of the speed limits: the whole window again, with entry floors from
  // `committed` on (setScales).
  void replan(const Commitment& committed);
  // `full`: every run, not only up to the first unchanged entry of a run pushed to before
  // stale_from_.
  void backwardPass(bool full = false);
  // Run i's junction limit under the live scales: also at most its and the previous run's
  // speed.
  double entryLimit(std::size_t i) const;

  std::vector<QueuedSegment> segments_;
  std::vector<Run> runs_;
  std::size_t seg_head_ = 0, segment_count_ = 0;
  uint64_t segments_popped_ = 0;     // over the ring's life: the front's absolute index
  uint64_t prefetched_until_ = 0;    // absolute index after the last segment prefetched
  std::size_t run_head_ = 0, run_count_ = 0;
  bool front_started_ = false;
  // Deferred backward pass: whether one is owed, and the first run (from the front) pushed to
  // since the last pass ran (run_count_ or more: none).
  bool defer_pass_ = false;
  bool pass_pending_ = false;
  std::size_t stale_from_ = 0;
  uint64_t version_ = 0;
  uint64_t runs_changed_ = 0;  // like version_, but not for a segment's end within a run
  WindowReach reach_machine_;
  double queued_length_ = 0.0;  // lengths of the segments behind the front one
  // The runs after the last queued run that ends at rest (every queued run when none does),
  // for wantsMore(). Kept as runs are pushed (a join only lowers a run's limits); an extreme
  // that leaves with a popped run is found again by a later wantsMore() (in the preparation,
  // not in the tick that popped it).
  struct QueuedExtremes {
    double velocity = 0.0;  // the highest speed limit of the moving runs (0: none)
    double acceleration = std::numeric_limits<double>::infinity();  // the lowest
    double jerk = std::numeric_limits<double>::infinity();          // the lowest
    void add(const SegmentLimits& l);
    bool operator==(const QueuedExtremes&) const = default;
  };
  struct Tail {
    std::size_t cuts = 0;       // queued runs with window_cut
    uint64_t last_cut = 0;      // the last of them, counted from the first run ever pushed
    double length = 0.0;        // path pushed after it
    QueuedExtremes extremes;    // of the moving runs after it
  };
  // Queued run i ends at rest: it cuts the window, and nothing follows it yet.
  void cutWindowAfter(std::size_t i);
  // Of the runs from `first` on, those whose pieces may start before the next preparation
  // queues more (the first, the next, and any starting within two cycles of travel at `v`
  // after the first's end), closed runs only (the last queued run's end is not known).
  // Their exits are planned when they start, so the reach counts from there.
  struct StartingRuns {
    std::size_t end = 0;  // the run after them
    double length = 0.0;
  };
  StartingRuns startingRuns(std::size_t first, double v) const;
  // Whether the plan of the runs before `run` is cut off from the window's end: a run from
  // `run` on enters at its own cap. More input only raises the planned entries near the end
  // (the window then ends moving, not at rest), so it cannot reach past such a run. Looks at
  // kCutOffScan runs at most: beyond them, not cut off.
  bool cutOffFromEnd(std::size_t run) const;
  static constexpr std::size_t kCutOffScan = 64;
  uint64_t runs_popped_ = 0;  // over the ring's life: the front run's index
  double front_progress_ = 0.0;  // setFrontProgress
  mutable Tail tail_;
  // What wantsMore() needs of the path ahead, worked out again when the queue changes.
  struct WindowNeeds {
    uint64_t version = std::numeric_limits<uint64_t>::max();  // runs_changed_ it is for
    bool always = false;   // nothing moving in the tail: more input is wanted
    bool cut = false;      // a run ending at rest is queued
    double reach = 0.0;    // the tail's WindowReach
    double starting = 0.0;  // the length of the runs about to start (startingRuns)
    // The runs about to start are closed and their plan is cut off from the window's end.
    bool settled = false;
  };
  WindowNeeds windowNeeds() const;
  mutable WindowNeeds window_;
  mutable QueuedExtremes reach_for_{.velocity = -1.0};  // the last reach worked out (none)
  mutable double reach_for_length_ = 0.0;
  // Runs popped since one that held an extreme of the tail left (0: the extremes are exact).
  mutable std::size_t tail_stale_pops_ = 0;
  SpeedScales scales_;
};

// Defers a LookAhead's backward passes while it lives and runs one when it goes: a feed move
// queues up to three segments (the held move, a blend, itself), each of which would walk
// back over the runs within braking distance of the window's end.
class DeferredBackwardPass {
 public:
  explicit DeferredBackwardPass(LookAhead& queue) : queue_(queue) { queue_.deferBackwardPass(); }
  ~DeferredBackwardPass() { queue_.runDeferredBackwardPass(); }
  DeferredBackwardPass(const DeferredBackwardPass&) = delete;
  DeferredBackwardPass& operator=(const DeferredBackwardPass&) = delete;

 private:
  LookAhead& queue_;
};

}  // namespace ncc::vm::motion
