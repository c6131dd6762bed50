#include "ncc/bytecode/verifier.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "absl/strings/str_cat.h"
#include "ncc/bytecode/code_view.h"
#include "ncc/bytecode/instruction.h"

namespace ncc::bytecode {

namespace {

std::string at(uint32_t offset) {
  return absl::StrCat("code offset ", absl::Hex(offset, absl::kZeroPad6));
}

std::string at(uint32_t offset, const Instruction& in) {
  return absl::StrCat(at(offset), " (", opcodeInfo(in.op).mnemonic, ")");
}

Error problem(std::string code, std::string message) {
  return Error{std::move(code), std::move(message)};
}

class Verifier {
 public:
  Verifier(const Program& program, const VerifyOptions& options)
      : program_(program), options_(options), axis_count_(program.axisCount()), code_(program) {}

  // Two passes over the code, so that a paged program is verified in memory proportional to
  // its jumps and units, not to its length: the first checks each instruction and collects the
  // jumps; the second checks jump targets, unit entries and line entries against the
  // instruction starts as they pass by, and summarises the code's basic blocks (cut at jumps,
  // ends and jump targets), whose stack depths are then checked on the block graph.
  std::optional<Error> run() {
    if (auto e = checkMachine()) return e;
    if (auto e = checkInstructions()) return e;
    if (program_.units.empty()) return problem("NCC7112", "no program unit");
    if (auto e = scanBoundaries()) return e;
    if (auto e = checkJumps()) return e;
    if (auto e = checkUnits()) return e;
    if (auto e = checkNames()) return e;
    if (auto e = checkStackAndFlow()) return e;
    return line_error_;
  }

 private:
  // Each name: a variable of the program, in ascending order, named by a string of the pool.
  std::optional<Error> checkNames() const {
    uint32_t previous = 0;
    for (const VariableName& n : program_.variable_names) {
      if (n.number == 0 || n.number >= program_.header.variable_count || n.number <= previous)
        return problem("NCC7117", absl::StrCat("variable name for #", n.number,
                                               ": not a variable of the program, or out of order"));
      if (n.name >= program_.strings.size() || program_.strings[n.name].empty())
        return problem("NCC7117", absl::StrCat("variable name for #", n.number,
                                               ": string ", n.name, " is not in the pool"));
      previous = n.number;
    }
    return std::nullopt;
  }

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

  // First pass: every instruction decodes and its operands are valid.
  std::optional<Error> checkInstructions() {
    const uint32_t code_size = code_.codeSize();
    if (code_size == 0) return problem("NCC7109", "the code section is empty");
    uint32_t offset = 0;
    while (offset < code_size) {
      Instruction in;
      uint32_t size = 0;
      switch (code_.decode(offset, axis_count_, in, size)) {
        case DecodeStatus::BadOpcode:
          return problem("NCC7101", absl::StrCat(at(offset), ": unknown opcode 0x",
                                                 absl::Hex(code_.byteAt(offset),
                                                           absl::kZeroPad2)));
        case DecodeStatus::Truncated:
          return problem("NCC7101", absl::StrCat(at(offset), ": instruction runs past the end "
                                                 "of the code"));
        case DecodeStatus::Ok:
          break;
      }
      if (auto e = checkOperands(offset, in)) return e;
      if (in.op == Opcode::Prepare && program_.blocks.empty())
        return problem("NCC7116", absl::StrCat(at(offset, in), ": PREPARE without a block "
                                               "store to prepare from"));
      if (opcodeInfo(in.op).hasOperand(Operand::JumpTarget))
        jumps_.push_back({offset, in.target});
      offset += size;
    }
    return std::nullopt;
  }

  // The allowed flags, then each operand by its kind, in byte order.
  std::optional<Error> checkOperands(uint32_t offset, const Instruction& in) {
    const OpcodeInfo& info = opcodeInfo(in.op);
    if ((in.flags & ~info.allowed_flags) != 0)
      return problem("NCC7102", absl::StrCat(at(offset, in), ": invalid flag bits 0x",
                                             absl::Hex(in.flags & ~info.allowed_flags,
                                                       absl::kZeroPad2)));
    for (Operand kind : info.operands())
      if (auto e = checkOperand(kind, offset, in)) return e;
    return std::nullopt;
  }

