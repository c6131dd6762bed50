#include "ncc/ir/printer.h"

#include <cstdio>
#include <sstream>

#include "absl/strings/str_cat.h"

namespace ncc::ir {

namespace {

// Fixed three decimals; a value that rounds to zero prints without a minus sign.
std::string num(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.3f", v);
  std::string s = buffer;
  if (s == "-0.000") s = "0.000";
  return s;
}

std::string axisList(const AxisValues& values, const AxisNames& axes, AxisMask mask = 0xFFFF) {
  std::string out;
  for (size_t i = 0; i < axes.size() && i < static_cast<size_t>(kMaxAxes); ++i) {
    if ((mask & (1u << i)) == 0) continue;
    absl::StrAppend(&out, out.empty() ? "" : " ", axes[i], num(values[i]));
  }
  return out;
}

bool allZero(const AxisValues& values) {
  for (double v : values)
    if (v != 0.0) return false;
  return true;
}


// The names of a plane's two axes, in the order their centre coordinates are given (I J / K I / J K).
std::pair<const char*, const char*> planeAxes(Plane p) {
  switch (p) {
    case Plane::XY: return {"X", "Y"};
    case Plane::ZX: return {"Z", "X"};
    case Plane::YZ: return {"Y", "Z"};
  }
  return {"X", "Y"};
}

AxisMask maskOfNames(const AxisNames& axes, std::pair<const char*, const char*> names) {
  AxisMask mask = 0;
  for (size_t i = 0; i < axes.size(); ++i)
    if (axes[i] == names.first || axes[i] == names.second) mask |= static_cast<AxisMask>(1u << i);
  return mask;
}

const char* spaceName(Space s) { return s == Space::Machine ? "machine" : "work"; }

std::string modalText(const Modal& m) {
  const char* distance = m.distance == DistanceMode::Absolute ? "G90" : "G91";
  const char* units = m.units == Units::Millimetre ? "G21" : "G20";
  const char* feed_mode = m.feed_mode == FeedMode::PerMinute      ? "G94"
                          : m.feed_mode == FeedMode::PerRevolution ? "G95"
                                                                   : "G93";
  const char* path = m.path == PathControl::Continuous  ? "G64"
                     : m.path == PathControl::ExactStop ? "G61"
                     : m.path == PathControl::Tapping   ? "G63"
                                                        : "G62";
  const char* length = m.length_offset_sign > 0 ? "G43" : m.length_offset_sign < 0 ? "G44" : "G49";
  return absl::StrCat(planeCode(m.plane), " ", distance, " ", units, " ", feed_mode, " ", path, " ",
                      m.work_offset.c_str(), " ", length, " H", m.length_offset_h, " T", m.tool, " F",
                      num(m.feed), " S", num(m.spindle_speed));
}

std::string machineFunctionText(const MachineFunction& f) {
  using K = MachineFunction::Kind;
  switch (f.kind) {
    case K::ProgramStop: return "M00";
    case K::OptionalStop: return "M01";
    case K::ProgramEnd: return "M02";
    case K::ProgramEndRewind: return "M30";
    case K::SpindleCW: return "M03";
    case K::SpindleCCW: return "M04";
    case K::SpindleStop: return "M05";
    case K::ToolChange: return "M06";
    case K::CoolantOn: return "M08";
    case K::CoolantOff: return "M09";
    case K::SpindleOrient: return "M19";
    case K::OtherM: return absl::StrCat("M", f.code);
    case K::SpindleSpeed: return absl::StrCat("S", num(f.value));
    case K::ToolSelect: return absl::StrCat("T", f.code);
  }
  return "M?";
}

struct OperationPrinter {
  const AxisNames& axes;

