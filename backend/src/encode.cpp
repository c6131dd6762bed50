#include "ncc/backend/encode.h"

#include <cmath>
#include <utility>
#include <variant>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace ncc::backend {

namespace {

// The two axes of a plane in centre order (G17: X Y, G18: Z X, G19: Y Z).
std::pair<const char*, const char*> planeAxisNames(ir::Plane plane) {
  switch (plane) {
    case ir::Plane::XY: return {"X", "Y"};
    case ir::Plane::ZX: return {"Z", "X"};
    case ir::Plane::YZ: return {"Y", "Z"};
  }
  return {"X", "Y"};
}

bytecode::ArcPlane arcPlane(ir::Plane plane) {
  switch (plane) {
    case ir::Plane::XY: return bytecode::ArcPlane::XY;
    case ir::Plane::ZX: return bytecode::ArcPlane::ZX;
    case ir::Plane::YZ: return bytecode::ArcPlane::YZ;
  }
  return bytecode::ArcPlane::XY;
}

bytecode::Opcode machineFunctionOpcode(ir::MachineFunction::Kind kind) {
  using K = ir::MachineFunction::Kind;
  using bytecode::Opcode;
  switch (kind) {
    case K::ProgramStop: return Opcode::ProgramStop;
    case K::OptionalStop: return Opcode::OptionalStop;
    case K::ProgramEnd: return Opcode::ProgramEnd;
    case K::ProgramEndRewind: return Opcode::ProgramEndRewind;
    case K::SpindleCW: return Opcode::SpindleCW;
    case K::SpindleCCW: return Opcode::SpindleCCW;
    case K::SpindleStop: return Opcode::SpindleStop;
    case K::ToolChange: return Opcode::ToolChange;
    case K::CoolantOn: return Opcode::CoolantOn;
    case K::CoolantOff: return Opcode::CoolantOff;
    case K::SpindleOrient: return Opcode::SpindleOrient;
    case K::OtherM: return Opcode::MCode;
    case K::SpindleSpeed: return Opcode::SpindleSpeed;
    case K::ToolSelect: return Opcode::ToolSelect;
  }
  return Opcode::MCode;
}

using Lowered = EncodedOperation;

// IR operation -> bytecode, one call operator per IR operation kind and no generic one: a kind
// added to ir::Operation without its case here does not compile (std::visit finds no match),
// where a chain of get_if would silently write it as END.
class Lowering {
 public:
  Lowering(const MachineConfig& machine, const ir::Block& block)
      : machine_(machine),
        exact_(block.exact_stop ? bytecode::kFlagExactStop : 0),
        // G63 tapping mode: the feed override is fixed at 100 % for the feed moves.
        fixed_override_(block.modal.path == ir::PathControl::Tapping
                            ? bytecode::kFlagFixedOverride
                            : 0),
        origin_(block.frame.total()) {}

  Lowered operator()(const ir::Rapid& r) const {
    bytecode::Instruction in = instruction(Opcode::Rapid);
    in.flags = exact_ | (r.type == ir::RapidType::PerAxis ? bytecode::kFlagPerAxis : 0);
    in.axes = r.to;
    return Lowered(in);
  }

  Lowered operator()(const ir::Linear& l) const {
    bytecode::Instruction in = instruction(Opcode::Line);
    in.flags = exact_ | fixed_override_ | (l.feed_per_rev ? bytecode::kFlagFeedPerRev : 0);
    in.value = l.feed;
    in.axes = l.to;
    return Lowered(in);
  }

  Lowered operator()(const ir::Arc& a) const {
    auto [first, second] = planeAxisNames(a.plane);
    const int axis1 = machine_.axisIndex(first);
    const int axis2 = machine_.axisIndex(second);
    if (axis1 < 0 || axis2 < 0) {
      Lowered failed;
      failed.error = {"NCC9003", absl::StrCat("internal error: an arc in the ", first, second,
                                              " plane needs axes ", first, " and ", second,
                                              " on the machine")};
      return failed;
    }
    bytecode::Instruction in = instruction(Opcode::Arc);
    in.flags = exact_ | fixed_override_ | (a.feed_per_rev ? bytecode::kFlagFeedPerRev : 0) |
               (a.clockwise ? bytecode::kFlagClockwise : 0);
    in.plane = arcPlane(a.plane);
    in.axis1 = static_cast<uint8_t>(axis1);
    in.axis2 = static_cast<uint8_t>(axis2);
    in.turns = a.extra_turns;
    in.value = a.feed;
    in.axes = a.to;
    in.center1 = a.center[axis1];
    in.center2 = a.center[axis2];
    return Lowered(in);
  }

  // G31: always an exact stop (the look-ahead must not blend through where the signal stops
  // the move) at 100 % override (Mazak §4.10; FANUC SKF = 0). The block's frame rides along
  // so that the VM can store the skip position in work coordinates.
  Lowered operator()(const ir::Skip& s) const {
    bytecode::Instruction in = instruction(Opcode::Skip);
    in.flags = bytecode::kFlagExactStop | bytecode::kFlagFixedOverride |
               (s.feed_per_rev ? bytecode::kFlagFeedPerRev : 0) |
               (s.inch_variables ? bytecode::kFlagInch : 0);
    in.value = s.feed;
    in.variable = s.first_variable;
    in.axes = s.to;
    in.origin = origin_;
    Lowered code(in);
    const uint64_t last = uint64_t{s.first_variable} + machine_.axisCount() - 1;
    if (s.first_variable != 0 && last >= bytecode::kDefaultVariableCount)
      code.error = {"NCC9001", absl::StrCat("internal error: skip position variables #",
                                            s.first_variable, " to #", last,
                                            " beyond the program's variables")};
    return code;
  }