  std::optional<Error> checkOperand(Operand kind, uint32_t offset, const Instruction& in) {
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
    auto nonNegative = [&]() -> std::optional<Error> {
      if (auto e = finite(in.value, "value")) return e;
      if (in.value >= 0.0) return std::nullopt;
      return problem("NCC7104", absl::StrCat(at(offset, in), ": negative value ", in.value));
    };
    auto variable = [&]() -> std::optional<Error> {
      if (in.variable < program_.header.variable_count) return std::nullopt;
      return problem("NCC7103", absl::StrCat(at(offset, in), ": variable #", in.variable,
                                             " beyond the ", program_.header.variable_count,
                                             " declared"));
    };
    switch (kind) {
      case Operand::Flags:  // checked against the opcode's allowed flags above
      case Operand::JumpTarget:  // an instruction start: checkJumps(), once all are known
        return std::nullopt;
      case Operand::Plane:
        if (static_cast<uint8_t>(in.plane) <= static_cast<uint8_t>(ArcPlane::YZ))
          return std::nullopt;
        return problem("NCC7103", absl::StrCat(at(offset, in), ": unknown plane ",
                                               static_cast<int>(in.plane)));
      case Operand::PlaneAxes:
        if (in.axis1 < axis_count_ && in.axis2 < axis_count_ && in.axis1 != in.axis2)
          return std::nullopt;
        return problem("NCC7103", absl::StrCat(at(offset, in), ": plane axes ", in.axis1, " and ",
                                               in.axis2, " are not two distinct axes of ",
                                               axis_count_));
      case Operand::Turns:
        if (in.turns <= kMaxExtraTurns) return std::nullopt;
        return problem("NCC7103", absl::StrCat(at(offset, in), ": ", in.turns,
                                               " extra turns (at most ", kMaxExtraTurns, ")"));
      case Operand::Feed:
        if (auto e = finite(in.value, "feed")) return e;
        if (in.value > 0.0) return std::nullopt;
        return problem("NCC7104", absl::StrCat(at(offset, in), ": feed ", in.value,
                                               " is not positive"));
      case Operand::Amount:
        if (auto e = nonNegative()) return e;
        if (in.value <= kMaxDwell) return std::nullopt;
        return problem("NCC7103",
                       absl::StrCat(at(offset, in), ": dwell of ", in.value,
                                    (in.flags & kFlagRevolutions) ? " revolutions" : " s",
                                    " is beyond the bound of ", kMaxDwell));
      case Operand::Speed:
        return nonNegative();
      case Operand::Constant:
        return finite(in.value, "constant");
      case Operand::Target:
      case Operand::Position:
        for (int i = 0; i < axis_count_; ++i)
          if (auto e = coordinate(in.axes[i], absl::StrCat("coordinate of ",
                                                           program_.header.axes[i].name)))
            return e;
        return std::nullopt;
      case Operand::Origin:
        for (int i = 0; i < axis_count_; ++i)
          if (auto e = coordinate(in.origin[i], absl::StrCat("origin of ",
                                                             program_.header.axes[i].name)))
            return e;
        return std::nullopt;
      case Operand::Results: {
        // 0 (none), or N variables from #variable, all below the count (never #0).
        const uint64_t last = uint64_t{in.variable} + static_cast<uint64_t>(axis_count_) - 1;
        if (in.variable == 0 || last < program_.header.variable_count) return std::nullopt;
        return problem("NCC7103", absl::StrCat(at(offset, in), ": result variables #",
                                               in.variable, " to #", last, " beyond the ",
                                               program_.header.variable_count, " declared"));
      }
      case Operand::Centre:
        if (auto e = coordinate(in.center1, "centre")) return e;
        return coordinate(in.center2, "centre");
      case Operand::Mask:
        if (in.mask != 0 && (in.mask >> axis_count_) == 0) return std::nullopt;
        return problem("NCC7103", absl::StrCat(at(offset, in), ": axis mask 0x",
                                               absl::Hex(in.mask, absl::kZeroPad4),
                                               " names no axis or an axis beyond ",
                                               axis_count_));
      case Operand::Reference:
        if (in.reference >= 1 && in.reference <= kMaxReference) return std::nullopt;
        return problem("NCC7103", absl::StrCat(at(offset, in), ": reference point ",
                                               in.reference, " (1 to ", kMaxReference, ")"));
      case Operand::Variable:
        return variable();
      case Operand::Assigned:
        if (auto e = variable()) return e;
        if (in.variable != 0) return std::nullopt;
        return problem("NCC7103", absl::StrCat(at(offset, in), ": #0 cannot be assigned"));
      case Operand::Code:
        if (in.code >= 0 && in.code <= kMaxFunctionCode) return std::nullopt;
        return problem("NCC7103", absl::StrCat(at(offset, in), ": code ", in.code,
                                               " out of range 0..", kMaxFunctionCode));
    }
    return std::nullopt;
  }

  // A run of instructions entered only at its first (a unit entry, a jump target, or the
  // instruction after a block's end) and left only after its last.
  struct Block {
    uint32_t start = 0;
    uint32_t last = 0;      // offset of its last instruction
    int need = 0;           // the entry depth it needs: max over its instructions of pops - depth
    int peak = 0;           // the highest depth it reaches, relative to its entry
    int delta = 0;          // depth at its end, relative to its entry
    bool falls_through = true;  // the last instruction continues at `next`
    bool jumps = false;         // the last instruction may continue at `target`
    bool ends = false;          // the last instruction ends the program
    uint32_t next = 0;
    uint32_t target = 0;
  };

