#include "ncc/ir/verifier.h"

#include <cmath>

#include "absl/strings/str_cat.h"

namespace ncc::ir {

namespace {

// Collects the problems of one block; `where` names the operation being checked.
class BlockChecker {
 public:
  BlockChecker(const VerifyOptions& options, std::vector<std::string>& problems)
      : options_(options), problems_(problems) {}

  void operator()(const Rapid& r) {
    space(r.space);
    axes(r.to, "target");
  }
  void operator()(const Linear& l) {
    space(l.space);
    axes(l.to, "target");
    feed(l.feed);
  }
  void operator()(const Arc& a) {
    space(a.space);
    axes(a.to, "target");
    axes(a.center, "centre");
    feed(a.feed);
  }
  void operator()(const Skip& s) {
    space(s.space);
    axes(s.to, "target");
    feed(s.feed);
  }
  void operator()(const Dwell& d) {
    if (!std::isfinite(d.seconds) || d.seconds < 0.0)
      add(absl::StrCat("dwell ", d.seconds, " is not a finite non-negative amount"));
  }
  void operator()(const MachineFunction& f) {
    using K = MachineFunction::Kind;
    if ((f.kind == K::OtherM || f.kind == K::ToolSelect) && f.code < 0)
      add(absl::StrCat("negative M/T code ", f.code));
    if (f.kind == K::SpindleSpeed && (!std::isfinite(f.value) || f.value < 0.0))
      add(absl::StrCat("spindle speed ", f.value, " is not a finite non-negative value"));
  }
  void operator()(const SetVariable& v) {
    if (v.number == 0) add("assignment to #0 (always vacant)");
    // ISO numbers end at #9999; a DIN variable above them has its name (named_variables.h).
    if (v.number >= 10000 && v.name.empty()) add(absl::StrCat("variable #", v.number, " without a name"));
    if (!v.vacant && !std::isfinite(v.value)) add(absl::StrCat("variable value ", v.value, " is not finite"));
  }
  void operator()(const Prepare& p) {
    if (!p.store || p.store->empty()) add("prepare without a block store");
  }
  void operator()(const HoleCycle& c) {
    // Only in work space, before the `cycles` pass replaces it: never in the backend's input.
    if (options_.require_machine_space) add("a hole cycle reached the backend (the cycles pass did not run)");
    axes(c.hole, "hole position");
    if (c.axis < 0 || c.axis >= options_.axis_count) add(absl::StrCat("drilling axis ", c.axis));
    for (double v : {c.initial, c.r_level, c.bottom, c.peck, c.peck_distance, c.dwell})
      if (!std::isfinite(v)) add("a hole cycle level or amount is not finite");
    feed(c.feed);
    if ((c.kind == HoleCycle::Kind::Peck || c.kind == HoleCycle::Kind::HighSpeedPeck) &&
        !(c.peck > 0.0))
      add(absl::StrCat("peck depth ", c.peck, " is not positive"));
  }
  void operator()(const ReferenceCheck& c) {
    axes(c.position, "position");
    const unsigned all = (1u << options_.axis_count) - 1u;
    if (c.axes == 0 || (c.axes & ~all) != 0)
      add(absl::StrCat("reference check axis mask ", c.axes, " is empty or names an axis beyond ",
                       options_.axis_count));
    if (c.reference < 1 || c.reference > 4)
      add(absl::StrCat("reference point ", c.reference, " (1 to 4)"));
  }

  void setOperation(size_t index) { where_ = absl::StrCat("operation ", index + 1, ": "); }
  void setBlock() { where_ = "block: "; }

  void frame(const Frame& f) {
    axes(f.work_offset, "work offset");
    axes(f.shift, "shift");
    axes(f.tool_length, "tool length");
  }
  void transform(const Transform& t) {
    // Only before the `transform` pass applies them: never in the backend's input.
    if (options_.require_machine_space && t.any())
      add("a coordinate transform reached the backend (the transform pass did not run)");
    for (const auto& a : {t.work, t.machine}) {
      if (!a) continue;
      for (double v : a->m)
        if (!std::isfinite(v)) add("a transform coefficient is not finite");
      for (double v : a->t)
        if (!std::isfinite(v)) add("a transform translation is not finite");
      for (int8_t i : a->axes)
        if (i < -1 || i >= options_.axis_count) add(absl::StrCat("transform axis index ", i));
    }
  }
  void comp(const std::optional<CutterComp>& c) {
    // Only before the `compensation` pass turns it into the tool centre's path.
    if (!c) return;
    if (options_.require_machine_space)
      add("a cutter compensation request reached the backend (the compensation pass did not run)");
    if (!std::isfinite(c->radius)) add("compensation radius is not finite");
    for (const auto& v : {c->vector, c->offset_3d})
      if (v)
        for (double x : *v)
          if (!std::isfinite(x)) add("compensation vector is not finite");
  }
  void modal(const Modal& m) {
    if (!std::isfinite(m.feed) || m.feed < 0.0) add(absl::StrCat("modal feed ", m.feed));
    if (!std::isfinite(m.spindle_speed) || m.spindle_speed < 0.0)
      add(absl::StrCat("modal spindle speed ", m.spindle_speed));
  }

 private:
  void add(std::string message) { problems_.push_back(absl::StrCat(where_, message)); }
  void space(Space s) {
    if (options_.require_machine_space && s != Space::Machine)
      add("work-space target reached the backend (the coordinate transform did not run)");
  }
  void axes(const AxisValues& v, const char* what) {
    for (int i = 0; i < options_.axis_count; ++i)
      if (!std::isfinite(v[i])) add(absl::StrCat(what, " of axis ", i + 1, " is not finite"));
  }
  void feed(double f) {
    if (!std::isfinite(f) || f <= 0.0) add(absl::StrCat("feed ", f, " is not positive"));
  }

  const VerifyOptions& options_;
  std::vector<std::string>& problems_;
  std::string where_;
};

}  // namespace

std::vector<std::string> verify(const Block& block, const VerifyOptions& options) {
  std::vector<std::string> problems;
  if (options.axis_count < 1 || options.axis_count > kMaxAxes) {
    problems.push_back(absl::StrCat("axis count ", options.axis_count, " (1 to ", kMaxAxes, ")"));
    return problems;
  }
  BlockChecker checker(options, problems);
  checker.setBlock();
  checker.modal(block.modal);
  checker.frame(block.frame);
  checker.transform(block.transform);
  checker.comp(block.comp);
  for (size_t i = 0; i < block.ops.size(); ++i) {
    checker.setOperation(i);
    std::visit(checker, block.ops[i]);
  }
  return problems;
}

void VerifyingSink::accept(Block&& block) {
  std::vector<std::string> problems = verify(block, options_);
  if (problems.empty()) {
    next_.accept(std::move(block));
    return;
  }
  // A compiler bug: report it where the block came from and keep it out of the output.
  for (const std::string& p : problems)
    diags_.error("NCC9001", block.loc, absl::StrCat("internal error: invalid IR: ", p));
}

}  // namespace ncc::ir