  Lowered operator()(const ir::Dwell& d) const {
    bytecode::Instruction in = instruction(Opcode::Dwell);
    in.flags = d.revolutions ? bytecode::kFlagRevolutions : 0;
    in.value = d.seconds;
    return Lowered(in);
  }

  Lowered operator()(const ir::MachineFunction& f) const {
    bytecode::Instruction in = instruction(machineFunctionOpcode(f.kind));
    in.code = f.code;
    in.value = f.value;
    return Lowered(in);
  }

  Lowered operator()(const ir::ReferenceCheck& c) const {
    bytecode::Instruction in = instruction(Opcode::RefCheck);
    in.mask = c.axes;
    in.reference = static_cast<uint8_t>(c.reference);
    in.axes = c.position;
    return Lowered(in);
  }

  // `#n = value`: PUSH value (PUSH_VACANT for `#n = #0`), STORE n.
  // The block store rides on the IR statement; the writer puts it after the units.
  Lowered operator()(const ir::Prepare&) const { return Lowered(instruction(Opcode::Prepare)); }

  // The `cycles` pass replaces every hole cycle by its moves; one here is a pipeline fault.
  Lowered operator()(const ir::HoleCycle& c) const {
    Lowered failed;
    failed.error = {"NCC9001", absl::StrCat("internal error: a hole cycle (G", c.code10 / 10,
                                            ") reached the backend: the cycles pass did not run")};
    return failed;
  }

  Lowered operator()(const ir::SetVariable& v) const {
    Lowered code;
    bytecode::Instruction& value = code.instructions[0];
    value = instruction(v.vacant ? Opcode::PushVacant : Opcode::Push);
    if (!v.vacant) value.value = v.value;
    bytecode::Instruction& store = code.instructions[1];
    store = instruction(Opcode::Store);
    store.variable = v.number;
    code.count = 2;
    return code;
  }

 private:
  using Opcode = bytecode::Opcode;

  static bytecode::Instruction instruction(Opcode op) {
    bytecode::Instruction in;
    in.op = op;
    return in;
  }

  const MachineConfig& machine_;
  const uint8_t exact_;
  const uint8_t fixed_override_;
  const AxisValues origin_;  // the block's frame: machine coordinates of the work zero
};

}  // namespace

EncodedOperation encodeOperation(const ir::Operation& op, const ir::Block& block,
                                 const MachineConfig& machine) {
  // The one IR invariant a wrong file would follow from, checked in every build (the verifier
  // in front of the backend runs outside Release only): targets are in machine space.
  const bool work_space = std::visit(
      [](const auto& o) {
        if constexpr (requires { o.space; }) return o.space == ir::Space::Work;
        return false;
      },
      op);
  if (work_space) {
    EncodedOperation failed;
    failed.error = {"NCC9001", "internal error: a work-space target reached the backend "
                               "(the work-to-machine pass did not run)"};
    return failed;
  }
  return std::visit(Lowering{machine, block}, op);
}

std::optional<std::string> outOfBounds(const bytecode::Instruction& in,
                                       const MachineConfig& machine_) {
  using bytecode::Opcode;
  auto beyond = [](double v) { return !(std::abs(v) <= bytecode::kMaxCoordinate); };
  auto number = [](double v) { return absl::StrFormat("%.10g", v); };
  // Built only for a message: this runs on every instruction.
  auto coordinate_bound = [&number] {
    return absl::StrCat(" is beyond +-", number(bytecode::kMaxCoordinate),
                        " mm (or degrees), the largest coordinate a bytecode program may hold");
  };
  const bool has_axes = in.op == Opcode::Rapid || in.op == Opcode::Line ||
                        in.op == Opcode::Arc || in.op == Opcode::RefCheck ||
                        in.op == Opcode::Skip;
  if (has_axes) {
    for (int i = 0; i < machine_.axisCount(); ++i) {
      if (beyond(in.axes[i]))
        return absl::StrCat("the ", machine_.axes[i].name, " position ", number(in.axes[i]),
                            " (machine coordinates, after offsets)", coordinate_bound());
    }
  }
  if (in.op == Opcode::Skip) {
    for (int i = 0; i < machine_.axisCount(); ++i)
      if (beyond(in.origin[i]))
        return absl::StrCat("the ", machine_.axes[i].name, " work origin ", number(in.origin[i]),
                            " (machine coordinates)", coordinate_bound());
  }
  if (in.op == Opcode::Arc) {
    if (beyond(in.center1) || beyond(in.center2))
      return absl::StrCat("the arc centre (", number(in.center1), ", ", number(in.center2),
                          ")", coordinate_bound());
    if (in.turns > bytecode::kMaxExtraTurns)
      return absl::StrCat(in.turns, " extra turns of an arc (at most ",
                          bytecode::kMaxExtraTurns, ")");
  }
  if (in.op == Opcode::Dwell && !(in.value <= bytecode::kMaxDwell))
    return absl::StrCat("a dwell of ", number(in.value),
                        (in.flags & bytecode::kFlagRevolutions) ? " revolutions" : " s",
                        " is beyond ", number(bytecode::kMaxDwell),
                        ", the longest a bytecode program may hold");
  return std::nullopt;
}

}  // namespace ncc::backend
