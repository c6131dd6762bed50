#include "ncc/vm/executor.h"

#include <cmath>

#include "absl/strings/str_cat.h"
#include "ncc/bytecode/disassembler.h"
#include "ncc/bytecode/instruction.h"
#include "ncc/machine/travel.h"
#include "block_preparation.h"

namespace ncc::vm {

void setArcOperands(const bytecode::Instruction& in, MotionPrimitive& m) {
  m.kind = MotionPrimitive::Kind::Arc;
  m.plane = static_cast<Plane>(in.plane);
  m.axis1 = in.axis1;
  m.axis2 = in.axis2;
  m.center[in.axis1] = in.center1;
  m.center[in.axis2] = in.center2;
  m.cw = (in.flags & bytecode::kFlagClockwise) != 0;
  m.extra_turns = in.turns;
}

namespace {

using bytecode::Instruction;
using bytecode::Opcode;

bool sameAxes(const AxisValues& a, const AxisValues& b, int count) {
  for (int i = 0; i < count; ++i)
    if (a[i] != b[i]) return false;
  return true;
}

// The event of a machine-function opcode: its kind and the M number it stands for (the
// operand's T or M for TOOL_SELECT and M_CODE; 0 for S). One case per opcode and no default,
// so an opcode added to the format without its answer here draws -Wswitch.
struct FunctionEvent {
  MachineEvent::Kind kind;
  int64_t code;
};
FunctionEvent functionEvent(const Instruction& in) {
  using K = MachineEvent::Kind;
  switch (in.op) {
    case Opcode::SpindleSpeed: return {K::SpindleSpeed, 0};
    case Opcode::SpindleCW: return {K::SpindleCW, 3};
    case Opcode::SpindleCCW: return {K::SpindleCCW, 4};
    case Opcode::SpindleStop: return {K::SpindleStop, 5};
    case Opcode::SpindleOrient: return {K::SpindleOrient, 19};
    case Opcode::ToolSelect: return {K::ToolSelect, in.code};
    case Opcode::ToolChange: return {K::ToolChange, 6};
    case Opcode::CoolantOn: return {K::CoolantOn, 8};
    case Opcode::CoolantOff: return {K::CoolantOff, 9};
    case Opcode::ProgramStop: return {K::ProgramStop, 0};
    case Opcode::OptionalStop: return {K::OptionalStop, 1};
    case Opcode::ProgramEnd: return {K::ProgramEnd, 2};
    case Opcode::ProgramEndRewind: return {K::ProgramEndRewind, 30};
    case Opcode::MCode: return {K::MCode, in.code};
    // Not machine functions: the dispatch below never asks for their event.
    case Opcode::End:
    case Opcode::Rapid:
    case Opcode::Line:
    case Opcode::Arc:
    case Opcode::Dwell:
    case Opcode::Skip:
    case Opcode::RefCheck:
    case Opcode::Push:
    case Opcode::PushVacant:
    case Opcode::Load:
    case Opcode::Store:
    case Opcode::Pop:
    case Opcode::Add:
    case Opcode::Sub:
    case Opcode::Mul:
    case Opcode::Div:
    case Opcode::Neg:
    case Opcode::CmpEq:
    case Opcode::CmpNe:
    case Opcode::CmpLt:
    case Opcode::CmpLe:
    case Opcode::CmpGt:
    case Opcode::CmpGe:
    case Opcode::Jump:
    case Opcode::JumpIfFalse:
    case Opcode::Prepare: break;
  }
  return {K::MCode, in.code};
}

// FANUC Macro B: a vacant operand counts as 0 in arithmetic and ordering; EQ/NE tell a vacant
// value from 0 (#1 EQ #0 is true only when #1 is vacant).
double numeric(bool vacant, double v) { return vacant ? 0.0 : v; }

}  // namespace

Executor::Executor(const bytecode::Program& program, const MachineConfig& machine)
    : program_(program),
      code_(program),
      axis_count_(program.axisCount()),
      axes_(machine.axes),
      travel_alarms_(travelAlarmCodes(program.header.dialect)),
      arc_radius_tolerance_(machine.params.getNumber("arc_radius_tolerance", 0.01)),
      probe_(machine.probe) {
  position_ = machine.start_position;
  const uint32_t count = program.header.variable_count <= bytecode::kMaxVariableCount
                             ? program.header.variable_count
                             : 0;
  variables_.assign(count, Value{});
  if (program.units.empty() || axis_count_ < 1 || axis_count_ > kMaxAxes || count == 0) {
    raise("NCC7205", "malformed program (was it verified?)", 0);
  } else if (machine.axisCount() != axis_count_) {
    raise("NCC7206", "the program's axes do not match the machine", 0);
  } else {
    pc_ = program.units.front().entry;
  }
  if (program.blocks.empty() || alarm_) return;
  RunningMachine running;
  running.position = [this] { return position_; };
  running.variable = [this](uint32_t n) {
    if (n >= variables_.size() || variables_[n].vacant) return eval::Value::none();
    return eval::Value::of(variables_[n].number);
  };
  running.seconds = [this] { return clock_; };
  std::string error;
  try {
    preparation_ = BlockPreparation::create(program, machine, std::move(running), error);
  } catch (const std::exception& e) {  // out of memory: the executor never throws
    error = e.what();
  }
  if (!preparation_) {
    raise("NCC7212", "", 0);
    alarm_->message = absl::StrCat("the program's block store cannot be prepared: ", error);
  }
}

Executor::~Executor() = default;

void Executor::setStepLimit(uint64_t limit) {
  step_limit_ = limit;
  if (preparation_) preparation_->boundIdleBlocks(limit);
}

bool Executor::fetch(Instruction& in, uint32_t& at) {
  at = pc_;
  if (!preparing_) {
    uint32_t size = 0;
    if (code_.decode(at, axis_count_, in, size) != bytecode::DecodeStatus::Ok)
      return raise("NCC7205", "cannot decode the instruction (unverified code)", at);
    pc_ = at + size;
    return true;
  }
  if (prepared_next_ == prepared_.size()) {
    std::optional<Alarm> alarm;
    prepared_next_ = 0;
    bool more = false;
    try {
      more = preparation_->next(prepared_, alarm);
    } catch (const std::exception& e) {  // out of memory: the executor never throws
      alarm = Alarm{"NCC7212", absl::StrCat("block preparation failed: ", e.what()), prepared_where_};
    }
    if (!more) {
      finished_ = true;
      if (alarm && !alarm_) alarm_ = std::move(alarm);
      return false;
    }
  }
  in = prepared_[prepared_next_].instruction;
  prepared_where_ = prepared_[prepared_next_].where;
  ++prepared_next_;
  return true;
}

SourcePosition Executor::where(uint32_t offset) {
  if (preparing_) return prepared_where_;
  const std::optional<bytecode::LineEntry> e = code_.lineFor(offset, line_hint_);
  return e ? SourcePosition{e->file, e->line, e->column} : SourcePosition{};
}

bool Executor::raise(const char* code, const char* message, uint32_t offset) {
  finished_ = true;
  if (!alarm_) alarm_ = Alarm{code, message, where(offset)};
  return false;
}

bool Executor::raiseRefCheck(int axis, double reference, uint32_t offset) {
  raise("NCC7201", "", offset);
  alarm_->message = absl::StrCat(
      "G27 reference position check failed: axis ", program_.header.axes[axis].name, " is at ",
      bytecode::formatNumber(position_[axis]), ", reference point is ",
      bytecode::formatNumber(reference));
  return false;
}

bool Executor::raiseTravel(const TravelViolation& v, uint32_t offset) {
  const std::string_view code = v.above ? travel_alarms_.plus : travel_alarms_.minus;
  raise("", "", offset);
  alarm_->code = std::string(code);
  alarm_->message = absl::StrCat(travelMessage(v, axes_), "; the move is not started");
  return false;
}

bool Executor::raiseArcRadius(double start_radius, double end_radius, uint32_t offset) {
  raise("NCC7211", "", offset);
  alarm_->message = absl::StrCat(
      "the arc's end point is not on its circle: start radius ", bytecode::formatNumber(start_radius),
      ", end radius ", bytecode::formatNumber(end_radius), " (difference above arc_radius_tolerance ",
      bytecode::formatNumber(arc_radius_tolerance_), "; was the file edited?)");
  return false;
}

bool Executor::skip(const Instruction& in, MotionPrimitive& m, uint32_t offset) {
  // The stop point: the first point of the path where the signal is on (probe.h), else the
  // end point (the manuals' notes do not say what happens without a signal; FANUC and Mazak
  // complete the move and the skip position is its end point).
  if (const std::optional<ProbeHit> hit = probeStop(probe_, m.from, m.to, axis_count_))
    m.to = probeStopPoint(probe_, *hit, m.from, m.to, axis_count_);
  // The machine stops there: no blending through the skip point, override 100 %.
  m.exact_stop = true;
  if (in.variable == 0) return true;
  if (uint64_t{in.variable} + static_cast<uint64_t>(axis_count_) > variables_.size())
    return raise("NCC7205", "skip result variables out of range (unverified code)", offset);
  for (int i = 0; i < axis_count_; ++i) {
    double work = m.to[i] - in.origin[i];
    if ((in.flags & bytecode::kFlagInch) && axes_[i].kind == AxisKind::Linear) work /= 25.4;
    variables_[in.variable + i] = Value{work, false};
  }
  return true;
}

bool Executor::pop(Value& out, uint32_t offset) {
  if (stack_size_ == 0) return raise("NCC7205", "value stack underflow (unverified code)", offset);
  out = stack_[--stack_size_];
  return true;
}

bool Executor::push(Value v, uint32_t offset) {
  if (stack_size_ >= bytecode::kMaxStackDepth)
    return raise("NCC7205", "value stack overflow (unverified code)", offset);
  stack_[stack_size_++] = v;
  return true;
}

bool Executor::next(Event& out) {
  while (!finished_) {
    if (step_limit_ != 0 && steps_ >= step_limit_)
      return raise("NCC7204", "step limit reached", pc_);
    ++steps_;
    uint32_t at = 0;
    Instruction in;
    if (!fetch(in, at)) return false;

    switch (in.op) {
      case Opcode::End:
        finished_ = true;
        return false;

      case Opcode::Rapid:
      case Opcode::Line:
      case Opcode::Arc:
      case Opcode::Skip:
      case Opcode::Dwell: {
        MotionPrimitive& m = out.motion;
        m = MotionPrimitive{};
        m.from = position_;
        m.to = position_;
        m.where = where(at);
        m.exact_stop = (in.flags & bytecode::kFlagExactStop) != 0;
        m.feed_per_rev = (in.flags & bytecode::kFlagFeedPerRev) != 0;
        m.fixed_override = (in.flags & bytecode::kFlagFixedOverride) != 0;
        m.feed = in.value;
        if (in.op == Opcode::Dwell) {
          m.kind = MotionPrimitive::Kind::Dwell;
          m.feed = 0.0;
          m.seconds = in.value;
          m.revolutions = (in.flags & bytecode::kFlagRevolutions) != 0;
        } else {
          for (int i = 0; i < axis_count_; ++i) m.to[i] = in.axes[i];
          if (in.op == Opcode::Rapid) {
            m.kind = MotionPrimitive::Kind::Rapid;
            m.feed = 0.0;
            m.per_axis = (in.flags & bytecode::kFlagPerAxis) != 0;
          } else if (in.op == Opcode::Line) {
            m.kind = MotionPrimitive::Kind::Line;
          } else if (in.op == Opcode::Skip) {
            m.kind = MotionPrimitive::Kind::Line;
            if (!skip(in, m, at)) return false;
          } else {
            if (in.axis1 >= axis_count_ || in.axis2 >= axis_count_ ||
                static_cast<uint8_t>(in.plane) > 2)
              return raise("NCC7205", "arc operands out of range (unverified code)", at);
            setArcOperands(in, m);
          }
          // A straight move to where the tool already is moves nothing: no primitive.
          if (in.op != Opcode::Arc && sameAxes(m.from, m.to, axis_count_)) continue;
          // Stored stroke limit, before the move: its end point (a straight or per-axis move
          // stays within the box of its ends) or the arc's whole extent.
          std::optional<TravelViolation> beyond;
          if (in.op == Opcode::Arc) {
            // The compiler lets the radii differ by arc_radius_tolerance at most (a slight
            // spiral); 1 um more for the rounding of a centre written in another unit.
            const double r0 = std::hypot(m.from[m.axis1] - in.center1, m.from[m.axis2] - in.center2);
            const double r1 = std::hypot(m.to[m.axis1] - in.center1, m.to[m.axis2] - in.center2);
            if (!(std::abs(r1 - r0) <= arc_radius_tolerance_ + 1e-3)) return raiseArcRadius(r0, r1, at);
            beyond = arcTravelViolation(axes_, ArcMove{m.from, m.to, m.axis1, m.axis2,
                                                       in.center1, in.center2, m.cw,
                                                       m.extra_turns});
          } else {
            beyond = travelViolation(axes_, m.to);
          }
          if (beyond) return raiseTravel(*beyond, at);
          position_ = m.to;
        }
        out.kind = Event::Kind::Motion;
        return true;
      }

      case Opcode::SpindleSpeed:
      case Opcode::SpindleCW:
      case Opcode::SpindleCCW:
      case Opcode::SpindleStop:
      case Opcode::SpindleOrient:
      case Opcode::ToolSelect:
      case Opcode::ToolChange:
      case Opcode::CoolantOn:
      case Opcode::CoolantOff:
      case Opcode::ProgramStop:
      case Opcode::OptionalStop:
      case Opcode::ProgramEnd:
      case Opcode::ProgramEndRewind:
      case Opcode::MCode: {
        MachineEvent& e = out.machine;
        const FunctionEvent f = functionEvent(in);
        e.kind = f.kind;
        e.code = f.code;
        e.value = in.op == Opcode::SpindleSpeed ? in.value : 0.0;
        e.where = where(at);
        out.kind = Event::Kind::Machine;
        if (in.op == Opcode::ProgramEnd || in.op == Opcode::ProgramEndRewind) finished_ = true;
        return true;
      }

      case Opcode::RefCheck:
        for (int i = 0; i < axis_count_; ++i) {
          if ((in.mask & (1u << i)) == 0) continue;
          if (!(std::fabs(position_[i] - in.axes[i]) <= kReferenceTolerance))
            return raiseRefCheck(i, in.axes[i], at);
        }
        continue;

      case Opcode::Push:
        if (!push(Value{in.value, false}, at)) return false;
        continue;
      case Opcode::PushVacant:
        if (!push(Value{}, at)) return false;
        continue;
      case Opcode::Load:
        if (in.variable >= variables_.size())
          return raise("NCC7205", "variable number out of range (unverified code)", at);
        if (!push(variables_[in.variable], at)) return false;
        continue;
      case Opcode::Store: {
        Value v;
        // A block prepared at run time may write a DIN variable declared after PREPARE, above
        // the count the file declared (its number comes from the compiler's own code).
        if (preparing_ && in.variable >= variables_.size() &&
            in.variable < bytecode::kMaxVariableCount)
          variables_.resize(in.variable + 1);
        if (in.variable == 0 || in.variable >= variables_.size())
          return raise("NCC7205", "variable number out of range (unverified code)", at);
        if (!pop(v, at)) return false;
        variables_[in.variable] = v;
        continue;
      }
      case Opcode::Pop: {
        Value v;
        if (!pop(v, at)) return false;
        continue;
      }
      case Opcode::Neg: {
        Value v;
        if (!pop(v, at)) return false;
        if (!push(Value{0.0 - numeric(v.vacant, v.number), false}, at)) return false;
        continue;
      }

      case Opcode::Add:
      case Opcode::Sub:
      case Opcode::Mul:
      case Opcode::Div:
      case Opcode::CmpEq:
      case Opcode::CmpNe:
      case Opcode::CmpLt:
      case Opcode::CmpLe:
      case Opcode::CmpGt:
      case Opcode::CmpGe: {
        Value rhs, lhs;
        if (!pop(rhs, at) || !pop(lhs, at)) return false;
        const double a = numeric(lhs.vacant, lhs.number);
        const double b = numeric(rhs.vacant, rhs.number);
        const bool same = lhs.vacant == rhs.vacant && (lhs.vacant || lhs.number == rhs.number);
        double r = 0.0;
        switch (in.op) {
          case Opcode::Add: r = a + b; break;
          case Opcode::Sub: r = a - b; break;
          case Opcode::Mul: r = a * b; break;
          case Opcode::Div:
            if (b == 0.0) return raise("NCC7202", "division by zero", at);
            r = a / b;
            break;
          case Opcode::CmpEq: r = same ? 1.0 : 0.0; break;
          case Opcode::CmpNe: r = same ? 0.0 : 1.0; break;
          case Opcode::CmpLt: r = a < b ? 1.0 : 0.0; break;
          case Opcode::CmpLe: r = a <= b ? 1.0 : 0.0; break;
          case Opcode::CmpGt: r = a > b ? 1.0 : 0.0; break;
          case Opcode::CmpGe: r = a >= b ? 1.0 : 0.0; break;
          default: break;  // only the opcodes of the case above reach this switch
        }
        if (!std::isfinite(r)) return raise("NCC7203", "arithmetic overflow", at);
        if (!push(Value{r, false}, at)) return false;
        continue;
      }

      case Opcode::Prepare:
        if (!preparation_ || preparing_)
          return raise("NCC7205", "PREPARE without a block store (unverified code)", at);
        preparing_ = true;
        continue;

      case Opcode::Jump:
        if (preparing_) break;  // prepared blocks never jump
        pc_ = in.target;
        continue;
      case Opcode::JumpIfFalse: {
        if (preparing_) break;
        Value c;
        if (!pop(c, at)) return false;
        if (numeric(c.vacant, c.number) == 0.0) pc_ = in.target;
        continue;
      }
    }
    return raise("NCC7205", "unknown instruction (unverified code)", at);
  }
  return false;
}

std::optional<double> Executor::variable(uint32_t number) const {
  if (number >= variables_.size() || variables_[number].vacant) return std::nullopt;
  return variables_[number].number;
}

std::vector<std::pair<std::string, double>> Executor::variables() const {
  std::vector<std::pair<std::string, double>> out;
  const std::vector<bytecode::VariableName>& names = program_.variable_names;
  auto name = names.begin();
  for (uint32_t n = 0; n < variables_.size(); ++n) {
    while (name != names.end() && name->number < n) ++name;
    if (variables_[n].vacant) continue;
    if (name != names.end() && name->number == n && name->name < program_.strings.size()) {
      out.emplace_back(program_.strings[name->name], variables_[n].number);
      continue;
    }
    if (preparation_) {
      const std::map<uint32_t, std::string>& prepared = preparation_->variableNames();
      if (auto it = prepared.find(n); it != prepared.end()) {
        out.emplace_back(it->second, variables_[n].number);
        continue;
      }
    }
    out.emplace_back(absl::StrCat("#", n), variables_[n].number);
  }
  return out;
}

}  // namespace ncc::vm
