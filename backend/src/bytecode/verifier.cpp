#include "ncc/bytecode/verifier.h"

#include <cmath>
#include <utility>
#include <vector>

#include "absl/strings/str_cat.h"
#include "ncc/bytecode/instruction.h"

namespace ncc::bytecode {

namespace {

std::string at(uint32_t offset) {
  return absl::StrCat("code offset ", absl::Hex(offset, absl::kZeroPad6));
}

std::string at(uint32_t offset, const Instruction& in) {
  return absl::StrCat(at(offset), " (", opcodeInfo(static_cast<uint8_t>(in.op))->mnemonic, ")");
}

Error problem(std::string code, std::string message) {
  return Error{std::move(code), std::move(message)};
}

class Verifier {
 public:
  Verifier(const Program& program, const VerifyOptions& options)
      : program_(program), options_(options), axis_count_(program.axisCount()) {}

  std::optional<Error> run() {
    if (auto e = checkMachine()) return e;
    if (auto e = checkInstructions()) return e;
    if (auto e = checkJumps()) return e;
    if (auto e = checkUnits()) return e;
    if (auto e = checkStackAndFlow()) return e;
    return checkLines();
  }

 private:
  std::optional<Error> checkMachine() {
    if (axis_count_ < 1 || axis_count_ > kMaxAxes)
      return problem("NCC7113", absl::StrCat("program has ", axis_count_, " axes"));
    if (program_.header.variable_count < 1 ||
        program_.header.variable_count > kMaxVariableCount)
      return problem("NCC7103", absl::StrCat("variable count ", program_.header.variable_count,
                                             " out of range"));
    const MachineConfig* machine = options_.machine;
    if (machine == nullptr) return std::nullopt;
    if (machine->axisCount() != axis_count_)
      return problem("NCC7113", absl::StrCat("program was compiled for ", axis_count_,
                                             " axes, the machine has ", machine->axisCount()));
    for (int i = 0; i < axis_count_; ++i) {
      if (machine->axes[i].name != program_.header.axes[i].name)
        return problem("NCC7113", absl::StrCat("axis ", i + 1, " is '",
                                               program_.header.axes[i].name,
                                               "' in the program and '", machine->axes[i].name,
                                               "' on the machine"));
    }
    if (options_.check_config_hash && machine->configHash() != program_.header.config_hash)
      return problem("NCC7114",
                     absl::StrCat("program was compiled for another machine configuration (hash ",
                                  absl::Hex(program_.header.config_hash, absl::kZeroPad16),
                                  ", this machine ",
                                  absl::Hex(machine->configHash(), absl::kZeroPad16), ")"));
    return std::nullopt;
  }

  // Linear pass: every instruction decodes and its operands are valid.
  std::optional<Error> checkInstructions() {
    const std::vector<uint8_t>& code = program_.code;
    if (code.empty()) return problem("NCC7109", "the code section is empty");
    starts_.assign(code.size(), false);
    uint32_t offset = 0;
    while (offset < code.size()) {
      Instruction in;
      uint32_t size = 0;
      switch (decode(code, offset, axis_count_, in, size)) {
        case DecodeStatus::BadOpcode:
          return problem("NCC7101", absl::StrCat(at(offset), ": unknown opcode 0x",
                                                 absl::Hex(code[offset], absl::kZeroPad2)));
        case DecodeStatus::Truncated:
          return problem("NCC7101", absl::StrCat(at(offset), ": instruction runs past the end "
                                                 "of the code"));
        case DecodeStatus::Ok:
          break;
      }
      starts_[offset] = true;
      if (auto e = checkOperands(offset, in)) return e;
      if (in.op == Opcode::Jump || in.op == Opcode::JumpIfFalse) jumps_.push_back({offset, in.target});
      offset += size;
    }
    return std::nullopt;
  }

