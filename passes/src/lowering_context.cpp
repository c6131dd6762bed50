// What every lowering concept shares: the frame of a controller state, the state kept between
// blocks (LoweringCore, with the power-on state), and BlockContext's helpers for diagnostics,
// word values and work/machine positions. No G or M code semantics live here.
#include "lowering_context.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace ncc::passes {

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

// ---- LoweringCore ---------------------------------------------------------------------------
LoweringCore::LoweringCore(LoweringOptions o, DiagnosticEngine& d, ir::BlockSink& s)
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

void LoweringCore::powerOn() {
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
    m.feed_mode =
        e->action == GAction::PerRevolution ? ir::FeedMode::PerRevolution : ir::FeedMode::PerMinute;
  m.path = ir::PathControl::Continuous;
  m.work_offset = "G54";
  cs.work_name = "G54";
  cs.work_value = tables.workOffset("G54");
  cs.position = machine->start_position;
}

// ---- BlockContext: diagnostics and values ---------------------------------------------------
void BlockContext::fail(Alarm a, SourceLocation loc, std::string message) {
  core.diags.error(std::string(table.alarm(a)), loc, std::move(message));
  failed = true;
}

std::optional<int64_t> BlockContext::integer(const WordValue& w) {
  if (w.point && behaviour.integer_point_is_error) {
    fail(Alarm::DecimalPointNotAllowed, w.loc,
         absl::StrCat("address ", w.address, " takes an integer; a decimal point is not allowed"));
    return std::nullopt;
  }
  return static_cast<int64_t>(std::trunc(w.value));
}

bool BlockContext::isRotary(int axis) const {
  return axis < core.machine->axisCount() && core.machine->axes[axis].kind == AxisKind::Rotary;
}

double BlockContext::axisValue(int axis, const WordValue& w) const {
  return isRotary(axis) ? settings.values.rotary(w.value, w.point)
                        : settings.values.linear(w.value, w.point, next.modal.units);
}

double BlockContext::lengthValue(const WordValue& w) const {
  return settings.values.linear(w.value, w.point, next.modal.units);
}

int BlockContext::axisCount() const { return std::min(core.machine->axisCount(), kMaxAxes); }

int BlockContext::axisNamed(const char* name) const { return core.machine->axisIndex(name); }

AxisMask BlockContext::namedAxes() const {
  AxisMask mask = 0;
  for (int i = 0; i < axisCount(); ++i)
    if (words.axes[i]) mask |= AxisMask(1u << i);
  return mask;
}

SourceLocation BlockContext::motionLoc() const {
  if (const auto& g = words.group(GGroup::Motion)) return g->loc;
  if (words.first_axis_loc) return *words.first_axis_loc;
  return block.loc;
}

// ---- BlockContext: positions ----------------------------------------------------------------
bool BlockContext::samePosition(const AxisValues& a, const AxisValues& b) const {
  for (int i = 0; i < axisCount(); ++i)
    if (std::fabs(a[i] - b[i]) > kSamePoint) return false;
  return true;
}

AxisValues BlockContext::toMachine(const AxisValues& work, const ir::Frame& f) const {
  AxisValues m{};
  AxisValues t = f.total();
  for (int i = 0; i < axisCount(); ++i) m[i] = work[i] + t[i];
  return m;
}

AxisValues BlockContext::baseWork() const {
  AxisValues t = frameOf(next, behaviour).total(), w{};
  for (int i = 0; i < axisCount(); ++i) w[i] = next.position[i] - t[i];
  if (length_delta_axis >= 0 && !words.axes[length_delta_axis])
    w[length_delta_axis] += length_delta;
  return w;
}

AxisValues BlockContext::workTargets(const AxisValues& base) const {
  AxisValues t = base;
  for (int i = 0; i < axisCount(); ++i) {
    if (!words.axes[i]) continue;
    double v = axisValue(i, *words.axes[i]);
    t[i] = words.axes[i]->mode == ir::DistanceMode::Absolute ? v : base[i] + v;
  }
  return t;
}

}  // namespace ncc::passes
