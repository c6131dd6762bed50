#include "run_budget.h"

#include <variant>

#include "absl/strings/str_cat.h"
#include "ncc/backend/encode.h"
#include "ncc/vm/executor.h"
#include "ncc/vm/run_limits.h"

namespace ncc::driver {

namespace {
// The highest feed override a run can set (vm::ControllerOptions, 200 %): the compile's bound
// holds for any run of the program.
constexpr double kHighestFeedOverride = 2.0;
}  // namespace

RunBudgetSink::RunBudgetSink(const MachineConfig& machine, const RunBounds& bounds,
                             ir::BlockSink& next)
    : machine_(machine), bounds_(bounds), next_(next) {}

double RunBudgetSink::leastSeconds(const ir::Operation& op, const ir::Block& block) {
  using Kind = vm::MotionPrimitive::Kind;
  vm::MotionPrimitive m;
  if (const auto* d = std::get_if<ir::Dwell>(&op)) {
    m.kind = Kind::Dwell;
    m.seconds = d->seconds;
    m.revolutions = d->revolutions;
    return vm::minimumSeconds(m, machine_, kHighestFeedOverride, spindle_rpm_);
  }
  if (const auto* f = std::get_if<ir::MachineFunction>(&op)) {
    if (f->kind == ir::MachineFunction::Kind::SpindleSpeed) spindle_rpm_ = f->value;
    return 0.0;
  }
  if (std::holds_alternative<ir::Skip>(op)) {
    at_known_ = false;  // it ends where the probe stops it
    return 0.0;
  }
  m.from = at_;
  if (const auto* r = std::get_if<ir::Rapid>(&op)) {
    m.kind = Kind::Rapid;
    m.to = r->to;
  } else if (const auto* l = std::get_if<ir::Linear>(&op)) {
    m.kind = Kind::Line;
    m.to = l->to;
    m.feed = l->feed;
    m.feed_per_rev = l->feed_per_rev;
  } else if (std::holds_alternative<ir::Arc>(op)) {
    // As the VM receives it: the backend's one mapping gives the plane's machine axes.
    const backend::EncodedOperation code = backend::encodeOperation(op, block, machine_);
    if (code.error || code.count == 0) return 0.0;
    const bytecode::Instruction& in = code.instructions[0];
    vm::setArcOperands(in, m);
    m.to = in.axes;
    m.feed = in.value;
    m.feed_per_rev = (in.flags & bytecode::kFlagFeedPerRev) != 0;
  } else {
    return 0.0;
  }
  const bool counted = at_known_;
  at_ = m.to;
  at_known_ = true;
  return counted ? vm::minimumSeconds(m, machine_, kHighestFeedOverride, spindle_rpm_) : 0.0;
}

void RunBudgetSink::accept(ir::Block&& block) {
  if (exceeded_) return;
  if (!prepared_) {
    for (const ir::Operation& op : block.ops) {
      if (std::holds_alternative<ir::Prepare>(op)) prepared_ = true;
      if (prepared_) break;
      ++steps_;
      if (bounds_.max_seconds > 0.0) seconds_ += leastSeconds(op, block);
    }
  }
  const SourceLocation loc = block.loc;
  next_.accept(std::move(block));
  if (bounds_.max_seconds > 0.0 && seconds_ > bounds_.max_seconds) {
    exceeded_ = Exceeded{loc, "NCC7208",
                         absl::StrCat("simulated time limit ", bounds_.max_seconds,
                                      " s reached: the run needs at least ", seconds_,
                                      " s by the end of this block (at the machine's top speed; "
                                      "the limit is --max-time)")};
  } else if (bounds_.max_steps > 0 && steps_ > bounds_.max_steps) {
    exceeded_ = Exceeded{loc, "NCC7204",
                         absl::StrCat("step limit reached: the run needs more than ",
                                      bounds_.max_steps,
                                      " VM instructions by this block (the limit is --max-steps)")};
  }
}

}  // namespace ncc::driver