  std::optional<Error> checkOperands(uint32_t offset, const Instruction& in) {
    const OpcodeInfo& info = *opcodeInfo(static_cast<uint8_t>(in.op));
    if ((in.flags & ~info.allowed_flags) != 0)
      return problem("NCC7102", absl::StrCat(at(offset, in), ": invalid flag bits 0x",
                                             absl::Hex(in.flags & ~info.allowed_flags,
                                                       absl::kZeroPad2)));
    auto finite = [&](double v, const std::string& what) -> std::optional<Error> {
      if (std::isfinite(v)) return std::nullopt;
      return problem("NCC7104", absl::StrCat(at(offset, in), ": ", what, " is not finite"));
    };
    // Finite and within ±kMaxCoordinate (mm or degrees).
    auto coordinate = [&](double v, const std::string& what) -> std::optional<Error> {
      if (auto e = finite(v, what)) return e;
      if (std::abs(v) <= kMaxCoordinate) return std::nullopt;
      return problem("NCC7103", absl::StrCat(at(offset, in), ": ", what, " ", v,
                                             " is beyond the bound of +-", kMaxCoordinate,
                                             " mm (or degrees)"));
    };
    auto finiteAxes = [&]() -> std::optional<Error> {
      for (int i = 0; i < axis_count_; ++i)
        if (auto e = coordinate(in.axes[i], absl::StrCat("coordinate of ",
                                                         program_.header.axes[i].name)))
          return e;
      return std::nullopt;
    };
    auto positiveFeed = [&]() -> std::optional<Error> {
      if (auto e = finite(in.value, "feed")) return e;
      if (in.value > 0.0) return std::nullopt;
      return problem("NCC7104", absl::StrCat(at(offset, in), ": feed ", in.value,
                                             " is not positive"));
    };
    auto functionCode = [&]() -> std::optional<Error> {
      if (in.code >= 0 && in.code <= kMaxFunctionCode) return std::nullopt;
      return problem("NCC7103", absl::StrCat(at(offset, in), ": code ", in.code,
                                             " out of range 0..", kMaxFunctionCode));
    };
    switch (in.op) {
      case Opcode::Rapid:
        return finiteAxes();
      case Opcode::Line:
        if (auto e = positiveFeed()) return e;
        return finiteAxes();
      case Opcode::Arc:
        if (static_cast<uint8_t>(in.plane) > static_cast<uint8_t>(ArcPlane::YZ))
          return problem("NCC7103", absl::StrCat(at(offset, in), ": unknown plane ",
                                                 static_cast<int>(in.plane)));
        if (in.axis1 >= axis_count_ || in.axis2 >= axis_count_ || in.axis1 == in.axis2)
          return problem("NCC7103", absl::StrCat(at(offset, in), ": plane axes ", in.axis1, " and ",
                                                 in.axis2, " are not two distinct axes of ",
                                                 axis_count_));
        if (in.turns > kMaxExtraTurns)
          return problem("NCC7103", absl::StrCat(at(offset, in), ": ", in.turns,
                                                 " extra turns (at most ", kMaxExtraTurns, ")"));
        if (auto e = positiveFeed()) return e;
        if (auto e = coordinate(in.center1, "centre")) return e;
        if (auto e = coordinate(in.center2, "centre")) return e;
        return finiteAxes();
      case Opcode::Dwell:
      case Opcode::SpindleSpeed:
        if (auto e = finite(in.value, "value")) return e;
        if (in.value < 0.0)
          return problem("NCC7104", absl::StrCat(at(offset, in), ": negative value ", in.value));
        if (in.op == Opcode::Dwell && in.value > kMaxDwell)
          return problem("NCC7103",
                         absl::StrCat(at(offset, in), ": dwell of ", in.value,
                                      (in.flags & kFlagRevolutions) ? " revolutions" : " s",
                                      " is beyond the bound of ", kMaxDwell));
        return std::nullopt;
      case Opcode::ToolSelect:
      case Opcode::MCode:
        return functionCode();
      case Opcode::RefCheck:
        if (in.mask == 0 || (in.mask >> axis_count_) != 0)
          return problem("NCC7103", absl::StrCat(at(offset, in), ": axis mask 0x",
                                                 absl::Hex(in.mask, absl::kZeroPad4),
                                                 " names no axis or an axis beyond ",
                                                 axis_count_));
        if (in.reference < 1 || in.reference > kMaxReference)
          return problem("NCC7103", absl::StrCat(at(offset, in), ": reference point ",
                                                 in.reference, " (1 to ", kMaxReference, ")"));
        return finiteAxes();
      case Opcode::Push:
        return finite(in.value, "constant");
      case Opcode::Load:
      case Opcode::Store:
        if (in.variable >= program_.header.variable_count)
          return problem("NCC7103", absl::StrCat(at(offset, in), ": variable #", in.variable,
                                                 " beyond the ", program_.header.variable_count,
                                                 " declared"));
        if (in.op == Opcode::Store && in.variable == 0)
          return problem("NCC7103", absl::StrCat(at(offset, in), ": #0 cannot be assigned"));
        return std::nullopt;
      default:
        return std::nullopt;
    }
  }

  bool isStart(uint32_t offset) const { return offset < starts_.size() && starts_[offset]; }

  std::optional<Error> checkJumps() {
    for (const auto& [offset, target] : jumps_) {
      if (!isStart(target))
        return problem("NCC7105", absl::StrCat(at(offset), ": jump target ",
                                               absl::Hex(target, absl::kZeroPad6),
                                               " is not the start of an instruction"));
    }
    return std::nullopt;
  }

