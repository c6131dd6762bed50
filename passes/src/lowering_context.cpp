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
  static constexpr AxisValues kNone{};
  const AxisValues* local = &cs.local;
  if (b.local_shift_per_work_offset) {
    auto it = cs.local_by_work.find(cs.work_name.view());
    local = it == cs.local_by_work.end() ? &kNone : &it->second;
  }
  for (int i = 0; i < kMaxAxes; ++i) f.shift[i] = cs.g92[i] + (*local)[i];
  if (cs.tool_length_axis >= 0) f.tool_length[cs.tool_length_axis] = cs.tool_length;
  return f;
}

AxisValues& localOf(ControllerState& cs, const DialectBehaviour& b) {
  return b.local_shift_per_work_offset ? cs.local_by_work[cs.work_name.str()] : cs.local;
}

// ---- LoweringCore ---------------------------------------------------------------------------
LoweringCore::LoweringCore(LoweringOptions o, DiagnosticEngine& d, ir::BlockSink& s)
    : options(std::move(o)), diags(d), out(s) {
  if (!options.machine) fallback_machine = defaultMachine();
  machine = options.machine ? options.machine : &fallback_machine;
  const LanguageTables tables_by_language = languageTables(options.dialect);
  for (frontend::Language l : {frontend::Language::Iso, frontend::Language::Din}) {
    LanguageLowering& ll = languages[static_cast<size_t>(l)];
    ll.table = tables_by_language.of(l);
    if (!ll.table) continue;
    ll.addresses.emplace(*ll.table, *machine);
    ll.settings = LoweringSettings::resolve(*ll.table, *machine);
  }
  if (!languages[0].table) return;
  bindLanguage(frontend::Language::Iso);
  for (int s = 0; s < 3; ++s) {
    const int i = machine->axisIndex(std::string(1, "XYZ"[s]));
    xyz[s] = static_cast<int8_t>(i >= 0 && i < kMaxAxes ? i : -1);
  }
  tables.work = {machine->work_offsets.begin(), machine->work_offsets.end()};
  tables.length = machine->tool_offsets.length;
  tables.radius = machine->tool_offsets.radius;
  powerOn();
}

bool LoweringCore::useLanguage(frontend::Language l) {
  if (l == language) return true;
  if (!languages[static_cast<size_t>(l)].table) return false;
  bindLanguage(l);
  return true;
}

void LoweringCore::bindLanguage(frontend::Language l) {
  const LanguageLowering& ll = languages[static_cast<size_t>(l)];
  table = ll.table;
  addresses = &*ll.addresses;
  settings = ll.settings;
  language = l;
}

void LoweringCore::resolveSkip() {
  if (!running() || cs().skip_axes == 0) return;
  const AxisValues at = running()->machinePosition();
  for (int i = 0; i < machine->axisCount(); ++i)
    if (cs().skip_axes & (1u << i)) cs().position[i] = at[i];
  cs().skip_axes = 0;
}

void LoweringCore::powerOn() {
  ir::Modal& m = cs().modal;
  m.units = settings.reset_unit;
  m.plane = settings.reset_plane;
  cs().motion = settings.reset_motion;
  if (const GCodeEntry* e = table->powerOnDefault(GGroup::Distance))
    m.distance = e->action == GAction::Incremental ? ir::DistanceMode::Incremental
                                                   : ir::DistanceMode::Absolute;
  if (const GCodeEntry* e = table->powerOnDefault(GGroup::FeedMode))
    m.feed_mode =
        e->action == GAction::PerRevolution ? ir::FeedMode::PerRevolution : ir::FeedMode::PerMinute;
  m.path = ir::PathControl::Continuous;
  m.work_offset = "G54";
  cs().work_name = "G54";
  cs().work_value = tables.workOffset("G54");
  cs().position = machine->start_position;
}

// ---- BlockContext: diagnostics and values ---------------------------------------------------
void BlockContext::fail(Alarm a, SourceLocation loc, std::string message) {
  if (!silent) core.diags.error(std::string(table.alarm(a)), loc, std::move(message));
  failed = true;
}

