#include "ncc/passes/lowering.h"

#include <cmath>
#include <numbers>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "arc_geometry.h"
#include "block_words.h"
#include "controller_state.h"
#include "lowering_settings.h"

namespace ncc::passes {

namespace {

constexpr double kSamePoint = 1e-9;     // mm: "end equals start"
constexpr double kPositionCheck = 1e-6; // mm: G27 reference position check

std::string mm(double v) { return absl::StrFormat("%.3f", v); }

ir::Frame frameOf(const ControllerState& cs, const DialectBehaviour& b) {
  ir::Frame f;
  for (int i = 0; i < kMaxAxes; ++i) f.work_offset[i] = cs.work_value[i] + cs.external[i];
  AxisValues local = cs.local;
  if (b.local_shift_per_work_offset) {
    auto it = cs.local_by_work.find(cs.work_name);
    local = it == cs.local_by_work.end() ? AxisValues{} : it->second;
  }
  for (int i = 0; i < kMaxAxes; ++i) f.shift[i] = cs.g92[i] + local[i];
  if (cs.tool_length_axis >= 0) f.tool_length[cs.tool_length_axis] = cs.tool_length;
  return f;
}

AxisValues& localOf(ControllerState& cs, const DialectBehaviour& b) {
  return b.local_shift_per_work_offset ? cs.local_by_work[cs.work_name] : cs.local;
}

}  // namespace

// Everything lowering keeps between blocks.
struct LoweringCore {
  LoweringOptions options;
  DiagnosticEngine& diags;
  ir::BlockSink& out;
  MachineConfig fallback_machine;
  const MachineConfig* machine = nullptr;
  const DialectTable* table = nullptr;
  LoweringSettings settings;
  ControllerState cs;
  OffsetTables tables;
  bool reported_dialect = false;

  LoweringCore(LoweringOptions o, DiagnosticEngine& d, ir::BlockSink& s)
      : options(std::move(o)), diags(d), out(s) {
    if (!options.machine) fallback_machine = defaultMachine();
    machine = options.machine ? options.machine : &fallback_machine;
    table = dialectTable(options.dialect);
    if (!table) return;
    settings = LoweringSettings::resolve(*table, *machine);
    tables.work = machine->work_offsets;
    tables.length = machine->tool_offsets.length;
    tables.radius = machine->tool_offsets.radius;
    powerOn();
  }

  // The power-on state: the table's '*' codes, overridden by the reset_* parameters.
  void powerOn() {
    ir::Modal& m = cs.modal;
    m.units = settings.reset_unit == "G20" ? ir::Units::Inch : ir::Units::Millimetre;
    m.plane = settings.reset_plane == "G18"   ? ir::Plane::ZX
              : settings.reset_plane == "G19" ? ir::Plane::YZ
                                              : ir::Plane::XY;
    cs.motion = settings.reset_motion == "G01" ? GAction::Linear : GAction::Rapid;
    if (const GCodeEntry* e = table->powerOnDefault(GGroup::Distance))
      m.distance = e->action == GAction::Incremental ? ir::DistanceMode::Incremental
                                                     : ir::DistanceMode::Absolute;
    if (const GCodeEntry* e = table->powerOnDefault(GGroup::FeedMode))
      m.feed_mode = e->action == GAction::PerRevolution ? ir::FeedMode::PerRevolution
                                                        : ir::FeedMode::PerMinute;
    m.path = ir::PathControl::Continuous;
    m.work_offset = "G54";
    cs.work_name = "G54";
    cs.work_value = tables.workOffset("G54");
    cs.position = machine->start_position;
  }
};

struct Lowering::State : LoweringCore {
  using LoweringCore::LoweringCore;
};

namespace {

// Lowers one block on a copy of the controller state.
class BlockLowering {
 public:
  BlockLowering(LoweringCore& st, const ast::Block& block)
      : st_(st), block_(block), table_(*st.table), b_(table_.behaviour), set_(st.settings),
        next_(st.cs) {}

  LowerResult run() {
    LowerResult result;
    DecodeContext ctx{table_, *st_.machine, set_.policy, st_.cs.modal.distance, st_.diags};
    auto decoded = decodeBlock(block_, ctx);
    if (!decoded) return result;
    d_ = std::move(*decoded);

    applyModalCodes(result);
    applyFeed();
    applyLengthOffset();
    applyToolWords();
    if (failed_) return result;
    if (d_.one_shot) oneShot();
    else motion();
    machineFunctions(result);
    checkUnused();
    if (failed_) return LowerResult{};
    commit();
    return result;
  }

 private:
  // ---- diagnostics and values -------------------------------------------------------------
  void fail(Alarm a, SourceLocation loc, std::string message) {
    st_.diags.error(std::string(table_.alarm(a)), loc, std::move(message));
    failed_ = true;
  }

  std::optional<int64_t> integer(const WordValue& w) {
    if (w.point && b_.integer_point_is_error) {
      fail(Alarm::DecimalPointNotAllowed, w.loc,
           absl::StrCat("address ", w.address, " takes an integer; a decimal point is not allowed"));
      return std::nullopt;
    }
    return static_cast<int64_t>(std::trunc(w.value));
  }

