#include "ncc/vm/motion/continuous_path.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ncc/vm/motion/corner_blend.h"
#include "ncc/vm/motion/curve_corner.h"
#include "ncc/vm/motion/scurve.h"

namespace ncc::vm::motion {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Turns above this are never chain vertices (the chain model's small-angle bounds).
constexpr double kChainMaxTurn = 0.1;
// The polygon is smooth (not noisy) at a vertex where the second difference of its curvature
// vectors over three vertices is at most this share of their size (ContinuousPath::
// smoothPolygon); a chain already bowed at the vertex before goes on up to kSmoothKeep (near
// the threshold, bows and blends alternated, slower than either throughout).
constexpr double kSmoothChange = 0.1;
constexpr double kSmoothKeep = 0.5;
// A bow's d2x/ds2 off the chain's reference by at most e reads in a sampled jerk as at most
// 1.5 e v^2 / T (docs/planner.md, "Chains"), budgeted like a curvature step of 1.5 e.
constexpr double kResidualWeight = 1.5;
// The tangent offset and curvature of a bow's end that is not a chain vertex: none.
constexpr AxisValues kStraight{};
// What is left of a trimmed line below this length (mm) is not queued: the blends meet.
constexpr double kNegligibleLength = 1e-9;

bool isFeed(MotionPrimitive::Kind k) {
  return k == MotionPrimitive::Kind::Line || k == MotionPrimitive::Kind::Arc;
}

// The feed is at least kMinPathVelocity, but a curve's own speed cap may be lower (an arc of a
// fraction of a micrometre radius on weak axes, or a chain's polygon around one): its
// acceleration and jerk are budgeted at that speed, so it keeps it (lifted to the floor, a
// 0.2 um arc reached 11.6x the jerk limit, a polygon around a 0.3 um circle 1.07x). Only a
// cap of 0 moves at the floor. A plain line's limits do not depend on its speed.
void keepSpeedCap(SegmentLimits& limits, bool curve) {
  if (!curve) limits.velocity = std::max(limits.velocity, kMinPathVelocity);
  else if (!(limits.velocity > 0.0)) limits.velocity = kMinPathVelocity;
}

}  // namespace

bool ContinuousPath::joinsMoving(MotionPrimitive::Kind kind) const {
  return queue_.lastSegment() != nullptr && !queue_.lastStops() &&
         queue_.lastKind() != MotionPrimitive::Kind::Dwell &&
         isFeed(queue_.lastKind()) == isFeed(kind);
}

void ContinuousPath::enqueue(const QueuedSegment& segment, MotionPrimitive::Kind kind,
                             const SegmentLimits& limits, double vertex_limit, bool stop_after) {
  const double entry =
      joinsMoving(kind) ? std::min({queue_.lastLimits().velocity, limits.velocity, vertex_limit})
                        : 0.0;
  queue_.push(segment, kind, limits, entry, stop_after, 0.0);
}

// A ramp between v and V takes t and covers (v + V) / 2 * t: against cruising at V it loses
// t * (V - v) / (2V). A stop has two such ramps from v = 0, one at each side's feed.
double ContinuousPath::rampCost(double from, double to, double accel, double jerk) {
  return VelocityRamp::make(from, to, accel, jerk).duration * (to - from) / (2.0 * to);
}

double ContinuousPath::stopCost(double speed_in, double speed_out, double accel, double jerk) {
  return rampCost(0.0, speed_in, accel, jerk) + rampCost(0.0, speed_out, accel, jerk);
}

double ContinuousPath::blendCost(double speed_in, double speed_out, double accel, double jerk,
                                 double blend_speed, double blend_length, double trim) {
  // The trim comes off each side at its own feed (a blend after a fast move and before a
  // slow one runs the fast move's share at the slow speed).
  const double v = std::min({blend_speed, speed_in, speed_out});
  return rampCost(v, speed_in, accel, jerk) + rampCost(v, speed_out, accel, jerk) +
         blend_length / v - trim / speed_in - trim / speed_out;
}

ContinuousPath::Weakest ContinuousPath::weakest(const AxisValues& involved) const {
  Weakest w{kInf, kInf};
  for (int i = 0; i < limits_.count; ++i) {
    if (involved[i] == 0.0) continue;
    w.acceleration = std::min(w.acceleration, limits_.acceleration[i]);
    w.jerk = std::min(w.jerk, limits_.jerk[i]);
  }
  return w;
}

double ContinuousPath::curvatureStepLimit(double step, const AxisValues& involved) const {
  if (!(step > 0.0)) return kInf;
  return std::sqrt(kJunctionJerkShare * weakest(involved).jerk * limits_.ipo_cycle / step);
}

double ContinuousPath::kinkAcceleration(double velocity, const EndVertex& vertex) const {
  double limit = kInf;
  if (held_.start_kinked)
    limit = kinkAccelerationLimit(held_.previous_direction, held_.direction,
                                  std::min(held_.previous_length, held_.length),
                                  std::min(held_.start_limit, velocity), limits_);
  if (vertex.kink_velocity > 0.0)
    limit = std::min(limit, kinkAccelerationLimit(held_.end_direction, vertex.next_direction,
                                                  std::min(held_.length, vertex.next_length),
                                                  std::min(vertex.kink_velocity, velocity),
                                                  limits_));
  return limit;
}

bool ContinuousPath::wiggleFits(const AxisValues& wiggle) const {
  // limits.h: 2 delta / T^2 of acceleration and 4 delta / T^3 of jerk.
  const double T = limits_.ipo_cycle;
  for (int i = 0; i < limits_.count; ++i) {
    if (wiggle[i] == 0.0) continue;
    const double allowed = std::min(kWiggleJerkShare * limits_.jerk[i] * T * T * T / 4.0,
                                    kWiggleAccelerationShare * limits_.acceleration[i] * T * T / 2.0);
    if (!(wiggle[i] <= allowed)) return false;
  }
  return true;
}

PathSegment ContinuousPath::heldPart(const AxisValues& end, double end_trim,
                                     const BowVertex* end_bow, bool bounds) const {
  if (held_.arc) return held_arc_.part(held_.start_trim, held_arc_.length() - end_trim);
  if (!held_.start_bowed && end_bow == nullptr)
    return PathSegment::line(held_.start, end, limits_.count);
  return PathSegment::bow(held_.start, end, held_.start_bowed ? held_.start_bow.tangent : held_.direction,
                          end_bow != nullptr ? end_bow->tangent : held_.direction,
                          held_.start_bowed ? held_.start_bow.curvature : kStraight,
                          end_bow != nullptr ? end_bow->curvature : kStraight, limits_.count,
                          bounds);
}

std::optional<ContinuousPath::BowVertex> ContinuousPath::bowVertex(
    const HeldMove& next, double theta, const AxisValues& chain, bool smooth) const {
  const int n = limits_.count;
  const double tolerance = limits_.corner_tolerance;
  if (!(tolerance > 0.0)) return std::nullopt;
  const HeldMove& a = held_;
  // The vertex tangent turns from the held line's direction towards the next's by the share
  // f of theta, the held line's share of the two lengths: on a circle in chords of any
  // lengths, it is then the circle's tangent. The curvature vector: the chain's, less its
  // part along that tangent.
  BowVertex bow;
  const double f = a.length / (a.length + next.length);
  const double sine = std::sin(theta);
  for (int i = 0; i < n; ++i) {
    bow.tangent[i] = sine > 0.0 ? (std::sin((1.0 - f) * theta) * a.direction[i] +
                                   std::sin(f * theta) * next.direction[i]) / sine
                                : a.direction[i];
  }
  double norm = 0.0, along = 0.0;
  for (int i = 0; i < n; ++i) norm += bow.tangent[i] * bow.tangent[i];
  norm = std::sqrt(norm);
  for (int i = 0; i < n; ++i) {
    bow.tangent[i] /= norm;
    along += chain[i] * bow.tangent[i];
  }
  for (int i = 0; i < n; ++i) bow.curvature[i] = chain[i] - along * bow.tangent[i];
  // Both bows within the tolerance of their chords. The next line's far end is not known
  // yet: checked straight there (it is bowed there only if that fits too).
  const double held = PathSegment::bowOffset(
      a.start, a.end, a.start_bowed ? a.start_bow.tangent : a.direction, bow.tangent,
      a.start_bowed ? a.start_bow.curvature : kStraight, bow.curvature, n);
  const double following = PathSegment::bowOffset(a.end, next.end, bow.tangent, next.direction,
                                                  bow.curvature, kStraight, n);
  if (!(std::max(held, following) <= tolerance)) return std::nullopt;
  // Not where the polygon is noisy, here or at the vertex before (smoothPolygon): a bow
  // passes through its chord's ends, and where they are noisy its curvature follows the
  // noise; a lone smooth vertex among noisy ones makes a chain of one vertex whose bows end
  // straight on both sides.
  if (!(held_.start_smooth && smooth)) return std::nullopt;
  return bow;
}

bool ContinuousPath::smoothPolygon(const AxisValues& k) const {
  // Noisy vertices (CAM coordinates rounded to 1 um on chords of a few tenths) are told from
  // a smooth curve's by the polygon's curvature vectors K at this vertex and the two before:
  // on a smooth curve their second difference is tiny (K'' l^2), also where the curvature
  // changes sign; a rounding of d makes it about 4 d / l^2. Smooth: at most kSmoothChange of
  // the largest of the three (one vertex known before: their difference; none: smooth), or
  // kSmoothKeep where the line before starts bowed.
  const HeldMove& a = held_;
  if (a.polygon_curvatures == 0) return true;
  const int n = limits_.count;
  const AxisValues& k1 = a.start_polygon_curvature;
  const AxisValues& k2 = a.polygon_curvature_before;
  const bool both = a.polygon_curvatures > 1;
  double change = 0.0, here = 0.0, before = 0.0, before_that = 0.0;
  for (int i = 0; i < n; ++i) {
    const double d = both ? k[i] - 2.0 * k1[i] + k2[i] : k[i] - k1[i];
    change += d * d;
    here += k[i] * k[i];
    before += k1[i] * k1[i];
    before_that += both ? k2[i] * k2[i] : 0.0;
  }
  const double share = a.start_bowed ? kSmoothKeep : kSmoothChange;
  return std::sqrt(change) <= share * std::sqrt(std::max({here, before, before_that}));
}

PathSegment ContinuousPath::heldProgrammed() const {
  return held_.arc ? held_arc_ : PathSegment::line(held_.from, held_.end, limits_.count);
}

AxisValues ContinuousPath::involvedAxes(const HeldMove& next, const PathSegment& next_path) const {
  AxisValues a = held_.direction, b = next.direction;
  if (held_.arc) held_arc_.maxTangent(a);
  if (next.arc) next_path.maxTangent(b);
  AxisValues involved{};
  for (int i = 0; i < limits_.count; ++i) involved[i] = (a[i] != 0.0 || b[i] != 0.0) ? 1.0 : 0.0;
  return involved;
}

void ContinuousPath::bowShape(const PathSegment& bow, ChainShape& chain, double& residual) const {
  const AxisValues& involved = chain.involved;
  // Two bounds of the sampled jerk hold (docs/planner.md, "Chains"): from d3x/ds3 itself,
  // or from the chain's reference G' plus the residual's 1.5 e v^2 / T. The first is tight
  // where the chain is noisy, the second where the bows are short (d3x/ds3 swings within
  // each, which the samples average). The one that allows the higher speed on the weakest
  // axes is taken.
  const double jerk = kKinkFreeJerkShare * weakest(involved).jerk / 3.0;
  const double own = bow.bowRateAlongChord() + bow.bowRateAcrossChord();
  const double reference = bow.bowReferenceRateAlongChord() + bow.bowReferenceRateAcrossChord();
  const double own_speed = own > 0.0 ? std::cbrt(jerk / own) : kInf;
  const double reference_speed =
      std::min(reference > 0.0 ? std::cbrt(jerk / reference) : kInf,
               curvatureStepLimit(kResidualWeight * bow.bowResidualCurvature(), involved));
  const bool by_reference = reference_speed > own_speed;
  residual = by_reference ? bow.bowResidualCurvature() : 0.0;
  // While the speed changes, the residual's part of a third difference gains 2 v a_t e
  // beside 1.5 e v^2 / T (review 8): covered by counting 2/3 e more curvature in the cross
  // term 3 v a_t k (and, more than needed, in the centripetal one).
  chain.curvature = grids_.curvature.round(bow.maxCurvature() + 2.0 / 3.0 * residual);
  chain.rate_along = grids_.rate_along.round(by_reference ? bow.bowReferenceRateAlongChord()
                                                    : bow.bowRateAlongChord());
  // These three are small on a circle (a thousandth of the rotation, and 1e-7 and 1e-4 over
  // 1) and change with every chord's length: coarser grids, so that a chain's bows share a
  // few shapes and their limits are computed once.
  chain.rate_across = grids_.rate_across.round(by_reference ? bow.bowReferenceRateAcrossChord()
                                                      : bow.bowRateAcrossChord());
  chain.speed = 1.0 + grids_.speed.round(bow.maxSpeed() - 1.0);
  chain.stretch = 1.0 + grids_.stretch.round(bow.parameterStretch() - 1.0);
}

void ContinuousPath::setChainAxes(ChainShape& chain, const EndVertex& vertex) const {
  // The chain's curve turns towards the neighbours across chain vertices only: at any other
  // vertex (a stop, a kink, a blend) the line's own direction is where it starts or ends.
  const bool chain_start = held_.start_curvature > 0.0, chain_end = vertex.curvature > 0.0;
  for (int i = 0; i < limits_.count; ++i) {
    chain.wiggle[i] = grids_.wiggle[i].round(std::max(held_.start_wiggle[i], vertex.wiggle[i]));
    const bool moves = held_.direction[i] != 0.0 ||
                       (chain_start && held_.previous_direction[i] != 0.0) ||
                       (chain_end && vertex.next_direction[i] != 0.0);
    chain.involved[i] = moves ? 1.0 : 0.0;
  }
}

void ContinuousPath::enqueueChainLine(QueuedSegment& seg, SegmentLimits limits, double feed_cap,
                                      const EndVertex& vertex, bool stop_after) {
  // Neighbouring lines of a chain differ slightly in their limits; rounded down to a common
  // grid (the speed only below the feed), their limits are equal and they join one run (one
  // S-curve, not one per 10 um).
  if (limits.velocity < feed_cap) limits.velocity = grids_.velocity.round(limits.velocity);
  limits.acceleration = grids_.acceleration.round(limits.acceleration);
  limits.jerk = grids_.jerk.round(limits.jerk);
  keepSpeedCap(limits, true);
  limits.acceleration = std::min(limits.acceleration, kinkAcceleration(limits.velocity, vertex));
  enqueue(seg, MotionPrimitive::Kind::Line, limits, held_.start_limit, stop_after);
}

void ContinuousPath::queueHeld(const AxisValues& end, double end_trim, const EndVertex& vertex,
                               bool stop_after, bool end_at_rest) {
  const bool start_at_rest = held_.start_limit <= 0.0, end_at_stop = stop_after || end_at_rest;
  const bool resting_end =
      !held_.arc && held_.start_bowed != vertex.bowed && (vertex.bowed ? start_at_rest : end_at_stop);
  // The path built in place (a segment is 2.4 KB: assigning it zeroed and copied as much).
  QueuedSegment seg{.path = heldPart(end, end_trim, vertex.bowed ? &vertex.bow : nullptr,
                                     !resting_end),
                    .where = held_.where};
  if (resting_end) bowRestingEnd(seg.path, vertex.bowed);
  seg.exact_stop = stop_after && held_.exact_stop;
  seg.feed_limit = held_.feed_limit;
  if (!(seg.path.length() > kNegligibleLength)) {
    // Trimmed away by the blends at both ends (they meet with the same tangent and curvature).
    if (stop_after) queue_.stopAfterLast();
    return;
  }
  // The room its ends need in the jerk (smoothJerkShare, limits.h).
  const double jerk_share = smoothJerkShare(
      start_at_rest && end_at_stop,
      held_.start_kinked || ((vertex.kink_velocity > 0.0 || vertex.unknown) && !end_at_stop));
  if (held_.arc) {
    SegmentLimits limits = segmentLimits(seg.path, limits_, false, held_.feed, {}, jerk_share);
    keepSpeedCap(limits, true);
    limits.acceleration = std::min(limits.acceleration,
                                   kinkAcceleration(limits.velocity, vertex));
    enqueue(seg, MotionPrimitive::Kind::Arc, limits, held_.start_limit, stop_after);
    return;
  }
  if (seg.path.shape() == PathSegment::Shape::Bow) {
    queueBow(seg, vertex, jerk_share, stop_after, end_at_stop);
    return;
  }
  ChainShape chain;
  const double end_curvature = vertex.curvature;
  chain.curvature = grids_.polygon_curvature.round(std::max(held_.start_curvature, end_curvature));
  setChainAxes(chain, vertex);
  chain.rate_along = chain.curvature * chain.curvature;  // the circle's rotation
  SegmentLimits limits = chain.curvature > 0.0
                             ? chainLimits(seg.path, held_.feed, chain, jerk_share)
                             : segmentLimits(seg.path, limits_, false, held_.feed, chain, jerk_share);
  // The chain's curvature changes from one vertex to the next along this line: an
  // acceleration step v^2 dk within at most one cycle reads as a jerk v^2 dk / T. Where the
  // path is at rest (the first line of a chain started from a standstill, the last one
  // before a stop) the step is v^2 dk = 0: the line takes its other vertex's curvature.
  if (chain.curvature > 0.0) {
    const double start_k = start_at_rest ? end_curvature : held_.start_curvature;
    const double end_k = end_at_stop ? held_.start_curvature : end_curvature;
    const double step = start_at_rest && end_at_stop ? 0.0 : std::abs(end_k - start_k);
    limits.velocity = std::min(limits.velocity, curvatureStepLimit(step, chain.involved));
    enqueueChainLine(seg, limits, held_.feed, vertex, stop_after);
    return;
  }
  keepSpeedCap(limits, false);
  limits.acceleration = std::min(limits.acceleration,
                                 kinkAcceleration(limits.velocity, vertex));
  enqueue(seg, MotionPrimitive::Kind::Line, limits, held_.start_limit, stop_after);
}

void ContinuousPath::bowRestingEnd(PathSegment& line, bool at_start) const {
  // The chain's end bow is straight at an end where the path goes on moving (a kink, a
  // blend). Where it rests, its tangent and curvature there are free: the mirror images of
  // the other end's (across the chord's middle) make the bow symmetric, like an arc of the
  // chain's curvature (straight there, its curvature would fall to 0 within the chord), if
  // that stays within the tolerance. `line` comes without bounds and leaves with them.
  const int n = limits_.count;
  AxisValues t, k, c, free_tangent, free_curvature;
  const double at = at_start ? line.length() : 0.0;
  line.tangent(at, t);
  line.curvature(at, k);
  double chord = 0.0, t_along = 0.0, k_along = 0.0;
  for (int i = 0; i < n; ++i) chord += (line.to()[i] - line.from()[i]) * (line.to()[i] - line.from()[i]);
  chord = std::sqrt(chord);  // (a bow's length() is its arc's)
  for (int i = 0; i < n; ++i) {
    c[i] = (line.to()[i] - line.from()[i]) / chord;
    t_along += t[i] * c[i];
    k_along += k[i] * c[i];
  }
  for (int i = 0; i < n; ++i) {
    free_tangent[i] = 2.0 * t_along * c[i] - t[i];
    free_curvature[i] = k[i] - 2.0 * k_along * c[i];
  }
  const AxisValues& from = line.from();
  const AxisValues& to = line.to();
  const double offset =
      at_start ? PathSegment::bowOffset(from, to, free_tangent, t, free_curvature, k, n)
               : PathSegment::bowOffset(from, to, t, free_tangent, k, free_curvature, n);
  if (!(offset <= limits_.corner_tolerance)) {  // straight there, as it came
    free_tangent = c;
    free_curvature = AxisValues{};
  }
  line = at_start ? PathSegment::bow(from, to, free_tangent, t, free_curvature, k, n)
                  : PathSegment::bow(from, to, t, free_tangent, k, free_curvature, n);
}

void ContinuousPath::queueBow(QueuedSegment& seg, const EndVertex& vertex, double jerk_share,
                              bool stop_after, bool end_at_rest) {
  const int n = limits_.count;
  ChainShape chain;
  setChainAxes(chain, vertex);  // (a polygon chain vertex at an end keeps its wiggle)
  double residual = 0.0;
  bowShape(seg.path, chain, residual);
  if (held_.start_bowed) {
    // Along a chain the speed bound and the stretch only grow (to the chain's largest, a
    // hair over 1): fewer shapes.
    const ChainShape& before = last_bow_shape_;
    chain.speed = std::max(chain.speed, before.speed);
    chain.stretch = std::max(chain.stretch, before.stretch);
  }
  if (held_.start_bowed && !vertex.bowed && end_at_rest) {
    // The last bow before a stop takes the shape of the one before it where that is larger,
    // so that it joins its run (else the run's braking ends at a = 0 where it starts, and the
    // last bow is a profile of its own: 12 ms at the end of a circle in 0.01 mm chords).
    const ChainShape& before = last_bow_shape_;
    chain.curvature = std::max(chain.curvature, before.curvature);
    chain.rate_along = std::max(chain.rate_along, before.rate_along);
    chain.rate_across = std::max(chain.rate_across, before.rate_across);
    chain.speed = std::max(chain.speed, before.speed);
    chain.stretch = std::max(chain.stretch, before.stretch);
    for (int i = 0; i < n; ++i) chain.involved[i] = std::max(chain.involved[i], before.involved[i]);
  }
  // The ramp envelope is searched for a bow's limits where its shape repeats (a circle in
  // chords: once) or a chain starts (its first bow joins the run of the next ones, and a run
  // takes the lowest limits of its segments); not where the shape changes from bow to bow (a
  // sine, an ellipse), where every bow paid for a search: 30 us each, 4x the simulation time
  // of a six-axis program. A shape seen before repeats, searched or not: the two lookups
  // that tell also answer chainLimits' own (the limits with the envelope are `searched`, if
  // any; those without it, for a shape that does not repeat, are not cached).
  const SegmentLimits* searched = cachedChainLimits(held_.feed, chain, jerk_share);
  ChainShape seen = chain;
  seen.ramp_envelope = false;
  const bool repeats = searched != nullptr || !held_.start_bowed || chain == last_bow_shape_ ||
                       cachedChainLimits(held_.feed, seen, jerk_share) != nullptr;
  last_bow_shape_ = chain;
  chain.ramp_envelope = repeats;
  SegmentLimits limits =
      searched != nullptr ? *searched : newChainLimits(seg.path, held_.feed, chain, jerk_share);
  limits.velocity = std::min(limits.velocity,
                             curvatureStepLimit(kResidualWeight * residual, chain.involved));
  // (The feed over the speed bound is the same for the chain's bows.)
  enqueueChainLine(seg, limits, held_.feed / chain.speed, vertex, stop_after);
}

const SegmentLimits* ContinuousPath::cachedChainLimits(double feed, const ChainShape& chain,
                                                       double jerk_share) const {
  // The curvature first: it tells the shapes of a chain apart (the feed and the share are
  // mostly the same in every entry), so that a miss costs one comparison per entry.
  for (const ChainLimits& c : chain_cache_) {
    if (c.shape.curvature == chain.curvature && c.valid && c.feed == feed &&
        c.jerk_share == jerk_share && c.shape == chain)
      return &c.limits;
  }
  return nullptr;
}

SegmentLimits ContinuousPath::chainLimits(const PathSegment& line, double feed,
                                          const ChainShape& chain, double jerk_share) {
  // A chain line's limits depend on nothing else: its tangent and normal are bounded by 1 on
  // every involved axis (limits.h), whatever its direction.
  if (const SegmentLimits* cached = cachedChainLimits(feed, chain, jerk_share)) return *cached;
  return newChainLimits(line, feed, chain, jerk_share);
}

SegmentLimits ContinuousPath::newChainLimits(const PathSegment& line, double feed,
                                             const ChainShape& chain, double jerk_share) {
  ChainLimits& slot = chain_cache_[chain_cache_next_];
  chain_cache_next_ = (chain_cache_next_ + 1) % chain_cache_.size();
  slot = {true, feed, jerk_share, chain, segmentLimits(line, limits_, false, feed, chain, jerk_share)};
  return slot.limits;
}

void ContinuousPath::flush(bool at_rest) {
  if (!held_.active) return;
  queueHeld(held_.end, 0.0, EndVertex{.unknown = !at_rest}, false, at_rest);
  held_.active = false;
}

bool ContinuousPath::blendCorner(HeldMove& next, const PathSegment& next_path, double theta,
                                 double unblended, double chain_end) {
  const int n = limits_.count;
  const HeldMove& a = held_;
  const double tolerance = limits_.corner_tolerance;
  if (!(tolerance > 0.0 && theta > 0.0 && theta <= CornerBlend::kMaxTurn)) return false;
  double trim = 0.0;
  AxisValues b_from = a.end, b_to = a.end;
  CornerBlend curve;
  if (!a.arc && !next.arc) {
    // Two lines: d from the tolerance, at most half of each line.
    trim = std::min({tolerance / (CornerBlend::kDeviationFactor * std::sin(0.5 * theta)),
                     0.5 * a.length, 0.5 * next.length});
    for (int i = 0; i < n; ++i) {
      b_from[i] = a.end[i] - trim * a.direction[i];
      b_to[i] = a.end[i] + trim * next.direction[i];
    }
    curve = CornerBlend::make(a.end, a.direction, next.direction, trim, n);
  } else {
    // A tangent junction with an arc keeps its exact geometry (passed at the junction
    // velocity); a corner is fitted.
    if (theta <= kCornerAngle) return false;
    const std::optional<CurveCorner> fit =
        fitCurveCorner(heldProgrammed(), next_path, tolerance, n);
    if (!fit) return false;
    trim = fit->trim;
    b_from = fit->from;
    b_to = fit->to;
    curve = fit->curve;
  }
  QueuedSegment blend;
  blend.where = next.where;
  blend.feed_limit = std::min(a.feed_limit, next.feed_limit);
  blend.path = PathSegment::blend(b_from, b_to, curve, n);
  const SegmentLimits bl = segmentLimits(blend.path, limits_, false, std::min(a.feed, next.feed));
  // A blend so tight for the axes that its curvature caps the speed below the slowest speed
  // anything is planned with (the feeds are at least that) could not keep the limits at that
  // speed: stop instead (a 0.2 um blend on an axis of 35 mm/s^3 reached 4.9x its jerk).
  if (!(bl.velocity >= kMinPathVelocity)) return false;
  // Worth it if faster than the alternative: the kink's speed, or a stop.
  const Weakest w = weakest(involvedAxes(next, next_path));
  const double path_accel = w.acceleration, path_jerk = kSmoothJerkShare * w.jerk;
  const bool beats_stop =
      blendCost(a.feed, next.feed, path_accel, path_jerk, bl.velocity, blend.path.length(), trim) <
      stopCost(a.feed, next.feed, path_accel, path_jerk);
  if (!(bl.velocity > unblended && (unblended > 0.0 || beats_stop))) return false;
  queueHeld(b_from, trim, {next.direction, next.length}, false);
  // The blend starts exactly where the trimmed move ended (also when the blends on both sides
  // left nothing of it).
  const QueuedSegment* last = queue_.lastSegment();
  if (last != nullptr) blend.path = PathSegment::blend(last->path.to(), b_to, curve, n);
  enqueue(blend, MotionPrimitive::Kind::Line, bl, chain_end, false);
  next.start = b_to;
  next.start_trim = trim;
  next.start_limit = kInf;  // G2 junction: same tangent and curvature
  return true;
}

bool ContinuousPath::move(const PathSegment& programmed, double feed, double feed_limit,
                          bool exact_stop, const SourcePosition& where) {
  const int n = limits_.count;
  if (!(programmed.length() > 0.0)) return false;
  HeldMove next;
  next.active = true;
  next.arc = programmed.shape() == PathSegment::Shape::Arc;
  next.from = programmed.from();
  next.start = programmed.from();
  next.end = programmed.to();
  next.feed = feed;
  next.feed_limit = feed_limit;
  next.where = where;
  next.exact_stop = exact_stop;
  next.length = programmed.length();
  programmed.tangent(0.0, next.direction);
  programmed.tangent(next.length, next.end_direction);

  if (!held_.active) {
    // The junction with whatever is queued (a rapid, or nothing): the plain rule; 0 from
    // rest (nothing queued, a stop, a dwell or a rapid before it).
    if (joinsMoving(MotionPrimitive::Kind::Line)) {
      const PathSegment& before = queue_.lastSegment()->path;
      next.start_limit = junctionVelocity(before, programmed, limits_);
      before.tangent(before.length(), next.previous_direction);
      next.previous_length = before.length();
      next.start_kinked = true;
    }
  } else {
    const HeldMove& a = held_;
    const double theta = turnAngle(a.end_direction, next.direction, n);
    const AxisValues involved = involvedAxes(next, programmed);
    const bool lines = !a.arc && !next.arc;
    // The polygon's curvature vector here, (c_b - c_a) / mean length (lines only), and
    // whether the polygon is smooth here (smoothPolygon).
    AxisValues polygon_curvature{};
    if (lines)
      for (int i = 0; i < n; ++i)
        polygon_curvature[i] =
            (next.direction[i] - a.direction[i]) / (0.5 * (a.length + next.length));
    const bool smooth = lines && smoothPolygon(polygon_curvature);
    const double kappa = 2.0 * std::sin(0.5 * theta) / (0.5 * (a.length + next.length));
    const double longest = std::max(a.length, next.length);
    // The polygon's deviation from the curve through the vertex, along the axes the turn
    // moves (its normal's): the sagitta.
    const double sagitta = longest * longest * kappa / 8.0;
    AxisValues wiggle{};
    for (int i = 0; i < n; ++i)
      wiggle[i] = next.direction[i] != a.end_direction[i] ? sagitta : 0.0;

    // A turn the kink rule passes at full speed needs nothing else (collinear lines, tangent
    // arcs, and tiny turns between long lines).
    const double kink =
        theta <= kCornerAngle
            ? junctionVelocity(heldPart(a.end, 0.0, nullptr, false), programmed, limits_)
            : 0.0;
    const bool kink_free = a.start_curvature == 0.0 && kink >= std::max(a.feed, feed);
    if (kink_free) {
      queueHeld(a.end, 0.0, {.next_direction = next.direction, .next_length = next.length,
                             .kink_velocity = kink},
                false);
      next.start_limit = kink;
      next.start_kinked = true;
    } else if (const std::optional<BowVertex> bow =
                   lines && theta <= kChainMaxTurn
                       ? bowVertex(next, theta, polygon_curvature, smooth)
                       : std::nullopt) {
      // Bowed chain vertex: both lines planned as the curve through it, bowed to its tangent.
      queueHeld(a.end, 0.0,
                {.next_direction = next.direction, .next_length = next.length, .curvature = kappa,
                 .bowed = true, .bow = *bow},
                false);
      next.start_limit = kInf;
      next.start_curvature = kappa;
      next.start_bowed = true;
      next.start_bow = *bow;
    } else if (lines && theta <= kChainMaxTurn && wiggleFits(wiggle)) {
      // Chain vertex: passed as is, both lines planned as the curve through it.
      queueHeld(a.end, 0.0, {next.direction, next.length, kappa, wiggle}, false);
      next.start_limit = kInf;
      next.start_curvature = kappa;
      next.start_wiggle = wiggle;
    } else {
      // Candidates that keep the geometry: the kink rule (small turns), else a stop; both
      // with the curvature step where a chain ends here.
      // (A bowed line ends straight and without curvature where the chain ends: no step.)
      const double chain_end =
          curvatureStepLimit(a.start_bowed ? 0.0 : a.start_curvature, involved);
      const double unblended = std::min(kink, chain_end);
      if (!blendCorner(next, programmed, theta, unblended, chain_end)) {
        const bool stop = unblended <= 0.0;
        queueHeld(a.end, 0.0,
                  {.next_direction = next.direction, .next_length = next.length,
                   .kink_velocity = stop ? 0.0 : unblended},
                  stop);
        next.start_limit = unblended;
        next.start_kinked = !stop;
      }
    }
    next.previous_direction = a.end_direction;
    next.previous_length = a.length;
    if (lines) {
      next.start_smooth = smooth;
      next.start_polygon_curvature = polygon_curvature;
      next.polygon_curvature_before = a.start_polygon_curvature;
      next.polygon_curvatures = std::min(a.polygon_curvatures + 1, 2);
    }
  }
  held_ = next;
  if (next.arc) held_arc_ = programmed;
  if (exact_stop) {
    queueHeld(held_.end, 0.0, EndVertex{}, true);
    held_.active = false;
  }
  return true;
}

}  // namespace ncc::vm::motion
