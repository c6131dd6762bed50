#include "compensation_harness.h"

#include <variant>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "compensation/compensation_pass.h"

namespace ncc::passes::testing {

namespace {

struct Collect : ir::BlockSink {
  void accept(ir::Block&& b) override { blocks.push_back(std::move(b)); }
  void finish() override {}
  std::vector<ir::Block> blocks;
};

std::string num(double v) {
  if (std::abs(v) < 5e-4) v = 0.0;  // no "-0.000"
  return absl::StrFormat("%.3f", v);
}

}  // namespace

CompProgram& CompProgram::side(ir::CutterComp::Side side, double radius) {
  if (side == ir::CutterComp::Side::Off) {
    cancelling_ = on_;
  } else {
    on_ = true;
    commanded_ = true;
  }
  side_ = side;
  radius_ = radius;
  return *this;
}

ir::Block CompProgram::next(ir::Operation op) {
  ir::Block b;
  b.loc = SourceLocation{1, static_cast<uint32_t>(blocks_.size() + 1), 1};
  b.ops.push_back(std::move(op));
  b.modal.feed_mode = feed_mode_;
  if (on_ || cancelling_) {
    ir::CutterComp c = settings_;
    c.side = side_;
    c.radius = radius_;
    c.d_number = 1;
    c.side_commanded = commanded_;
    c.special = next_.special;
    c.vector = next_.vector;
    c.suspended = next_.suspended;
    b.comp = c;
    if (side_ == ir::CutterComp::Side::Off) on_ = cancelling_ = false;
  }
  commanded_ = false;
  next_ = {};
  return b;
}

CompProgram& CompProgram::rapid(double x, double y, double z) {
  blocks_.push_back(next(ir::Rapid{{x, y, z}, ir::Space::Work}));
  return *this;
}
CompProgram& CompProgram::line(double x, double y, double z, double feed) {
  blocks_.push_back(next(ir::Linear{{x, y, z}, ir::Space::Work, feed}));
  return *this;
}
CompProgram& CompProgram::arc(double x, double y, double cx, double cy, bool clockwise, double z) {
  ir::Arc a;
  a.to = {x, y, z};
  a.center = {cx, cy, 0};
  a.clockwise = clockwise;
  a.feed = 100.0;
  blocks_.push_back(next(a));
  return *this;
}
CompProgram& CompProgram::still() {
  ir::MachineFunction m;
  m.kind = ir::MachineFunction::Kind::CoolantOn;
  blocks_.push_back(next(m));
  return *this;
}
CompProgram& CompProgram::machineRapid(double x, double y, double z) {
  blocks_.push_back(next(ir::Rapid{{x, y, z}, ir::Space::Machine}));
  return *this;
}

std::vector<ir::Block> CompProgram::runBlocks() {
  Collect out;
  CompensationPass pass(out, dialect_, diags_);
  for (ir::Block& b : blocks_) pass.accept(ir::Block(b));
  pass.finish();
  return out.blocks;
}

std::string CompProgram::run() { return movesText(runBlocks()); }

std::string movesText(const std::vector<ir::Block>& blocks) {
  std::string out;
  for (const ir::Block& b : blocks)
    for (const ir::Operation& op : b.ops) {
      const std::string at = absl::StrCat(b.loc.line, ": ");
      if (const auto* r = std::get_if<ir::Rapid>(&op))
        absl::StrAppend(&out, at, "R ", num(r->to[0]), " ", num(r->to[1]), "\n");
      else if (const auto* l = std::get_if<ir::Linear>(&op))
        absl::StrAppend(&out, at, "L ", num(l->to[0]), " ", num(l->to[1]), "\n");
      else if (const auto* a = std::get_if<ir::Arc>(&op))
        absl::StrAppend(&out, at, "A ", num(a->to[0]), " ", num(a->to[1]), " ", num(a->center[0]),
                        " ", num(a->center[1]), a->clockwise ? " cw" : " ccw",
                        std::abs(a->to[2]) >= 5e-4 ? absl::StrCat(" z", num(a->to[2])) : "", "\n");
    }
  return out;
}

}  // namespace ncc::passes::testing