  bool isRotary(int axis) const {
    return axis < st_.machine->axisCount() && st_.machine->axes[axis].kind == AxisKind::Rotary;
  }
  double axisValue(int axis, const WordValue& w) const {
    return isRotary(axis) ? set_.values.rotary(w.value, w.point)
                          : set_.values.linear(w.value, w.point, next_.modal.units);
  }
  double lengthValue(const WordValue& w) const {
    return set_.values.linear(w.value, w.point, next_.modal.units);
  }
  int axisCount() const { return std::min(st_.machine->axisCount(), kMaxAxes); }
  int axisNamed(const char* name) const { return st_.machine->axisIndex(name); }

  AxisMask namedAxes() const {
    AxisMask mask = 0;
    for (int i = 0; i < axisCount(); ++i)
      if (d_.axes[i]) mask |= AxisMask(1u << i);
    return mask;
  }

  SourceLocation motionLoc() const {
    if (const auto& g = d_.group(GGroup::Motion)) return g->loc;
    if (d_.first_axis_loc) return *d_.first_axis_loc;
    return block_.loc;
  }

  bool samePosition(const AxisValues& a, const AxisValues& b) const {
    for (int i = 0; i < axisCount(); ++i)
      if (std::fabs(a[i] - b[i]) > kSamePoint) return false;
    return true;
  }

  AxisValues toMachine(const AxisValues& work, const ir::Frame& f) const {
    AxisValues m{};
    AxisValues t = f.total();
    for (int i = 0; i < axisCount(); ++i) m[i] = work[i] + t[i];
    return m;
  }

  // The work position of the commanded point under the block's new frame; the length axis
  // keeps its old work coordinate when a length change is to move it (G43 H alone).
  AxisValues baseWork() const {
    AxisValues t = frameOf(next_, b_).total(), w{};
    for (int i = 0; i < axisCount(); ++i) w[i] = next_.position[i] - t[i];
    if (length_delta_axis_ >= 0 && !d_.axes[length_delta_axis_])
      w[length_delta_axis_] += length_delta_;
    return w;
  }

  // Work-space targets: programmed axes absolute or incremental per word, others unchanged.
  AxisValues workTargets(const AxisValues& base) const {
    AxisValues t = base;
    for (int i = 0; i < axisCount(); ++i) {
      if (!d_.axes[i]) continue;
      double v = axisValue(i, *d_.axes[i]);
      t[i] = d_.axes[i]->mode == ir::DistanceMode::Absolute ? v : base[i] + v;
    }
    return t;
  }

  // ---- modal codes --------------------------------------------------------------------------
  void applyModalCodes(LowerResult& result) {
    ir::Modal& m = next_.modal;
    auto action = [&](GGroup g) -> std::optional<GAction> {
      if (const auto& w = d_.group(g)) return w->entry->action;
      return std::nullopt;
    };
    if (auto a = action(GGroup::Motion)) next_.motion = *a;
    if (auto a = action(GGroup::Plane))
      m.plane = *a == GAction::PlaneXY ? ir::Plane::XY
                : *a == GAction::PlaneZX ? ir::Plane::ZX : ir::Plane::YZ;
    if (auto a = action(GGroup::Distance))
      m.distance = *a == GAction::Absolute ? ir::DistanceMode::Absolute
                                           : ir::DistanceMode::Incremental;
    if (auto a = action(GGroup::FeedMode))
      m.feed_mode = *a == GAction::PerMinute       ? ir::FeedMode::PerMinute
                    : *a == GAction::PerRevolution ? ir::FeedMode::PerRevolution
                                                   : ir::FeedMode::InverseTime;
    if (auto a = action(GGroup::Units))
      m.units = *a == GAction::Inch ? ir::Units::Inch : ir::Units::Millimetre;
    if (auto a = action(GGroup::PathControl))
      m.path = *a == GAction::ExactStopMode    ? ir::PathControl::ExactStop
               : *a == GAction::CornerOverride ? ir::PathControl::CornerOverride
               : *a == GAction::TappingMode    ? ir::PathControl::Tapping
                                               : ir::PathControl::Continuous;
    if (auto a = action(GGroup::Language))
      result.switch_language =
          *a == GAction::LanguageDin ? frontend::Language::Din : frontend::Language::Iso;
    if (const auto& w = d_.group(GGroup::WorkOffset)) selectWorkOffset(*w);
  }

  std::string extendedName(int64_t n) const {
    return absl::StrCat(b_.extended_offset_is_g54_p ? "G54P" : "G54.1P", n);
  }
  bool isExtended(const std::string& name) const {
    return name.rfind("G54P", 0) == 0 || name.rfind("G54.1P", 0) == 0;
  }

  // Whether the one-shot code of the block reads P itself.
  bool oneShotTakesP() const {
    if (!d_.one_shot) return false;
    GAction a = d_.one_shot->entry->action;
    return a == GAction::Dwell || a == GAction::DataSet || a == GAction::ReferenceReturnN ||
           a == GAction::ReferenceCheck;
  }

  void selectWorkOffset(const GWord& w) {
    const GCodeEntry& e = *w.entry;
    std::string name = gCodeName(e.code10);
    bool extended = e.action == GAction::WorkOffsetExtended ||
                    (b_.extended_offset_is_g54_p && e.work_index == 1 && d_.p && !oneShotTakesP());
    if (extended) {
      if (!d_.p) {
        fail(Alarm::ExtendedOffsetNumber, w.loc,
             absl::StrCat(name, " needs P1-P", b_.extended_offset_count));
        return;
      }
      used_p_ = true;
      auto n = integer(*d_.p);
      if (!n) return;
      if (*n < 1 || *n > b_.extended_offset_count) {
        fail(Alarm::ExtendedOffsetNumber, d_.p->loc,
             absl::StrCat("P", *n, " is out of range: ", name, " takes P1-P",
                          b_.extended_offset_count));
        return;
      }
      name = extendedName(*n);
    }
    next_.work_name = name;
    next_.work_value = st_.tables.workOffset(name);
    next_.modal.work_offset = name;
  }

