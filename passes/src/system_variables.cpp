#include "system_variables.h"

#include <cmath>

#include "absl/strings/str_cat.h"
#include "lowering_context.h"

namespace ncc::passes {

namespace {

const SystemVariableRange* findRange(const DialectTable& table, int64_t number) {
  for (const SystemVariableRange& r : table.system_variables)
    if (number >= r.first && number <= r.last) return &r;
  return nullptr;
}

// Lengths are read and written in the input unit in force (G20: inch).
double unitScale(const ControllerState& cs) {
  return cs.modal.units == ir::Units::Inch ? 25.4 : 1.0;
}

// The register table of a kind (const or not, as `t` is); nullptr for other kinds.
template <class Tables>
auto* registerTable(Tables& t, SystemVariable kind) {
  using Table = decltype(&t.length);
  switch (kind) {
    case SystemVariable::LengthGeometry: return &t.length;
    case SystemVariable::LengthWear: return &t.length_wear;
    case SystemVariable::RadiusGeometry: return &t.radius;
    case SystemVariable::RadiusWear: return &t.radius_wear;
    default: return Table{nullptr};
  }
}

// The work system a WorkOffset / ExtendedWorkOffset variable belongs to, and its axis.
struct WorkSlot {
  std::string name;
  int axis;
};
WorkSlot workSlot(const SystemVariableRange& r, int64_t number, const DialectTable& table) {
  const int64_t system = (number - r.first) / r.stride + 1;
  const int axis = static_cast<int>((number - r.first) % r.stride);
  if (r.kind == SystemVariable::WorkOffset) return {gCodeName(530 + 10 * static_cast<int>(system)), axis};
  return {absl::StrCat(table.behaviour.extended_offset_is_g54_p ? "G54P" : "G54.1P", system), axis};
}

// The value of the G code in force in a group, as the manual numbers the group (#4001 + n-1).
std::optional<double> modalCode(const LoweringCore& core, int group_number) {
  const DialectTable& table = *core.table;
  const ControllerState& cs = core.cs();
  const GCodeEntry* any = nullptr;
  for (const GCodeEntry& e : table.gcodes)
    if (e.group_number == group_number && e.group != GGroup::OneShot) {
      any = &e;
      break;
    }
  if (!any) return std::nullopt;
  auto codeOf = [&](GAction a) -> std::optional<double> {
    for (const GCodeEntry& e : table.gcodes)
      if (e.group == any->group && e.action == a) return e.code10 / 10.0;
    return std::nullopt;
  };
  switch (any->group) {
    case GGroup::Motion: return codeOf(cs.motion);
    case GGroup::Plane:
      return codeOf(cs.modal.plane == ir::Plane::XY   ? GAction::PlaneXY
                    : cs.modal.plane == ir::Plane::ZX ? GAction::PlaneZX
                                                      : GAction::PlaneYZ);
    case GGroup::Distance:
      return codeOf(cs.modal.distance == ir::DistanceMode::Absolute ? GAction::Absolute
                                                                    : GAction::Incremental);
    case GGroup::FeedMode:
      return codeOf(cs.modal.feed_mode == ir::FeedMode::PerMinute       ? GAction::PerMinute
                    : cs.modal.feed_mode == ir::FeedMode::PerRevolution ? GAction::PerRevolution
                                                                        : GAction::InverseTime);
    case GGroup::Units:
      return codeOf(cs.modal.units == ir::Units::Inch ? GAction::Inch : GAction::Metric);
    case GGroup::LengthComp:
      return codeOf(cs.modal.length_offset_sign > 0   ? GAction::LengthPlus
                    : cs.modal.length_offset_sign < 0 ? GAction::LengthMinus
                                                      : GAction::LengthCancel);
    case GGroup::PathControl:
      return codeOf(cs.modal.path == ir::PathControl::ExactStop        ? GAction::ExactStopMode
                    : cs.modal.path == ir::PathControl::CornerOverride ? GAction::CornerOverride
                    : cs.modal.path == ir::PathControl::Tapping        ? GAction::TappingMode
                                                                       : GAction::ContinuousMode);
    case GGroup::Rotation:
      return codeOf(cs.transforms->rotations.empty() ? GAction::RotationCancel : GAction::Rotation);
    case GGroup::Scaling:
      return codeOf(cs.transforms->scaling ? GAction::Scaling : GAction::ScalingCancel);
    case GGroup::Mirror:
      return codeOf(cs.transforms->mirrorsAny() ? GAction::Mirror : GAction::MirrorCancel);
    case GGroup::Polar: return codeOf(cs.polar ? GAction::PolarOn : GAction::PolarOff);
    case GGroup::CutterComp:  // the side in force (Mazak: D00 cancels it)
      return codeOf(cs.comp.side == ir::CutterComp::Side::Left    ? GAction::CompLeft
                    : cs.comp.side == ir::CutterComp::Side::Right ? GAction::CompRight
                                                                  : GAction::CompCancel);
    case GGroup::WorkOffset: {
      const std::string w = cs.work_name.str();  // "G54".."G59", "G54.1P3", "G54P3"
      if (w.rfind("G54.1", 0) == 0) return 54.1;
      return std::stod(w.substr(1, 2));
    }
    default: {
      // Groups ncc keeps at their power-on code (cancel codes of functions not built yet).
      const GCodeEntry* e = table.powerOnDefault(any->group);
      if (!e) return std::nullopt;
      return e->code10 / 10.0;
    }
  }
}

// #4101 + n-1: the modal word of argument letter n (B 2, D 7, F 9, H 11, S 19, T 20, P 30).
std::optional<eval::Value> modalWord(const LoweringCore& core, int n) {
  const ControllerState& cs = core.cs();
  switch (n) {
    case 7: return eval::Value::of(cs.d_selected);
    case 9:
      return cs.feed_programmed ? eval::Value::of(cs.modal.feed / unitScale(cs)) : eval::Value::none();
    case 11: return eval::Value::of(cs.h_selected);
    case 19: return eval::Value::of(cs.modal.spindle_speed);
    case 20: return eval::Value::of(cs.modal.tool);
    case 30: {
      const std::string w = cs.work_name.str();
      const size_t p = w.find('P');
      return p == std::string::npos ? eval::Value::none() : eval::Value::of(std::stod(w.substr(p + 1)));
    }
    default: return eval::Value::none();  // B, M, N, O: not kept by the model (docs/macro.md)
  }
}


// Interface outputs (Mazak §13-9-4 4.): #1100 + i, i = 0..31 one bit each, i = 32 the word of
// those bits, i = 33..35 words of their own.
constexpr int64_t kOutputBits = 32;

double outputSignal(const LoweringCore& core, int64_t i) {
  if (i != kOutputBits) return core.output_signals[static_cast<size_t>(i)];
  double word = 0.0;
  for (int64_t bit = 0; bit < kOutputBits; ++bit)
    if (core.output_signals[static_cast<size_t>(bit)] != 0.0) word += std::ldexp(1.0, static_cast<int>(bit));
  return word;
}

// A bit takes 0 or 1: vacant is 0, any other value 1 (note 2; a value below 1e-8, which the
// manual calls undefined, is taken as 0). A word takes an integer 0..2^32-1; the word of the
// bits sets them all.
bool writeOutputSignal(LoweringCore& core, int64_t i, const eval::Value& value,
                       SourceLocation loc, eval::Failure& failure) {
  const double v = value.vacant ? 0.0 : value.number;
  if (i < kOutputBits) {
    core.output_signals[static_cast<size_t>(i)] = std::fabs(v) < 1e-8 ? 0.0 : 1.0;
    return true;
  }
  if (!(v >= 0.0 && v <= 4294967295.0) || v != std::floor(v)) {
    failure = {eval::EvalError::ValueRange, loc,
               absl::StrCat("#", 1100 + i, " is a 32-bit output word: an integer from 0 to "
                            "4294967295, not ", v),
               0};
    return false;
  }
  if (i > kOutputBits) {
    core.output_signals[static_cast<size_t>(i)] = v;
    return true;
  }
  const auto word = static_cast<uint64_t>(v);
  for (int64_t bit = 0; bit < kOutputBits; ++bit)
    core.output_signals[static_cast<size_t>(bit)] = ((word >> bit) & 1u) ? 1.0 : 0.0;
  return true;
}

}  // namespace

std::optional<eval::Value> ControllerVariables::read(int64_t number, SourceLocation loc,
                                                     eval::Failure& failure) {
  core_.resolveSkip();
  const DialectTable& table = *core_.table;
  const ControllerState& cs = core_.cs();
  const SystemVariableRange* r = findRange(table, number);
  auto unknown = [&](std::string message) -> std::optional<eval::Value> {
    failure = {eval::EvalError::VariableNumber, loc, std::move(message), 0};
    return std::nullopt;
  };
  // Ahead of time: the compiler stops preparing here and the VM goes on (docs/runtime.md).
  auto atRunTime = [&](std::string why) -> std::optional<eval::Value> {
    failure = {eval::EvalError::RunTimeValue, loc, std::move(why), 0};
    return std::nullopt;
  };
  // At run time: the value the machine has, if the VM simulates it.
  const RunTimeState* run = core_.running();
  auto fromRun = [&]() -> std::optional<eval::Value> {
    if (std::optional<eval::Value> v = run->machineVariable(number)) return v;
    failure = {eval::EvalError::NotSupported, loc,
               absl::StrCat("#", number, " (", std::string(r->what),
                            ") is not simulated by the VM yet"),
               0};
    return std::nullopt;
  };
  if (!r)
    return unknown(absl::StrCat("#", number, " is not a system variable of ",
                                std::string(dialectName(table.dialect))));
  const double scale = unitScale(cs);
  const int axes = core_.machine->axisCount();
  auto axisOf = [&](int64_t i) { return i < axes ? static_cast<int>(i) : -1; };
  const ir::Frame frame = frameOf(cs, table.behaviour);
  // Where a G31 stopped is known only when the program runs (lowering_skip.cpp); at run time
  // resolveSkip() above has made it known.
  auto afterSkip = [&](int axis) -> std::optional<eval::Value> {
    return atRunTime(absl::StrCat("#", number, " (", std::string(r->what), " of ",
                                  core_.machine->axes[axis].name,
                                  ") depends on where G31 stopped"));
  };
  switch (r->kind) {
    case SystemVariable::SkipPosition:
      if (run) return run->skipVariable(number);
      return atRunTime(absl::StrCat("#", number, " (", std::string(r->what),
                                    ") is where G31 stopped"));
    case SystemVariable::InputSignal:
      if (run) return fromRun();
      return atRunTime(absl::StrCat("#", number, " (", std::string(r->what),
                                    ") is known only when the program runs"));
    case SystemVariable::OutputSignal: return eval::Value::of(outputSignal(core_, number - r->first));
    case SystemVariable::TimerMs:
    case SystemVariable::TimerHours: {
      if (!run)
        return atRunTime(absl::StrCat("#", number, " (", std::string(r->what),
                                      ") is known only when the program runs"));
      const LoweringCore::TimerBase& base = core_.timers[static_cast<size_t>(number - 3001) % 2];
      const double elapsed = run->seconds() - base.seconds;
      // The ms timer counts whole milliseconds.
      return eval::Value::of(r->kind == SystemVariable::TimerMs
                                 ? base.value + std::floor(elapsed * 1000.0 + 1e-9)
                                 : base.value + elapsed / 3600.0);
    }
    case SystemVariable::RunTime:
      // Not simulated by the VM (yet): refused ahead of time rather than stopping a run.
      if (run) return fromRun();
      failure = {eval::EvalError::NotSupported, loc,
                 absl::StrCat("#", number, " (", std::string(r->what),
                              ") is known only when the program runs, and the VM does not "
                              "simulate it yet"),
                 0};
      return std::nullopt;
    case SystemVariable::LengthGeometry:
    case SystemVariable::LengthWear:
    case SystemVariable::RadiusGeometry:
    case SystemVariable::RadiusWear: {
      const std::map<int, double>& t = *registerTable(core_.tables, r->kind);
      auto it = t.find(static_cast<int>(number - r->first + 1));
      return eval::Value::of(it == t.end() ? 0.0 : it->second / scale);
    }
    case SystemVariable::ExternalOffset: {
      const int i = axisOf(number - r->first);
      return i < 0 ? eval::Value::none() : eval::Value::of(cs.external[i] / scale);
    }
    case SystemVariable::WorkOffset:
    case SystemVariable::ExtendedWorkOffset: {
      WorkSlot slot = workSlot(*r, number, table);
      if (slot.axis >= axes) return eval::Value::none();
      return eval::Value::of(core_.tables.workOffset(slot.name)[slot.axis] / scale);
    }
    case SystemVariable::ModalGroup: {
      std::optional<double> code = modalCode(core_, static_cast<int>(number - r->first + 1));
      return code ? eval::Value::of(*code) : eval::Value::none();
    }
    case SystemVariable::ModalWord: return modalWord(core_, static_cast<int>(number - r->first + 1));
    case SystemVariable::EndPoint:
    case SystemVariable::WorkPosition: {
      const int i = axisOf(number - r->first);
      if (i < 0) return eval::Value::none();
      if (cs.skip_axes & (1u << i)) return afterSkip(i);
      return eval::Value::of((cs.position[i] - frame.total()[i]) / scale);
    }
    case SystemVariable::MachinePosition: {
      const int i = axisOf(number - r->first);
      if (i >= 0 && (cs.skip_axes & (1u << i))) return afterSkip(i);
      return i < 0 ? eval::Value::none() : eval::Value::of(cs.position[i] / scale);
    }
    case SystemVariable::ToolLengthVector: {
      const int i = axisOf(number - r->first);
      return i < 0 ? eval::Value::none() : eval::Value::of(frame.tool_length[i] / scale);
    }
  }
  return eval::Value::none();
}

bool ControllerVariables::write(int64_t number, const eval::Value& value, SourceLocation loc,
                                eval::Failure& failure) {
  const DialectTable& table = *core_.table;
  ControllerState& cs = core_.cs();
  const SystemVariableRange* r = findRange(table, number);
  const double v = value.arithmetic() * unitScale(cs);
  auto readOnly = [&]() {
    failure = {eval::EvalError::VariableReadOnly, loc,
               r ? absl::StrCat("#", number, " (", std::string(r->what), ") cannot be written")
                 : absl::StrCat("#", number, " is not a system variable of ",
                                std::string(dialectName(table.dialect))),
               0};
    return false;
  };
  if (!r) return readOnly();
  const int axes = core_.machine->axisCount();
  switch (r->kind) {
    case SystemVariable::LengthGeometry:
    case SystemVariable::LengthWear:
    case SystemVariable::RadiusGeometry:
    case SystemVariable::RadiusWear:
      (*registerTable(core_.tables, r->kind))[static_cast<int>(number - r->first + 1)] = v;
      return true;
    case SystemVariable::ExternalOffset: {
      const int64_t i = number - r->first;
      if (i >= axes) return readOnly();
      cs.external[i] = v;
      return true;
    }
    case SystemVariable::WorkOffset:
    case SystemVariable::ExtendedWorkOffset: {
      WorkSlot slot = workSlot(*r, number, table);
      if (slot.axis >= axes) return readOnly();
      AxisValues& stored = core_.tables.work[slot.name];
      stored[slot.axis] = v;
      // As G10: the selected system takes the new value at once unless the dialect latches it
      // until the system is selected again.
      if (slot.name == cs.work_name && !table.behaviour.work_offset_write_on_reselect)
        cs.work_value = stored;
      return true;
    }
    case SystemVariable::OutputSignal:
      return writeOutputSignal(core_, number - r->first, value, loc, failure);
    case SystemVariable::TimerMs:
    case SystemVariable::TimerHours: {
      // The timer restarts from the value at the time of the write: known only when run.
      const RunTimeState* run = core_.running();
      if (!run) {
        failure = {eval::EvalError::RunTimeValue, loc,
                   absl::StrCat("#", number, " (", std::string(r->what),
                                ") restarts at the time of the write, known only when the "
                                "program runs"),
                   0};
        return false;
      }
      core_.timers[static_cast<size_t>(number - 3001) % 2] = {value.arithmetic(), run->seconds()};
      return true;
    }
    default: return readOnly();
  }
}

std::vector<ir::SetVariable> variablesOf(const TableWrite& write, const ControllerState& cs,
                                         const OffsetTables& tables, const DialectTable& table,
                                         int axis_count) {
  std::vector<ir::SetVariable> out;
  const double scale = unitScale(cs);
  for (const SystemVariableRange& r : table.system_variables) {
    switch (r.kind) {
      case SystemVariable::LengthGeometry:
      case SystemVariable::LengthWear:
      case SystemVariable::RadiusGeometry:
      case SystemVariable::RadiusWear: {
        using T = TableWrite::Target;
        const T target = r.kind == SystemVariable::LengthGeometry ? T::Length
                         : r.kind == SystemVariable::LengthWear   ? T::LengthWear
                         : r.kind == SystemVariable::RadiusGeometry ? T::Radius
                                                                    : T::RadiusWear;
        const int64_t n = r.first + write.number - 1;
        if (write.target != target || n > r.last) break;
        const std::map<int, double>& t = *registerTable(tables, r.kind);
        auto it = t.find(write.number);
        out.push_back({static_cast<uint32_t>(n), it == t.end() ? 0.0 : it->second / scale, false, {}});
        break;
      }
      case SystemVariable::WorkOffset:
      case SystemVariable::ExtendedWorkOffset: {
        if (write.target != TableWrite::Target::Work) break;
        for (int64_t first = r.first; first <= r.last; first += r.stride) {
          if (workSlot(r, first, table).name != write.work_name) continue;
          const AxisValues stored = tables.workOffset(write.work_name);
          for (int i = 0; i < axis_count; ++i)
            if (write.axes & (1u << i))
              out.push_back({static_cast<uint32_t>(first + i), stored[i] / scale, false, {}});
        }
        break;
      }
      default: break;
    }
  }
  return out;
}

// ---- DIN: system variables by name (Sinumerik "Lists System Variables") ---------------------

namespace {

// What a `$` name reads, each per axis (`$AA_IW[X]`).
enum class Named : uint8_t {
  ActualMachine,  // $AA_IM: where the tool is, machine coordinates
  ActualWork,     // $AA_IW: the same in the workpiece coordinates (every frame in force)
  EndPoint,       // $P_EP: the programmed end point of the last block, workpiece coordinates
};
struct NamedSystemVariable {
  std::string_view name;
  Named kind;
};
constexpr NamedSystemVariable kNamed[] = {
    {"$AA_IM", Named::ActualMachine},
    {"$AA_IW", Named::ActualWork},
    {"$P_EP", Named::EndPoint},
};

}  // namespace

std::optional<eval::Value> ControllerVariables::readSystem(std::string_view name,
                                                           std::span<const eval::SystemIndex> indices,
                                                           SourceLocation loc,
                                                           eval::Failure& failure) {
  const NamedSystemVariable* v = nullptr;
  for (const NamedSystemVariable& each : kNamed)
    if (each.name == name) v = &each;
  if (!v)
    return SystemVariables::readSystem(name, indices, loc, failure);
  const int axis = indices.size() == 1 ? core_.machine->axisIndex(indices[0].axis) : -1;
  if (axis < 0 || axis >= kMaxAxes) {
    failure = {eval::EvalError::UndefinedName, loc,
               absl::StrCat(std::string(name), " takes one index, the name of an axis of the machine (",
                            std::string(name), "[X])"),
               0};
    return std::nullopt;
  }
  core_.resolveSkip();  // at run time, where a G31 stopped is known from here
  const ControllerState& cs = core_.cs();
  if (cs.skip_axes & (1u << axis)) {
    failure = {eval::EvalError::RunTimeValue, loc,
               absl::StrCat(std::string(name), "[", indices[0].axis, "] depends on where G31 stopped"), 0};
    return std::nullopt;
  }
  const AxisValues total = frameOf(cs, core_.table->behaviour).total();
  const std::optional<AxisValues>& tool_at = cs.transforms->tool_at;
  const AxisValues tool = tool_at ? *tool_at : cs.position;
  double value = 0.0;
  switch (v->kind) {
    case Named::ActualMachine: value = tool[axis]; break;
    case Named::EndPoint: value = cs.position[axis] - total[axis]; break;
    case Named::ActualWork: value = programmedAt(core_, cs, tool)[axis] - total[axis]; break;
  }
  return eval::Value::of(value / unitScale(cs));
}

}  // namespace ncc::passes