  // Second pass: instruction starts, compared in order with the sorted jump targets, unit
  // entries and line entries; and the blocks. Records the first problem of each kind (in the
  // order a whole-code check would report it) for run() to report in its turn.
  std::optional<Error> scanBoundaries() {
    std::vector<std::pair<uint32_t, std::size_t>> targets;  // (target, jump index)
    for (std::size_t i = 0; i < jumps_.size(); ++i) targets.push_back({jumps_[i].second, i});
    std::vector<std::pair<uint32_t, std::size_t>> entries;  // (entry, unit index)
    for (std::size_t i = 0; i < program_.units.size(); ++i)
      entries.push_back({program_.units[i].entry, i});
    std::sort(targets.begin(), targets.end());
    std::sort(entries.begin(), entries.end());
    std::size_t next_target = 0, next_entry = 0, next_line = 0;
    std::optional<uint32_t> previous_line;
    bad_jump_ = jumps_.size();
    bad_unit_ = program_.units.size();

    // Passes the items before `boundary` (not instruction starts) and those at it; true when
    // one is at it (a block leader).
    auto reachBoundary = [&](uint64_t boundary) {
      bool leader = false;
      for (; next_target < targets.size() && targets[next_target].first <= boundary;
           ++next_target) {
        if (targets[next_target].first == boundary) leader = true;
        else bad_jump_ = std::min(bad_jump_, targets[next_target].second);
      }
      for (; next_entry < entries.size() && entries[next_entry].first <= boundary; ++next_entry) {
        if (entries[next_entry].first == boundary) leader = true;
        else bad_unit_ = std::min(bad_unit_, entries[next_entry].second);
      }
      while (!line_error_ && next_line < code_.lineCount()) {
        const std::optional<LineEntry> e = code_.line(next_line);
        if (!e) {
          line_error_ = problem("NCC7111", absl::StrCat("line table entry ", next_line,
                                                        ": cannot be read"));
          break;
        }
        if (e->offset > boundary) break;
        line_error_ = checkLine(next_line, *e, previous_line, e->offset == boundary);
        previous_line = e->offset;
        ++next_line;
      }
      return leader;
    };

    const uint32_t code_size = code_.codeSize();
    std::optional<Block> open;
    uint32_t offset = 0;
    while (offset < code_size) {
      const bool leader = reachBoundary(offset);
      if (open && leader) {
        open->next = offset;
        blocks_.push_back(*open);
        open.reset();
      }
      if (!open) open = Block{offset};
      Instruction in;
      uint32_t size = 0;
      if (code_.decode(offset, axis_count_, in, size) != DecodeStatus::Ok) return changed(offset);
      const OpcodeInfo& info = opcodeInfo(in.op);
      Block& b = *open;
      b.last = offset;
      b.need = std::max(b.need, info.pops - b.delta);
      b.delta += info.pushes - info.pops;
      b.peak = std::max(b.peak, b.delta);
      offset += size;
      if (info.flow != Flow::Next) {
        b.falls_through = info.flow == Flow::Branch;
        b.jumps = info.flow == Flow::Branch || info.flow == Flow::Jump;
        b.ends = info.flow == Flow::Stop;
        b.target = in.target;
        b.next = offset;
        blocks_.push_back(b);
        open.reset();
      }
    }
    if (open) {  // the last instruction falls through past the end of the code
      open->next = code_size;
      blocks_.push_back(*open);
    }
    // Everything left is at or beyond the end of the code: no instruction starts there.
    reachBoundary(std::numeric_limits<uint64_t>::max());
    return std::nullopt;
  }

  // An instruction the first pass decoded does not decode again: a paged program's file was
  // changed (or could not be read) while it was verified.
  static Error changed(uint32_t offset) {
    return problem("NCC7101", absl::StrCat(at(offset), ": the instruction reads differently "
                                           "than before (was the file changed?)"));
  }

  std::optional<Error> checkLine(std::size_t i, const LineEntry& e,
                                 std::optional<uint32_t> previous, bool starts) {
    auto where = [&] { return absl::StrCat("line table entry ", i); };
    if (previous && e.offset <= *previous)
      return problem("NCC7111", absl::StrCat(where(), ": offset ",
                                             absl::Hex(e.offset, absl::kZeroPad6),
                                             " does not increase"));
    if (!starts)
      return problem("NCC7111", absl::StrCat(where(), ": offset ",
                                             absl::Hex(e.offset, absl::kZeroPad6),
                                             " is not the start of an instruction"));
    if (e.file >= program_.strings.size())
      return problem("NCC7111", absl::StrCat(where(), ": file string ", e.file,
                                             " does not exist"));
    return std::nullopt;
  }