  // ---- F, H, S/T/D --------------------------------------------------------------------------
  void applyFeed() {
    if (!d_.f) return;
    const WordValue& f = *d_.f;
    ir::Modal& m = next_.modal;
    if (f.value < 0) {
      fail(Alarm::ValueOutOfRange, f.loc, "a feed rate cannot be negative");
      return;
    }
    // F1-digit feed (Siemens MD22920): F1-F9 select presets, F0 selects rapid traverse.
    if (set_.f1_digit && !f.point && f.value <= 9 && f.value == std::trunc(f.value)) {
      int n = static_cast<int>(f.value);
      if (n == 0) {
        next_.motion = GAction::Rapid;
        return;
      }
      m.feed = n <= static_cast<int>(set_.f1_feeds.size()) ? set_.f1_feeds[n - 1] : 0.0;
      next_.feed_programmed = m.feed > 0;
      return;
    }
    m.feed = set_.values.feed(f.value, f.point, m.units, m.feed_mode);
    next_.feed_programmed = m.feed > 0;
  }

  int lengthAxis() const {
    if (set_.tool_length_mode == "B") {
      switch (next_.modal.plane) {
        case ir::Plane::XY: return axisNamed("Z");
        case ir::Plane::ZX: return axisNamed("Y");
        case ir::Plane::YZ: return axisNamed("X");
      }
    }
    return axisNamed("Z");
  }

  void applyLengthOffset() {
    const auto& g = d_.group(GGroup::LengthComp);
    if (d_.h) {
      auto n = integer(*d_.h);
      if (!n) return;
      if (*n < 0 || *n > set_.offset_count) {
        fail(Alarm::OffsetNumberOutOfRange, d_.h->loc,
             absl::StrCat("H", *n, " is out of range: offset numbers are 1-", set_.offset_count,
                          " (offset_count)"));
        return;
      }
      next_.h_selected = static_cast<int>(*n);
    }
    if (!g && !d_.h) return;
    int sign = next_.modal.length_offset_sign;
    if (g) {
      GAction a = g->entry->action;
      sign = a == GAction::LengthPlus ? 1 : a == GAction::LengthMinus ? -1 : 0;
    }
    if (sign != 0 && set_.tool_length_mode == "C") {
      fail(Alarm::CodeNotSupported, g ? g->loc : d_.h->loc,
           "tool length mode C (offset on the axis programmed with H) is not supported yet");
      return;
    }
    int axis = -1;
    double length = 0.0;
    if (sign != 0) {
      axis = lengthAxis();
      if (axis < 0) {
        fail(Alarm::AxisMissing, g ? g->loc : d_.h->loc,
             "tool length compensation needs the length axis, which the machine does not have");
        return;
      }
      length = sign * st_.tables.toolLength(next_.h_selected);
    }
    double old = st_.cs.tool_length_axis >= 0 ? st_.cs.tool_length : 0.0;
    int changed_axis = axis >= 0 ? axis : st_.cs.tool_length_axis;
    if (set_.length_change_moves && changed_axis >= 0 && length != old) {
      length_delta_axis_ = changed_axis;
      length_delta_ = length - old;
    }
    next_.tool_length_axis = axis;
    next_.tool_length = length;
    next_.modal.length_offset_sign = sign;
    next_.modal.length_offset_h = sign != 0 ? next_.h_selected : 0;
  }

  void applyToolWords() {
    if (d_.d) {
      auto n = integer(*d_.d);
      if (n && (*n < 0 || *n > set_.offset_count))
        fail(Alarm::OffsetNumberOutOfRange, d_.d->loc,
             absl::StrCat("D", *n, " is out of range: offset numbers are 1-", set_.offset_count,
                          " (offset_count)"));
      else if (n) next_.d_selected = static_cast<int>(*n);
    }
    if (d_.s) {
      auto n = integer(*d_.s);
      if (n && *n < 0) fail(Alarm::ValueOutOfRange, d_.s->loc, "a spindle speed cannot be negative");
      else if (n) next_.modal.spindle_speed = static_cast<double>(*n);
    }
    for (size_t i = 0; i < d_.t.size(); ++i) {
      auto n = integer(d_.t[i]);
      if (n && *n < 0) fail(Alarm::ValueOutOfRange, d_.t[i].loc, "a tool number cannot be negative");
      else if (n && i == 0) next_.modal.tool = static_cast<int>(*n);
    }
  }

  // ---- motion -------------------------------------------------------------------------------
  bool checkFeed(bool inverse_time_needs_f) {
    const ir::Modal& m = next_.modal;
    if (m.feed_mode == ir::FeedMode::InverseTime) {
      if (inverse_time_needs_f && (!d_.f || d_.f->value <= 0)) {
        fail(Alarm::FeedMissing, motionLoc(),
             "no feed rate: in inverse time feed (G93) every cutting block needs its own F");
        return false;
      }
      return true;
    }
    if (!next_.feed_programmed) {
      fail(Alarm::FeedMissing, motionLoc(),
           "no feed rate: a cutting move needs an F word and none has been programmed");
      return false;
    }
    return true;
  }

