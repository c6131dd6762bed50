// G31 skip: a linear move that ends where the skip signal comes on (Mazak §4.10, FANUC,
// Sinumerik ISO "G31 X Y Z F"). Where it stops is known only when the program runs: the VM
// simulates the signal ([machine.probe]) and stores the stop point in the skip-position
// variables (#5061..). Lowering emits ir::Skip and marks the moved axes as known at run time
// only (ControllerState::skip_axes); a later block that needs them ends the compiler's
// preparation there (the VM prepares the rest, knowing where G31 stopped: docs/runtime.md);
// an absolute word makes an axis known again.
#include <cmath>

#include "absl/strings/str_cat.h"
#include "lowering_context.h"

namespace ncc::passes {

namespace {

// The first skip-position variable of the dialect (#5061), 0 when it has none (Siemens ISO
// latches $AA_MW, not a numbered variable).
uint32_t firstSkipVariable(const DialectTable& table) {
  for (const SystemVariableRange& r : table.system_variables)
    if (r.kind == SystemVariable::SkipPosition) return static_cast<uint32_t>(r.first);
  return 0;
}

// Axis words that are positions (not a dwell time, an offset value or a shift amount).
bool wordsArePositions(const DecodedBlock& w) {
  if (!w.one_shot) return true;
  switch (w.one_shot->entry->action) {
    case GAction::Dwell:
    case GAction::DwellFeedOrSpindle:
    case GAction::DataSet:
    case GAction::LocalShift:
      return false;
    default:
      return true;
  }
}

bool moves(const ir::Operations& ops) {
  for (const ir::Operation& op : ops)
    if (ir::isMove(op)) return true;
  return false;
}

std::string axisNames(const BlockContext& ctx, AxisMask mask) {
  std::string out;
  for (int i = 0; i < ctx.axisCount(); ++i)
    if (mask & (1u << i))
      absl::StrAppend(&out, out.empty() ? "" : ", ", ctx.core.machine->axes[i].name);
  return out;
}

}  // namespace

void skipMove(BlockContext& ctx, const GWord& g) {
  if (!ctx.words.anyAxis()) {
    ctx.fail(Alarm::AxisMissing, g.loc,
             absl::StrCat(gCodeName(g.entry->code10),
                          " needs the end point of the skip move (an axis word)"));
    return;
  }
  ir::Modal& m = ctx.next.modal;
  double feed = 0.0;
  if (ctx.behaviour.skip_feed_is_modal) {
    if (!checkFeed(ctx, true)) return;
    feed = m.feed;
  } else {
    // Mazak §4.10: the block's own F; without it the K41 feed, which is 0 (an error) since
    // ncc has no K41. The modal F stays what it was.
    if (!ctx.words.f || m.feed <= 0) {
      ctx.fail(Alarm::FeedMissing, ctx.words.f ? ctx.words.f->loc : g.loc,
               absl::StrCat(gCodeName(g.entry->code10),
                            " needs its own F: the modal F does not apply to a skip move "
                            "(parameter K41 = 0)"));
      return;
    }
    feed = m.feed;
    if (m.feed_mode == ctx.core.cs().modal.feed_mode) {
      m.feed = ctx.core.cs().modal.feed;
      ctx.next.feed_programmed = ctx.core.cs().feed_programmed;
    }
  }
  const ir::Frame frame = frameOf(ctx.next, ctx.behaviour);
  const AxisValues target = ctx.workTargets(ctx.baseWork());
  const AxisValues to_machine = ctx.toMachine(target, frame);
  if (m.feed_mode == ir::FeedMode::InverseTime) {
    double length = 0.0;
    for (int i = 0; i < ctx.axisCount(); ++i)
      length += (to_machine[i] - ctx.next.position[i]) * (to_machine[i] - ctx.next.position[i]);
    feed *= std::sqrt(length);
  }
  ir::Skip skip;
  skip.to = target;
  skip.space = ir::Space::Work;
  skip.feed = feed;
  skip.feed_per_rev = m.feed_mode == ir::FeedMode::PerRevolution;
  skip.first_variable = firstSkipVariable(ctx.table);
  skip.inch_variables = m.units == ir::Units::Inch;
  if (skip.feed > 0) ctx.ops.push_back(skip);
  for (int i = 0; i < ctx.axisCount(); ++i)
    if (std::fabs(to_machine[i] - ctx.next.position[i]) > kSamePoint)
      ctx.skip_moved |= static_cast<AxisMask>(1u << i);
  ctx.next.position = to_machine;
  ctx.lengthChangeTraversed();
}

void checkSkipDependence(BlockContext& ctx) {
  const AxisMask unknown = ctx.core.cs().skip_axes;
  if (ctx.failed || ctx.silent) return;
  if (unknown == 0) {
    ctx.next.skip_axes = ctx.skip_moved;
    return;
  }
  const DecodedBlock& w = ctx.words;
  AxisMask known_again = 0;
  if (wordsArePositions(w)) {
    const bool set_shift = w.one_shot && w.one_shot->entry->action == GAction::SetShift;
    for (int i = 0; i < ctx.axisCount(); ++i) {
      const auto bit = static_cast<AxisMask>(1u << i);
      if (!w.axes[i] || !(unknown & bit)) continue;
      const WordValue& word = *w.axes[i];
      if (word.mode == ir::DistanceMode::Incremental || set_shift) {
        ctx.needRunTime(word.loc,
                        absl::StrCat(set_shift ? "G92 " : "the incremental ", std::string(word.address),
                                     set_shift ? " sets the shift from" : " starts from",
                                     " the position where G31 stopped"));
        return;
      }
      known_again |= bit;
    }
  }
  // Every move carries all axes: one the block does not program would go back to where G31
  // was told to go, not stay where it stopped.
  const AxisMask kept = unknown & ~known_again;
  if (kept != 0 && moves(ctx.ops)) {
    ctx.needRunTime(ctx.motionLoc(),
                    absl::StrCat("this move keeps ", axisNames(ctx, kept), " where G31 stopped"));
    return;
  }
  ctx.next.skip_axes = kept | ctx.skip_moved;
}

}  // namespace ncc::passes