  std::optional<Error> checkJumps() {
    if (bad_jump_ == jumps_.size()) return std::nullopt;
    const auto& [offset, target] = jumps_[bad_jump_];
    return problem("NCC7105", absl::StrCat(at(offset), ": jump target ",
                                           absl::Hex(target, absl::kZeroPad6),
                                           " is not the start of an instruction"));
  }

  std::optional<Error> checkUnits() {
    for (size_t i = 0; i < program_.units.size(); ++i) {
      const Unit& unit = program_.units[i];
      if (i == bad_unit_)
        return problem("NCC7112", absl::StrCat("unit ", i, ": entry ",
                                               absl::Hex(unit.entry, absl::kZeroPad6),
                                               " is not the start of an instruction"));
      if (unit.name >= program_.strings.size())
        return problem("NCC7112", absl::StrCat("unit ", i, ": name string ", unit.name,
                                               " does not exist"));
    }
    return std::nullopt;
  }

  // The block starting at `offset` (a checked instruction start that begins a block).
  std::size_t blockAt(uint32_t offset) const {
    auto it = std::lower_bound(blocks_.begin(), blocks_.end(), offset,
                               [](const Block& b, uint32_t o) { return b.start < o; });
    return static_cast<std::size_t>(it - blocks_.begin());
  }

  // The problem a block entered at depth `d` has, found by running its instructions again.
  std::optional<Error> blockProblem(const Block& b, int d) {
    for (uint32_t offset = b.start; offset <= b.last;) {
      Instruction in;
      uint32_t size = 0;
      if (code_.decode(offset, axis_count_, in, size) != DecodeStatus::Ok) return changed(offset);
      const OpcodeInfo& info = opcodeInfo(in.op);
      if (d < info.pops)
        return problem("NCC7106", absl::StrCat(at(offset, in), ": needs ", int{info.pops},
                                               " values, the stack holds ", d));
      d = d - info.pops + info.pushes;
      if (d > kMaxStackDepth)
        return problem("NCC7107", absl::StrCat(at(offset, in), ": stack deeper than ",
                                               kMaxStackDepth));
      offset += size;
    }
    return std::nullopt;
  }

  // Abstract interpretation of the stack depth over the blocks, from every unit entry.
  std::optional<Error> checkStackAndFlow() {
    const uint32_t code_size = code_.codeSize();
    std::vector<int> depth(blocks_.size(), -1);  // at each block's entry
    std::vector<std::size_t> work;
    bool end_reachable = false;
    auto reach = [&](uint32_t from, uint32_t to, int d) -> std::optional<Error> {
      if (to >= code_size)
        return problem("NCC7109", absl::StrCat(at(from), ": execution runs past the end of "
                                               "the code (no END)"));
      const std::size_t i = blockAt(to);
      if (depth[i] < 0) {
        depth[i] = d;
        work.push_back(i);
      } else if (depth[i] != d) {
        return problem("NCC7108", absl::StrCat(at(to), ": stack depth ", d, " from ", at(from),
                                               " differs from depth ", depth[i],
                                               " on another path"));
      }
      return std::nullopt;
    };
    for (const Unit& unit : program_.units) {
      const std::size_t i = blockAt(unit.entry);
      if (depth[i] < 0) {
        depth[i] = 0;
        work.push_back(i);
      }
    }
    while (!work.empty()) {
      const Block& b = blocks_[work.back()];
      const int d = depth[work.back()];
      work.pop_back();
      if (d < b.need || d + b.peak > kMaxStackDepth) return blockProblem(b, d);
      const int out = d + b.delta;
      if (b.ends) end_reachable = true;
      if (b.jumps)
        if (auto e = reach(b.last, b.target, out)) return e;
      if (b.falls_through)
        if (auto e = reach(b.last, b.next, out)) return e;
    }
    if (!end_reachable)
      return problem("NCC7110", "no END, M02 or M30 is reachable: the program never ends");
    return std::nullopt;
  }

  const Program& program_;
  const VerifyOptions& options_;
  const int axis_count_;
  CodeView code_;
  std::vector<std::pair<uint32_t, uint32_t>> jumps_;  // (jump offset, target), in code order
  std::vector<Block> blocks_;                          // in code order
  std::size_t bad_jump_ = 0;  // first jump whose target is no instruction start (or none)
  std::size_t bad_unit_ = 0;  // first unit whose entry is no instruction start (or none)
  std::optional<Error> line_error_;  // first problem of the line table
};

}  // namespace

std::optional<Error> verify(const Program& program, const VerifyOptions& options) {
  return Verifier(program, options).run();
}

}  // namespace ncc::bytecode