  // Feed of a cutting op in the IR unit: inverse time (1/min) becomes mm/min over `length`.
  double opFeed(double length) const {
    const ir::Modal& m = next_.modal;
    if (m.feed_mode == ir::FeedMode::InverseTime) return m.feed * length;
    return m.feed;
  }

  double pathLength(const AxisValues& from, const AxisValues& to) const {
    double s = 0.0;
    for (int i = 0; i < axisCount(); ++i) s += (to[i] - from[i]) * (to[i] - from[i]);
    return std::sqrt(s);
  }

  void motion() {
    ir::Frame frame = frameOf(next_, b_);
    AxisValues start = baseWork();
    AxisValues target = workTargets(start);
    AxisValues to_machine = toMachine(target, frame);
    bool moves = !samePosition(to_machine, next_.position);
    bool feed_per_rev = next_.modal.feed_mode == ir::FeedMode::PerRevolution;
    GAction kind = next_.motion;
    bool arc_mode = kind == GAction::ArcCW || kind == GAction::ArcCCW;
    // A block with no arc words in an arc mode (G43 H alone) can only move the length axis:
    // that move is a straight line.
    if (arc_mode && !d_.anyAxis() && !d_.i && !d_.j && !d_.k && !d_.r) kind = GAction::Linear;
    switch (kind) {
      case GAction::Rapid:
        if (moves) ops_.push_back(ir::Rapid{target, ir::Space::Work, set_.rapid_type});
        break;
      case GAction::Linear:
        if (!moves) break;
        if (!checkFeed(true)) return;
        ops_.push_back(ir::Linear{target, ir::Space::Work,
                                  opFeed(pathLength(next_.position, to_machine)), feed_per_rev});
        break;
      case GAction::ArcCW:
      case GAction::ArcCCW:
        if (!arc(start, target, frame)) return;
        break;
      default:
        break;
    }
    next_.position = to_machine;
  }

  struct PlaneAxes {
    int a, b;                   // plane axes (first, second)
    const std::optional<WordValue>* wa;  // centre words on them
    const std::optional<WordValue>* wb;
    const std::optional<WordValue>* normal;  // the third centre word
    const char* names;          // "XY", "ZX", "YZ"
    const char* code;           // "G17"...
  };

  PlaneAxes planeAxes() const {
    switch (next_.modal.plane) {
      case ir::Plane::ZX: return {axisNamed("Z"), axisNamed("X"), &d_.k, &d_.i, &d_.j, "ZX", "G18"};
      case ir::Plane::YZ: return {axisNamed("Y"), axisNamed("Z"), &d_.j, &d_.k, &d_.i, "YZ", "G19"};
      case ir::Plane::XY: break;
    }
    return {axisNamed("X"), axisNamed("Y"), &d_.i, &d_.j, &d_.k, "XY", "G17"};
  }

  bool arc(const AxisValues& start, const AxisValues& target, const ir::Frame& frame) {
    bool cw = next_.motion == GAction::ArcCW;
    PlaneAxes pl = planeAxes();
    if (pl.a < 0 || pl.b < 0) {
      fail(Alarm::AxisMissing, motionLoc(),
           absl::StrCat("an arc in the ", pl.names, " plane (", pl.code,
                        ") needs both plane axes, which the machine does not have"));
      return false;
    }
    PlanePoint s{start[pl.a], start[pl.b]}, e{target[pl.a], target[pl.b]};
    bool end_given = d_.axes[pl.a] || d_.axes[pl.b];
    bool closed = distance(s, e) <= kSamePoint;
    bool has_centre = pl.wa->has_value() || pl.wb->has_value();
    used_ijk_ = true;  // centre words are read (or, next to R, ignored by rule) here
    PlanePoint c;
    if (d_.r && end_given && !closed) {
      // R beats I/J/K when an end point is given (Mazak §6-6, FANUC).
      used_r_ = true;
      double r = lengthValue(*d_.r);
      if (r == 0.0) {
        fail(Alarm::ArcDegenerate, d_.r->loc, "an arc radius R cannot be 0");
        return false;
      }
      auto centre = centreFromRadius(s, e, r, cw);
      if (!centre) {
        fail(Alarm::ArcRadiusTooSmall, d_.r->loc,
             absl::StrCat("no arc of radius ", mm(std::fabs(r)), " joins the start and end points ",
                          mm(distance(s, e)), " apart (the radius must be at least half the chord)"));
        return false;
      }
      c = *centre;
    } else if (has_centre) {
      if (pl.normal->has_value()) {
        fail(Alarm::AddressWithoutMeaning, (*pl.normal)->loc,
             absl::StrCat("address ", (*pl.normal)->address, " is not a centre word of the ",
                          pl.names, " plane (", pl.code, ")"));
        return false;
      }
      used_r_ = true;  // an I/J/K full circle ignores R (Mazak §6-6)
      c = {s.a + (pl.wa->has_value() ? lengthValue(**pl.wa) : 0.0),
           s.b + (pl.wb->has_value() ? lengthValue(**pl.wb) : 0.0)};
      double rs = distance(s, c), re = distance(e, c);
      if (rs <= kSamePoint) {
        fail(Alarm::ArcDegenerate, motionLoc(), "the arc centre is at the start point");
        return false;
      }
      if (std::fabs(rs - re) > set_.arc_tolerance) {
        fail(Alarm::ArcRadiusMismatch, motionLoc(),
             absl::StrCat("the end point is not on the arc: start radius ", mm(rs),
                          ", end radius ", mm(re), " (difference above arc_radius_tolerance ",
                          mm(set_.arc_tolerance), ")"));
        return false;
      }
    } else if (d_.r) {
      // R with no end point or end = start: an R full circle does not move (Mazak §6-6).
      used_r_ = true;
      if (!samePosition(toMachine(target, frame), next_.position))
        fail(Alarm::ArcDegenerate, d_.r->loc,
             "an R arc needs an end point in the plane different from the start point");
      return !failed_;
    } else {
      fail(Alarm::ArcCentreMissing, motionLoc(),
           absl::StrCat(cw ? "G02" : "G03", " needs the centre (I/J/K) or the radius (R)"));
      return false;
    }
    if (!checkFeed(true)) return false;
    ir::Arc a;
    a.to = target;
    a.center = target;
    a.center[pl.a] = c.a;
    a.center[pl.b] = c.b;
    a.space = ir::Space::Work;
    a.plane = next_.modal.plane;
    a.clockwise = cw;
    a.feed_per_rev = next_.modal.feed_mode == ir::FeedMode::PerRevolution;
    if (next_.modal.feed_mode == ir::FeedMode::InverseTime) {
      double r = distance(s, c);
      double sweep = std::atan2(s.b - c.b, s.a - c.a) - std::atan2(e.b - c.b, e.a - c.a);
      if (!cw) sweep = -sweep;
      while (sweep <= 0) sweep += 2 * std::numbers::pi;
      double plane_len = r * sweep;
      double lin = 0.0;
      for (int i = 0; i < axisCount(); ++i)
        if (i != pl.a && i != pl.b) lin += (target[i] - start[i]) * (target[i] - start[i]);
      a.feed = b_.inverse_time_arc_per_radius ? next_.modal.feed * r
                                              : next_.modal.feed * std::sqrt(plane_len * plane_len + lin);
    } else {
      a.feed = next_.modal.feed;
    }
    ops_.push_back(a);
    return true;
  }