  std::optional<Error> checkUnits() {
    if (program_.units.empty()) return problem("NCC7112", "no program unit");
    for (size_t i = 0; i < program_.units.size(); ++i) {
      const Unit& unit = program_.units[i];
      if (!isStart(unit.entry))
        return problem("NCC7112", absl::StrCat("unit ", i, ": entry ",
                                               absl::Hex(unit.entry, absl::kZeroPad6),
                                               " is not the start of an instruction"));
      if (unit.name >= program_.strings.size())
        return problem("NCC7112", absl::StrCat("unit ", i, ": name string ", unit.name,
                                               " does not exist"));
    }
    return std::nullopt;
  }

  // Abstract interpretation of the stack depth from every unit entry.
  std::optional<Error> checkStackAndFlow() {
    const std::vector<uint8_t>& code = program_.code;
    std::vector<int8_t> depth(code.size(), -1);
    std::vector<uint32_t> work;
    bool end_reachable = false;
    auto reach = [&](uint32_t from, uint32_t to, int d) -> std::optional<Error> {
      if (to >= code.size())
        return problem("NCC7109", absl::StrCat(at(from), ": execution runs past the end of "
                                               "the code (no END)"));
      if (depth[to] < 0) {
        depth[to] = static_cast<int8_t>(d);
        work.push_back(to);
      } else if (depth[to] != d) {
        return problem("NCC7108", absl::StrCat(at(to), ": stack depth ", d, " from ", at(from),
                                               " differs from depth ", depth[to],
                                               " on another path"));
      }
      return std::nullopt;
    };
    for (const Unit& unit : program_.units) {
      if (depth[unit.entry] < 0) {
        depth[unit.entry] = 0;
        work.push_back(unit.entry);
      } else if (depth[unit.entry] != 0) {
        return problem("NCC7108", absl::StrCat(at(unit.entry), ": unit entry reached with a "
                                               "non-empty stack"));
      }
    }
    while (!work.empty()) {
      const uint32_t offset = work.back();
      work.pop_back();
      Instruction in;
      uint32_t size = 0;
      decode(code, offset, axis_count_, in, size);  // checked by checkInstructions
      const OpcodeInfo& info = *opcodeInfo(static_cast<uint8_t>(in.op));
      int d = depth[offset];
      if (d < info.pops)
        return problem("NCC7106", absl::StrCat(at(offset, in), ": needs ", int{info.pops},
                                               " values, the stack holds ", d));
      d = d - info.pops + info.pushes;
      if (d > kMaxStackDepth)
        return problem("NCC7107", absl::StrCat(at(offset, in), ": stack deeper than ",
                                               kMaxStackDepth));
      if (in.op == Opcode::End || in.op == Opcode::ProgramEnd ||
          in.op == Opcode::ProgramEndRewind)
        end_reachable = true;
      if (in.op == Opcode::Jump || in.op == Opcode::JumpIfFalse)
        if (auto e = reach(offset, in.target, d)) return e;
      if (info.falls_through)
        if (auto e = reach(offset, offset + size, d)) return e;
    }
    if (!end_reachable)
      return problem("NCC7110", "no END, M02 or M30 is reachable: the program never ends");
    return std::nullopt;
  }

  std::optional<Error> checkLines() {
    const std::vector<LineEntry>& lines = program_.lines;
    for (size_t i = 0; i < lines.size(); ++i) {
      const LineEntry& e = lines[i];
      const std::string where = absl::StrCat("line table entry ", i);
      if (i > 0 && e.offset <= lines[i - 1].offset)
        return problem("NCC7111", absl::StrCat(where, ": offset ", absl::Hex(e.offset, absl::kZeroPad6),
                                               " does not increase"));
      if (!isStart(e.offset))
        return problem("NCC7111", absl::StrCat(where, ": offset ", absl::Hex(e.offset, absl::kZeroPad6),
                                               " is not the start of an instruction"));
      if (e.file >= program_.strings.size())
        return problem("NCC7111", absl::StrCat(where, ": file string ", e.file,
                                               " does not exist"));
    }
    return std::nullopt;
  }

  const Program& program_;
  const VerifyOptions& options_;
  const int axis_count_;
  std::vector<bool> starts_;
  std::vector<std::pair<uint32_t, uint32_t>> jumps_;  // (jump offset, target)
};

}  // namespace

std::optional<Error> verify(const Program& program, const VerifyOptions& options) {
  return Verifier(program, options).run();
}

}  // namespace ncc::bytecode