  std::string operator()(const Rapid& r) const {
    return absl::StrCat("rapid ", spaceName(r.space), " ", axisList(r.to, axes),
                        r.type == RapidType::PerAxis ? " per-axis" : "");
  }
  std::string operator()(const Linear& l) const {
    return absl::StrCat("line ", spaceName(l.space), " ", axisList(l.to, axes), " F", num(l.feed),
                        l.feed_per_rev ? " per-rev" : "");
  }
  std::string operator()(const Arc& a) const {
    std::string out = absl::StrCat("arc ", spaceName(a.space), " ", planeCode(a.plane),
                                   a.clockwise ? " cw " : " ccw ", axisList(a.to, axes),
                                   " centre ",
                                   axisList(a.center, axes, maskOfNames(axes, planeAxes(a.plane))),
                                   " F", num(a.feed));
    if (a.extra_turns != 0) absl::StrAppend(&out, " turns ", a.extra_turns);
    if (a.feed_per_rev) absl::StrAppend(&out, " per-rev");
    return out;
  }
  std::string operator()(const Skip& s) const {
    std::string out = absl::StrCat("skip ", spaceName(s.space), " ", axisList(s.to, axes), " F",
                                   num(s.feed), s.feed_per_rev ? " per-rev" : "");
    if (s.first_variable != 0)
      absl::StrAppend(&out, " position #", s.first_variable, s.inch_variables ? " inch" : "");
    return out;
  }
  std::string operator()(const Dwell& d) const {
    return absl::StrCat("dwell ", num(d.seconds), d.revolutions ? " rev" : " s");
  }
  std::string operator()(const MachineFunction& f) const { return machineFunctionText(f); }
  std::string operator()(const ReferenceCheck& c) const {
    return absl::StrCat("refcheck ref", c.reference, " ", axisList(c.position, axes, c.axes));
  }
  std::string operator()(const Prepare& p) const {
    return absl::StrCat("prepare at run time after ", p.ahead_blocks, " blocks (store: ", p.files,
                        " files, ", p.blocks, " blocks, ", p.store ? p.store->size() : 0,
                        " bytes)");
  }
  std::string operator()(const HoleCycle& c) const {
    static constexpr const char* kKinds[] = {"drill", "high-speed-peck", "peck", "tap",
                                             "fine-bore", "back-bore"};
    std::string out = absl::StrCat("cycle G", c.code10 / 10,
                                   c.code10 % 10 ? absl::StrCat(".", c.code10 % 10) : "", " ",
                                   kKinds[static_cast<int>(c.kind)],
                                   " work ", axisList(c.hole, axes), " initial ", num(c.initial),
                                   " R", num(c.r_level), " bottom ", num(c.bottom),
                                   c.return_to_r ? " G99" : " G98", " F", num(c.feed),
                                   c.feed_per_rev ? " per-rev" : "");
    if (c.peck > 0) absl::StrAppend(&out, " Q", num(c.peck), " d", num(c.peck_distance));
    if (c.dwell > 0) absl::StrAppend(&out, " dwell ", num(c.dwell), c.dwell_revolutions ? " rev" : " s");
    if (c.feed_out) absl::StrAppend(&out, " out F", num(c.retract_feed));
    if (c.stop_spindle_at_bottom) absl::StrAppend(&out, " spindle-stop");
    if (c.program_stop_at_bottom) absl::StrAppend(&out, " program-stop");
    if (!allZero(c.shift)) absl::StrAppend(&out, " shift(", axisList(c.shift, axes), ")");
    return out;
  }
  std::string operator()(const SetVariable& v) const {
    return absl::StrCat("set ", v.name.empty() ? absl::StrCat("#", v.number) : v.name.str(), " = ",
                        v.vacant ? "vacant" : num(v.value));
  }
};

}  // namespace

const char* planeCode(Plane p) {
  switch (p) {
    case Plane::XY: return "G17";
    case Plane::ZX: return "G18";
    case Plane::YZ: return "G19";
  }
  return "G17";
}

void printBlock(std::ostream& out, const Block& block, const AxisNames& axes) {
  out << "block " << block.loc.file << ":" << block.loc.line << ":" << block.loc.column;
  if (block.sequence >= 0) out << " N" << block.sequence;
  out << " " << modalText(block.modal);
  if (block.exact_stop) out << " exact-stop";
  if (!allZero(block.frame.work_offset))
    out << " offset(" << axisList(block.frame.work_offset, axes) << ")";
  if (!allZero(block.frame.shift)) out << " shift(" << axisList(block.frame.shift, axes) << ")";
  if (!allZero(block.frame.tool_length))
    out << " tool(" << axisList(block.frame.tool_length, axes) << ")";
  // Before the transform pass: the map of programmed points (rows of m | t over X Y Z).
  for (const auto& [name, a] : {std::pair{" transform(", &block.transform.work},
                                std::pair{" machine-rotation(", &block.transform.machine}}) {
    if (!*a) continue;
    out << name;
    for (int r = 0; r < 3; ++r)
      out << (r ? "; " : "") << num((*a)->m[3 * r]) << " " << num((*a)->m[3 * r + 1]) << " "
          << num((*a)->m[3 * r + 2]) << " | " << num((*a)->t[r]);
    out << ")";
  }
  if (block.corner)  // ,C / ,R not yet inserted (before the corners pass)
    out << (block.corner->kind == CornerRequest::Kind::Chamfer         ? " chamfer("
            : block.corner->kind == CornerRequest::Kind::ChamferLength ? " chamfer_length("
                                                                       : " round(")
        << num(block.corner->amount) << ")";
  if (block.comp) {  // before the compensation pass: the side, the radius and the specials
    const CutterComp& c = *block.comp;
    static constexpr const char* kSide[] = {"off", "left", "right"};
    out << " comp(" << kSide[static_cast<int>(c.side)] << " D" << c.d_number << "="
        << num(c.radius);
    if (c.side_commanded) out << " commanded";
    if (c.special == CutterComp::Special::VectorHold) out << " hold";
    if (c.special == CutterComp::Special::CornerArc) out << " corner-arc";
    if (c.vector)
      out << " vector " << num((*c.vector)[0]) << " " << num((*c.vector)[1]) << " "
          << num((*c.vector)[2]);
    if (c.offset_3d)
      out << " 3d " << num((*c.offset_3d)[0]) << " " << num((*c.offset_3d)[1]) << " "
          << num((*c.offset_3d)[2]);
    out << ")";
  }
  out << "\n";
  for (const Operation& op : block.ops) out << "  " << std::visit(OperationPrinter{axes}, op) << "\n";
}

std::string printBlock(const Block& block, const AxisNames& axes) {
  std::ostringstream out;
  printBlock(out, block, axes);
  return out.str();
}

}  // namespace ncc::ir