  // ---- one-shot codes -----------------------------------------------------------------------
  void oneShot() {
    const GWord& g = *d_.one_shot;
    switch (g.entry->action) {
      case GAction::Dwell: return dwell(g);
      case GAction::DataSet: return dataSet(g);
      case GAction::ReferenceCheck: return referenceCheck(g);
      case GAction::ReferenceReturn: return referenceReturn(g, 1);
      case GAction::ReferenceReturnN: return referenceReturn(g, referenceNumber(g, 2));
      case GAction::LocalShift: return localShift(g);
      case GAction::MachineCoordinates: return machineMove(g);
      case GAction::SetShift: return setShift();
      case GAction::ResetShift: return resetShift(g);
      default: return;
    }
  }

  void dwell(const GWord& g) {
    int x = axisNamed("X");
    std::optional<WordValue> xw = x >= 0 ? d_.axes[x] : std::nullopt;
    for (int i = 0; i < axisCount(); ++i) {
      if (d_.axes[i] && i != x) {
        fail(Alarm::AddressWithoutMeaning, d_.axes[i]->loc,
             absl::StrCat("address ", d_.axes[i]->address, " has no meaning in a dwell (G04) block"));
        return;
      }
    }
    if (xw && d_.p) {
      fail(Alarm::AddressWithoutMeaning, d_.p->loc, "G04 takes the time in X or in P, not both");
      return;
    }
    double value = 0.0;
    if (d_.p) {
      used_p_ = true;
      if (d_.p->point && b_.dwell_p_point_is_error) {
        fail(Alarm::DecimalPointNotAllowed, d_.p->loc,
             "G04 P is in milliseconds and takes no decimal point");
        return;
      }
      value = std::trunc(d_.p->value) / 1000.0;  // ms, fraction ignored
    } else if (xw) {
      value = set_.values.dwellX(xw->value, xw->point);
    } else {
      return;  // G04 alone: no dwell
    }
    if (value < 0) {
      fail(Alarm::ValueOutOfRange, g.loc, "a dwell time cannot be negative");
      return;
    }
    bool revs = set_.dwell_revolutions && next_.modal.feed_mode == ir::FeedMode::PerRevolution;
    ops_.push_back(ir::Dwell{value, revs});
  }

  int referenceNumber(const GWord& g, int fallback) {
    if (!d_.p) return fallback;
    used_p_ = true;
    auto n = integer(*d_.p);
    if (!n) return fallback;
    if (*n >= 2 && *n <= 4) return static_cast<int>(*n);
    if (g.entry->action == GAction::ReferenceCheck && *n == 1) return 1;
    if (b_.g30_p == DialectBehaviour::G30P::OtherMeansSecond) return 2;
    fail(Alarm::ReferencePointNumber, d_.p->loc,
         absl::StrCat("P", *n, ": ", gCodeName(g.entry->code10), " takes P2, P3 or P4"));
    return fallback;
  }

