// The sequences of the canned hole cycles (docs/cycles.md). Every dialect runs the same
// skeleton (FANUC-family "seven movements", Mazak §13-1-1, Siemens ISO §4.1.1): position in
// the plane, rapid to R, the cycle's way to the bottom, the actions at the bottom, the way back
// to R or to the initial level. What differs (the back-off of G73, the dwell places, the
// spindle functions) comes as data in the HoleCycle.
#include "cycle_expansion.h"

#include <algorithm>
#include <cmath>

namespace ncc::passes {

namespace {

constexpr double kSame = 1e-9;  // mm: a move of this length or less is no move

// A hole's operations, handed to `emit` one at a time as they are made (a deep hole's pecks are
// never all held).
class Sequence {
 public:
  Sequence(const ir::HoleCycle& c, int axis_count, const OperationEmitter& emit)
      : c_(c), n_(std::clamp(axis_count, 0, kMaxAxes)), at_(c.from), emit_(emit) {}

  void rapid(const AxisValues& to) {
    if (same(to)) return;
    emit_(ir::Rapid{to, ir::Space::Work, c_.rapid_type});
    at_ = to;
  }
  void feed(const AxisValues& to, double f) {
    if (same(to)) return;
    emit_(ir::Linear{to, ir::Space::Work, f, c_.feed_per_rev});
    at_ = to;
  }
  // A move of the drilling axis only.
  void rapidTo(double level) { rapid(level_(level)); }
  void feedTo(double level, double f) { feed(level_(level), f); }
  void dwell() {
    if (c_.dwell > 0) emit_(ir::Dwell{c_.dwell, c_.dwell_revolutions});
  }
  void spindle(ir::MachineFunction::Kind k) { emit_(ir::MachineFunction{k, 0, 0.0}); }
  const AxisValues& at() const { return at_; }

 private:
  bool same(const AxisValues& to) const {
    for (int i = 0; i < n_; ++i)
      if (std::fabs(to[i] - at_[i]) > kSame) return false;
    return true;
  }
  AxisValues level_(double v) const {
    AxisValues t = at_;
    t[c_.axis] = v;
    return t;
  }