void BlockContext::needRunTime(SourceLocation loc, std::string why) {
  if (!needs_run_time) needs_run_time = eval::Failure{eval::EvalError::RunTimeValue, loc, std::move(why), 0};
  failed = true;
}

std::optional<int64_t> BlockContext::integer(const WordValue& w) {
  if (w.point && behaviour.integer_point_is_error) {
    fail(Alarm::DecimalPointNotAllowed, w.loc,
         absl::StrCat("address ", std::string(w.address), " takes an integer; a decimal point is not allowed"));
    return std::nullopt;
  }
  if (!integerFits(w)) return std::nullopt;
  return static_cast<int64_t>(std::trunc(w.value));
}

bool BlockContext::integerFits(const WordValue& w) {
  const ValueRules& v = settings.values;
  if (std::fabs(std::trunc(w.value)) <= v.maxCount()) return true;  // also rejects NaN
  fail(Alarm::TooManyDigits, w.loc,
       absl::StrCat("address ", std::string(w.address), " has more than ", v.digits, " digits (at most ",
                    absl::StrFormat("%.0f", v.maxCount()), ")"));
  return false;
}

void BlockContext::checkFormats() {
  const ValueRules& v = settings.values;
  ir::Units units = next.modal.units;
  GAction one_shot = words.one_shot ? words.one_shot->entry->action : GAction::NotSupported;
  // A value word: the number as written counts least increments (standard notation without
  // a point) or is a value whose least increment is `increment`.
  auto value = [&](const std::optional<WordValue>& w, double increment, const char* unit) {
    if (!w || failed) return;
    double count = (v.standard && !w->point) ? std::fabs(w->value) : std::fabs(w->value) / increment;
    if (count <= v.maxCount() + 0.5) return;  // also rejects NaN
    int decimals = std::max(0, static_cast<int>(std::lround(-std::log10(increment))));
    fail(Alarm::TooManyDigits, w->loc,
         absl::StrCat("address ", std::string(w->address), ": the value exceeds the ", v.digits,
                      "-digit format (at most ±",
                      absl::StrFormat("%.*f", decimals, v.maxCount() * increment), " ", unit, ")"));
  };
  const char* length_unit = units == ir::Units::Inch ? "in" : "mm";
  double length = v.lengthIncrement(units);
  const int x = words.timeAxis(*core.machine);
  const int angle = polarAngleAxis(*this);  // G16: the angle word has the rotary format
  for (int i = 0; i < axisCount(); ++i) {
    if (i == x)
      value(words.axes[i], v.time_increment, "s");
    else if (isRotary(i) || i == angle)
      value(words.axes[i], v.deg_increment * v.x10, "deg");
    else
      value(words.axes[i], length * v.x10, length_unit);
  }
  for (const auto* w : {&words.i, &words.j, &words.k}) value(*w, length * v.x10, length_unit);
  // G10 L10-L13 R is an offset value: no x10 input unit (ValueRules::offset).
  value(words.r, one_shot == GAction::DataSet ? length : length * v.x10, length_unit);
  for (const auto* w : {&words.h, &words.d, &words.p, &words.l, &words.s})
    if (*w && !failed) integerFits(**w);
  for (const auto& w : words.t)
    if (!failed) integerFits(w);
  for (const auto& w : words.m)
    if (!failed) integerFits(w);
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

AxisValues BlockContext::baseWork() const { return baseWork(frameOf(next, behaviour)); }

AxisValues BlockContext::baseWork(const ir::Frame& frame) const {
  AxisValues t = frame.total(), w{};
  for (int i = 0; i < axisCount(); ++i) w[i] = next.position[i] - t[i];
  if (length_delta_axis >= 0 && length_delta_axis < axisCount()) {
    const auto& word = words.axes[length_delta_axis];
    bool incremental = word && word->mode == ir::DistanceMode::Incremental;
    if (incremental || (!word && !length_delta_deferred)) w[length_delta_axis] += length_delta;
  }
  return w;
}

void BlockContext::lengthChangeTraversed() {
  if (next.length_pending_axis >= 0 && next.length_pending_axis < axisCount() &&
      words.axes[next.length_pending_axis]) {
    next.length_pending_axis = -1;
    next.length_pending = 0.0;
  }
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