  // G28 / G30: rapid to the intermediate point, then the named axes to the reference point;
  // both legs in machine coordinates (the frame would be wrong for the second).
  void referenceReturn(const GWord&, int n) {
    if (failed_) return;
    ir::Frame frame = frameOf(next_, b_);
    AxisValues via = toMachine(workTargets(baseWork()), frame);
    if (!samePosition(via, next_.position))
      ops_.push_back(ir::Rapid{via, ir::Space::Machine, set_.rapid_type});
    AxisValues home = via;
    for (int i = 0; i < axisCount(); ++i)
      if (d_.axes[i]) home[i] = set_.reference[n - 1][i];
    if (!samePosition(home, via))
      ops_.push_back(ir::Rapid{home, ir::Space::Machine, ir::RapidType::PerAxis});
    next_.position = home;
    if (b_.reference_return_cancels_length && namedAxes() != 0 &&
        next_.modal.length_offset_sign != 0) {
      next_.modal.length_offset_sign = 0;
      next_.modal.length_offset_h = 0;
      next_.tool_length_axis = -1;
      next_.tool_length = 0.0;
    }
  }

  void referenceCheck(const GWord& g) {
    int n = referenceNumber(g, 1);
    if (failed_) return;
    ir::Frame frame = frameOf(next_, b_);
    AxisValues target = workTargets(baseWork());
    AxisValues reached = toMachine(target, frame);
    for (int i = 0; i < axisCount(); ++i) {
      if (!d_.axes[i]) continue;
      double ref = set_.reference[n - 1][i];
      if (std::fabs(reached[i] - ref) > kPositionCheck) {
        fail(Alarm::ReferenceCheckFailed, d_.axes[i]->loc,
             absl::StrCat("G27: ", st_.machine->axes[i].name, " reaches machine position ",
                          mm(reached[i]), ", not reference point ", n, " (", mm(ref), ")"));
        return;
      }
    }
    if (!samePosition(reached, next_.position))
      ops_.push_back(ir::Rapid{target, ir::Space::Work, set_.rapid_type});
    ops_.push_back(ir::ReferenceCheck{reached, namedAxes(), n});
    next_.position = reached;
  }

  void machineMove(const GWord& g) {
    AxisValues target = next_.position;
    for (int i = 0; i < axisCount(); ++i) {
      if (!d_.axes[i]) continue;
      double v = axisValue(i, *d_.axes[i]);
      if (d_.axes[i]->mode == ir::DistanceMode::Incremental) {
        switch (b_.g53_in_g91) {
          case DialectBehaviour::G53InG91::Incremental: v += next_.position[i]; break;
          case DialectBehaviour::G53InG91::Absolute: break;
          case DialectBehaviour::G53InG91::Ignored:
            st_.diags.warning(std::string(table_.alarm(Alarm::G53Incremental)), g.loc,
                              "G53 in incremental mode (G91) is ignored");
            return;
        }
      }
      target[i] = v;
    }
    if (!samePosition(target, next_.position))
      ops_.push_back(ir::Rapid{target, ir::Space::Machine, set_.rapid_type});
    next_.position = target;
  }

  void localShift(const GWord& g) {
    if (b_.local_shift_in_extended_is_error && isExtended(next_.work_name)) {
      fail(Alarm::LocalShiftInExtended, g.loc,
           absl::StrCat("G52 cannot be given while ", next_.work_name, " is selected"));
      return;
    }
    AxisValues& local = localOf(next_, b_);
    for (int i = 0; i < axisCount(); ++i) {
      if (!d_.axes[i]) continue;
      double v = axisValue(i, *d_.axes[i]);
      local[i] = d_.axes[i]->mode == ir::DistanceMode::Absolute ? v : local[i] + v;
    }
  }

  // G92: the current point takes the programmed coordinates (G91: current + value).
  void setShift() {
    AxisValues current = baseWork();
    ir::Frame without = frameOf(next_, b_);
    for (int i = 0; i < axisCount(); ++i) {
      if (!d_.axes[i]) continue;
      double v = axisValue(i, *d_.axes[i]);
      double w = d_.axes[i]->mode == ir::DistanceMode::Absolute ? v : current[i] + v;
      double others = without.total()[i] - next_.g92[i];
      next_.g92[i] = next_.position[i] - others - w;
    }
  }

  void resetShift(const GWord&) {
    AxisValues& local = localOf(next_, b_);
    for (int i = 0; i < axisCount(); ++i) {
      if (!d_.axes[i]) continue;
      if (axisValue(i, *d_.axes[i]) != 0.0) {
        fail(Alarm::ValueOutOfRange, d_.axes[i]->loc,
             absl::StrCat("G92.1 resets an axis with the value 0; ", d_.axes[i]->address,
                          " is given another value"));
        return;
      }
      next_.g92[i] = 0.0;
      local[i] = 0.0;
    }
  }

  void dataSet(const GWord& g) {
    if (!d_.l) {
      fail(Alarm::DataSetFormat, g.loc, "G10 needs L2, L10-L13 or L20");
      return;
    }
    used_l_ = true;
    auto l = integer(*d_.l);
    if (!l) return;
    bool add = next_.modal.distance == ir::DistanceMode::Incremental;
    if (*l == 2 || *l == 20) return dataSetWork(g, static_cast<int>(*l), add);
    if (*l >= 10 && *l <= 13) return dataSetRegister(g, static_cast<int>(*l), add);
    fail(Alarm::DataSetFormat, d_.l->loc,
         absl::StrCat("G10 L", *l, " is not supported; ncc knows L2, L10-L13 and L20"));
  }