  const ir::HoleCycle& c_;
  int n_;
  AxisValues at_;
  const OperationEmitter& emit_;
};

using K = ir::MachineFunction::Kind;

// Mazak §13-1 K (G73/G83) / D (G82): a rapid from R down to where the feed starts. Returns that
// level (R without it).
double feedStart(Sequence& s, const ir::HoleCycle& c) {
  if (!(c.feed_start > 0)) return c.r_level;
  const double dir = c.bottom < c.r_level ? -1.0 : 1.0;
  const double start = c.r_level + dir * c.feed_start;
  s.rapidTo(start);
  return start;
}

// The feed of an infeed that starts at `from`: Mazak's I J slow it when it starts within I of
// the bottom ("the feed is f1 only if the cut starts within the range i0", §13-1-15).
double feedFrom(const ir::HoleCycle& c, double from) {
  return c.slow_zone > 0 && std::fabs(from - c.bottom) <= c.slow_zone + kSame ? c.slow_feed : c.feed;
}

// Infeeds of Q from R (or the feed start) to Z: after each one but the last, `retreat(depth, above)` takes the tool
// back (above: d above the depth just reached) so that the next infeed starts there.
template <typename Retreat>
void infeeds(Sequence& s, const ir::HoleCycle& c, Retreat retreat) {
  const double dir = c.bottom < c.r_level ? -1.0 : 1.0;  // into the hole
  double depth = feedStart(s, c);
  double from = depth;  // where this infeed starts (after the retreat)
  for (;;) {
    double next = depth + dir * c.peck;
    if ((next - c.bottom) * dir >= -kSame) next = c.bottom;
    s.feedTo(next, feedFrom(c, from));
    depth = next;
    if (next == c.bottom) return;
    from = depth - dir * c.peck_distance;
    retreat(from);
  }
}

// G73: feed Q, back off d (rapid, or Mazak's fixed retract feed), feed d + Q, ... to Z.
// G83: feed Q, rapid to R, rapid to d above the last depth, feed d + Q, ... to Z.
void pecks(Sequence& s, const ir::HoleCycle& c) {
  infeeds(s, c, [&](double above) {
    if (c.kind == ir::HoleCycle::Kind::HighSpeedPeck) {
      if (c.peck_retract_feed > 0)
        s.feedTo(above, c.peck_retract_feed);
      else
        s.rapidTo(above);
    } else {
      s.rapidTo(c.r_level);
      s.rapidTo(above);
    }
  });
}

// Peck tapping (FANUC deep-hole rigid tapping, Siemens §4.1.13): tap Q at F; then back off d
// at the retract speed and tap d + Q (high speed), or out to R at the retract speed, back down
// to d above the last depth (Siemens at F, FANUC at the retract speed) and tap d + Q; to Z. The
// spindle follows the axis (rigid): the back-offs reverse it without an M code.
void tapPecks(Sequence& s, const ir::HoleCycle& c) {
  infeeds(s, c, [&](double above) {
    if (c.peck_tap_to_r) s.feedTo(c.r_level, c.retract_feed);
    s.feedTo(above, c.peck_tap_to_r ? c.peck_approach_feed : c.retract_feed);
  });
}

K direction(int d) { return d < 0 ? K::SpindleCCW : K::SpindleCW; }

AxisValues shifted(const AxisValues& at, const AxisValues& shift, double sign) {
  AxisValues t = at;
  for (int i = 0; i < kMaxAxes; ++i) t[i] += sign * shift[i];
  return t;
}

// G87 (Siemens §4.1 table, Mazak §13-1-2, FANUC common): at the initial level orient the
// spindle and shift off the hole axis, rapid down to R (below the part), shift back, spindle
// on, bore upwards to Z, dwell, orient, shift, rapid up to the initial level, shift back, spindle
// on. Always back to the initial level.
void backBore(Sequence& s, const ir::HoleCycle& c) {
  s.spindle(K::SpindleOrient);
  s.rapid(shifted(s.at(), c.shift, 1.0));
  s.rapidTo(c.r_level);
  s.rapid(shifted(s.at(), c.shift, -1.0));
  s.spindle(direction(c.spindle_direction));
  s.feedTo(c.bottom, c.feed);
  s.dwell();
  s.spindle(K::SpindleOrient);
  s.rapid(shifted(s.at(), c.shift, 1.0));
  s.rapidTo(c.initial);
  s.rapid(shifted(s.at(), c.shift, -1.0));
  s.spindle(direction(c.spindle_direction));
}

}  // namespace

std::vector<ir::Operation> expandHoleCycle(const ir::HoleCycle& c, int axis_count) {
  std::vector<ir::Operation> ops;
  expandHoleCycle(c, axis_count, [&ops](ir::Operation&& op) { ops.push_back(std::move(op)); });
  return ops;
}

void expandHoleCycle(const ir::HoleCycle& c, int axis_count, const OperationEmitter& emit) {
  using Kind = ir::HoleCycle::Kind;
  Sequence s(c, axis_count, emit);
  // 1. Positioning in the plane (the drilling axis stays where it is).
  if (c.positioning_by_feed)
    s.feed(c.hole, c.feed);
  else
    s.rapid(c.hole);
  if (c.kind == Kind::BackBore) {
    backBore(s, c);
    return;
  }
  // 2. Rapid to R.
  s.rapidTo(c.r_level);
  const double level = c.return_to_r ? c.r_level : c.initial;
  // 3.-4. Into the hole and the actions at the bottom; 5.-6. the way back.
  switch (c.kind) {
    case Kind::HighSpeedPeck:
    case Kind::Peck:
      pecks(s, c);
      s.dwell();
      s.rapidTo(level);
      break;
    case Kind::Tap:
      if (c.peck > 0)
        tapPecks(s, c);
      else
        s.feedTo(c.bottom, c.feed);
      s.dwell();
      s.spindle(direction(-c.spindle_direction));
      s.feedTo(c.r_level, c.retract_feed);
      if (c.dwell_at_r) s.dwell();
      s.spindle(direction(c.spindle_direction));
      s.rapidTo(level);
      break;
    case Kind::FineBore:
      s.feedTo(c.bottom, c.feed);
      s.dwell();
      s.spindle(K::SpindleOrient);
      s.rapid(shifted(s.at(), c.shift, 1.0));
      s.rapidTo(level);
      s.rapid(shifted(s.at(), c.shift, -1.0));
      s.spindle(direction(c.spindle_direction));
      break;
    case Kind::BackBore: break;  // above
    case Kind::Drill:
      s.feedTo(c.bottom, feedFrom(c, feedStart(s, c)));
      s.dwell();
      if (c.stop_spindle_at_bottom) s.spindle(K::SpindleStop);
      if (c.program_stop_at_bottom) s.spindle(K::ProgramStop);  // G88: the manual moves
      if (c.feed_out) s.feedTo(c.r_level, c.retract_feed);
      s.rapidTo(level);
      if (c.stop_spindle_at_bottom) s.spindle(direction(c.spindle_direction));
      break;
  }
}

void CycleExpansionPass::accept(ir::Block&& block) {
  bool any = false;
  for (const ir::Operation& op : block.ops) any |= std::holds_alternative<ir::HoleCycle>(op);
  if (!any) {
    next_.accept(std::move(block));
    return;
  }
  // The operations go on in blocks of at most kMaxOperations, each with the block's modal state
  // and frame: memory stays flat however many holes (K) and pecks a block has. The corner
  // request, if any, belongs to the block's end: the last part.
  ir::Operations source = std::move(block.ops);
  block.ops.clear();
  ir::Block header = block;
  header.corner.reset();
  auto add = [&](ir::Operation&& op) {
    if (block.ops.size() >= kMaxOperations) {
      ir::Block part = header;
      part.ops = std::move(block.ops);
      block.ops.clear();
      next_.accept(std::move(part));
    }
    block.ops.push_back(std::move(op));
  };
  for (ir::Operation& op : source) {
    if (const auto* c = std::get_if<ir::HoleCycle>(&op))
      expandHoleCycle(*c, axis_count_, add);
    else
      add(std::move(op));
  }
  next_.accept(std::move(block));
}

}  // namespace ncc::passes