  void dataSetWork(const GWord& g, int l, bool add) {
    TableWrite w;
    w.add = add;
    if (l == 2) {
      int64_t p = next_.last_g10_l2_p;
      if (d_.p) {
        used_p_ = true;
        auto n = integer(*d_.p);
        if (!n) return;
        p = *n;
      } else if (!b_.g10_l2_p_lenient) {
        fail(Alarm::DataSetFormat, g.loc, "G10 L2 needs P0-P6 (P0 external, P1-P6 G54-G59)");
        return;
      }
      if (p < 0 || p > 6) {
        if (!b_.g10_l2_p_lenient) {
          fail(Alarm::DataSetFormat, d_.p->loc,
               absl::StrCat("P", p, " is out of range: G10 L2 takes P0-P6"));
          return;
        }
        p = 1;  // Mazak §12-6: outside 0-6 is treated as 1
      }
      next_.last_g10_l2_p = static_cast<int>(p);
      if (p == 0) w.target = TableWrite::Target::External;
      else w.work_name = gCodeName(530 + 10 * static_cast<int>(p));
    } else {
      std::string name;
      if (d_.p) {
        used_p_ = true;
        auto n = integer(*d_.p);
        if (!n) return;
        if (*n < 1 || *n > b_.extended_offset_count) {
          fail(Alarm::ExtendedOffsetNumber, d_.p->loc,
               absl::StrCat("P", *n, " is out of range: G10 L20 takes P1-P",
                            b_.extended_offset_count));
          return;
        }
        name = extendedName(*n);
      } else if (isExtended(next_.work_name)) {
        name = next_.work_name;
      } else {
        fail(Alarm::ExtendedOffsetRequired, g.loc,
             absl::StrCat("G10 L20 without P needs an additional work system to be selected (",
                          next_.work_name, " is)"));
        return;
      }
      w.work_name = name;
    }
    for (int i = 0; i < axisCount(); ++i) {
      if (!d_.axes[i]) continue;
      w.values[i] = axisValue(i, *d_.axes[i]);
      w.axes |= AxisMask(1u << i);
    }
    if (w.target == TableWrite::Target::External) {
      for (int i = 0; i < axisCount(); ++i)
        if (w.axes & (1u << i)) next_.external[i] = add ? next_.external[i] + w.values[i] : w.values[i];
      return;
    }
    writes_.push_back(std::move(w));
  }

  void dataSetRegister(const GWord& g, int l, bool add) {
    for (int i = 0; i < axisCount(); ++i) {
      if (d_.axes[i]) {
        fail(Alarm::AddressWithoutMeaning, d_.axes[i]->loc,
             absl::StrCat("address ", d_.axes[i]->address, " has no meaning in G10 L", l));
        return;
      }
    }
    if (!d_.p || !d_.r) {
      fail(Alarm::DataSetFormat, g.loc, absl::StrCat("G10 L", l, " needs P (offset number) and R (value)"));
      return;
    }
    used_p_ = used_r_ = true;
    auto n = integer(*d_.p);
    if (!n) return;
    if (*n < 1 || *n > set_.offset_count) {
      fail(Alarm::OffsetNumberOutOfRange, d_.p->loc,
           absl::StrCat("P", *n, " is out of range: offset numbers are 1-", set_.offset_count,
                        " (offset_count)"));
      return;
    }
    TableWrite w;
    w.target = l == 10   ? TableWrite::Target::Length
               : l == 11 ? TableWrite::Target::LengthWear
               : l == 12 ? TableWrite::Target::Radius
                         : TableWrite::Target::RadiusWear;
    w.number = static_cast<int>(*n);
    w.values[0] = set_.values.offset(d_.r->value, d_.r->point, next_.modal.units);
    w.add = add;
    writes_.push_back(std::move(w));
  }

  // ---- words no code of the block reads -----------------------------------------------------
  void checkUnused() {
    if (failed_) return;
    std::string context = d_.one_shot ? gCodeName(d_.one_shot->entry->code10) : "this block";
    auto unused = [&](const std::optional<WordValue>& w, bool used) {
      if (!w || used || failed_) return;
      fail(Alarm::AddressWithoutMeaning, w->loc,
           absl::StrCat("address ", w->address, " has no meaning in ", context));
    };
    bool arc_block = !d_.one_shot && (next_.motion == GAction::ArcCW || next_.motion == GAction::ArcCCW);
    unused(d_.i, used_ijk_ || arc_block);
    unused(d_.j, used_ijk_ || arc_block);
    unused(d_.k, used_ijk_ || arc_block);
    unused(d_.r, used_r_);
    unused(d_.p, used_p_);
    unused(d_.l, used_l_);
  }

  // ---- M, S, T ------------------------------------------------------------------------------
  void machineFunctions(LowerResult& result) {
    using K = ir::MachineFunction::Kind;
    std::vector<WordValue> ms = d_.m;
    if (static_cast<int>(ms.size()) > b_.max_m_codes) {
      if (b_.m_overflow_keeps_last) {
        st_.diags.warning(std::string(table_.alarm(Alarm::TooManyMCodes)), ms.front().loc,
                          absl::StrCat("more than ", b_.max_m_codes,
                                       " M codes in a block: only the last ", b_.max_m_codes,
                                       " are effective"));
        ms.erase(ms.begin(), ms.end() - b_.max_m_codes);
      } else {
        fail(Alarm::TooManyMCodes, ms[b_.max_m_codes].loc,
             absl::StrCat("at most ", b_.max_m_codes, " M codes may be given in a block"));
        return;
      }
    }
    std::vector<ir::Operation> before, after;
    if (d_.s) before.push_back(ir::MachineFunction{K::SpindleSpeed, 0, next_.modal.spindle_speed});
    for (const WordValue& t : d_.t)
      before.push_back(ir::MachineFunction{K::ToolSelect, static_cast<int64_t>(std::trunc(t.value)), 0.0});
    for (const WordValue& w : ms) {
      auto n = integer(w);
      if (!n) return;
      if (*n < 0) {
        fail(Alarm::ValueOutOfRange, w.loc, "an M code cannot be negative");
        return;
      }
      if (set_.macro_m_codes.count(static_cast<int>(*n))) {
        fail(Alarm::CodeNotSupported, w.loc,
             absl::StrCat("M", *n, " calls a macro (m_code_macros), which is not supported yet"));
        return;
      }
      ir::MachineFunction f{K::OtherM, *n, 0.0};
      bool pre = false;
      switch (*n) {
        case 0: f.kind = K::ProgramStop; break;
        case 1: f.kind = K::OptionalStop; break;
        case 2: f.kind = K::ProgramEnd; result.program_end = true; break;
        case 30: f.kind = K::ProgramEndRewind; result.program_end = true; break;
        case 3: f.kind = K::SpindleCW; pre = true; break;
        case 4: f.kind = K::SpindleCCW; pre = true; break;
        case 5: f.kind = K::SpindleStop; break;
        case 6: f.kind = K::ToolChange; pre = true; break;
        case 8: f.kind = K::CoolantOn; pre = true; break;
        case 9: f.kind = K::CoolantOff; break;
        case 19: f.kind = K::SpindleOrient; pre = true; break;
        case 96: case 97:
          fail(Alarm::CodeNotSupported, w.loc, absl::StrCat("M", *n, " (macro interrupt) is not supported yet"));
          return;
        case 98:
          fail(Alarm::CodeNotSupported, w.loc, "M98 (subprogram call) is not supported yet");
          return;
        case 99:
          fail(Alarm::CodeNotSupported, w.loc, "M99 (subprogram return) is not supported yet");
          return;
        default: break;
      }
      (pre ? before : after).push_back(f);
    }
    // Spindle, tool and coolant start before the block's motion; stops, ends and the other
    // (machine-builder) M codes after it.
    before.insert(before.end(), ops_.begin(), ops_.end());
    before.insert(before.end(), after.begin(), after.end());
    ops_ = std::move(before);
  }

  // ---- commit -------------------------------------------------------------------------------
  void commit() {
    OffsetTables& tables = st_.tables;
    for (const TableWrite& w : writes_) {
      auto set = [&](double& slot, double v) { slot = w.add ? slot + v : v; };
      switch (w.target) {
        case TableWrite::Target::Work: {
          AxisValues& stored = tables.work[w.work_name];
          for (int i = 0; i < axisCount(); ++i)
            if (w.axes & (1u << i)) set(stored[i], w.values[i]);
          if (!b_.work_offset_write_on_reselect && w.work_name == next_.work_name)
            next_.work_value = stored;
          break;
        }
        case TableWrite::Target::External: break;  // applied to the state directly
        case TableWrite::Target::Length: set(tables.length[w.number], w.values[0]); break;
        case TableWrite::Target::LengthWear: set(tables.length_wear[w.number], w.values[0]); break;
        case TableWrite::Target::Radius: set(tables.radius[w.number], w.values[0]); break;
        case TableWrite::Target::RadiusWear: set(tables.radius_wear[w.number], w.values[0]); break;
      }
    }
    st_.cs = next_;
    ir::Block out;
    out.loc = block_.loc;
    out.sequence = block_.sequence.value_or(-1);
    out.modal = next_.modal;
    out.modal.work_offset = next_.work_name;
    out.frame = frameOf(next_, b_);
    out.exact_stop = d_.exact_stop.has_value() || next_.modal.path == ir::PathControl::ExactStop;
    out.ops = std::move(ops_);
    st_.out.accept(std::move(out));
  }

  LoweringCore& st_;
  const ast::Block& block_;
  const DialectTable& table_;
  const DialectBehaviour& b_;
  const LoweringSettings& set_;
  ControllerState next_;
  DecodedBlock d_;
  std::vector<ir::Operation> ops_;
  std::vector<TableWrite> writes_;
  int length_delta_axis_ = -1;
  double length_delta_ = 0.0;
  bool used_ijk_ = false, used_r_ = false, used_p_ = false, used_l_ = false;
  bool failed_ = false;
};

}  // namespace

Lowering::Lowering(LoweringOptions options, DiagnosticEngine& diags, ir::BlockSink& out)
    : state_(std::make_unique<State>(std::move(options), diags, out)) {}

Lowering::~Lowering() = default;

LowerResult Lowering::lower(const ast::Block& block) {
  State& st = *state_;
  if (!st.table) {
    if (!st.reported_dialect)
      st.diags.error("NCC2002", block.loc,
                     absl::StrCat("lowering of ", std::string(dialectName(st.options.dialect)),
                                  " programs is not supported yet (fanuc-m, mazak-m and "
                                  "siemens-iso-m are)"));
    st.reported_dialect = true;
    return {};
  }
  if (block.skip_level >= 0) {
    int level = block.skip_level == 0 ? 1 : block.skip_level;
    if ((st.settings.block_skip && level <= 1) || st.settings.skip_levels.count(level)) return {};
  }
  if (block.words.empty() && block.statements.empty()) return {};
  return BlockLowering(st, block).run();
}

void Lowering::finish() { state_->out.finish(); }

}  // namespace ncc::passes
