// Coordinate systems: everything that makes up the frame between work and machine
// coordinates except the tool length: selection of the work system (G54-G59, G54.1 P /
// G54 P), its G10 L2/L20 writes and the external offset, the G52 local shift, the G92 shift
// and its G92.1 reset, and the G53 move that bypasses the frame.
#include "absl/strings/str_cat.h"
#include "lowering_context.h"

namespace ncc::passes {

namespace {

// The name of additional work system n: "G54.1P<n>", or "G54P<n>" where G54 P selects it.
std::string extendedName(const BlockContext& ctx, int64_t n) {
  return absl::StrCat(ctx.behaviour.extended_offset_is_g54_p ? "G54P" : "G54.1P", n);
}

bool isExtended(std::string_view name) {
  return name.rfind("G54P", 0) == 0 || name.rfind("G54.1P", 0) == 0;
}

// Whether the one-shot code of the block reads P itself.
bool oneShotTakesP(const BlockContext& ctx) {
  if (!ctx.words.one_shot) return false;
  GAction a = ctx.words.one_shot->entry->action;
  return a == GAction::Dwell || a == GAction::DataSet || a == GAction::ReferenceReturnN ||
         a == GAction::ReferenceCheck;
}

}  // namespace

void selectWorkOffset(BlockContext& ctx, const GWord& w) {
  const GCodeEntry& e = *w.entry;
  std::string name = gCodeName(e.code10);
  bool extended = e.action == GAction::WorkOffsetExtended ||
                  (ctx.behaviour.extended_offset_is_g54_p && e.work_index == 1 && ctx.words.p &&
                   !oneShotTakesP(ctx));
  if (extended) {
    if (!ctx.words.p) {
      ctx.fail(Alarm::ExtendedOffsetNumber, w.loc,
               absl::StrCat(name, " needs P1-P", ctx.behaviour.extended_offset_count));
      return;
    }
    ctx.used_p = true;
    auto n = ctx.integer(*ctx.words.p);
    if (!n) return;
    if (*n < 1 || *n > ctx.behaviour.extended_offset_count) {
      ctx.fail(Alarm::ExtendedOffsetNumber, ctx.words.p->loc,
               absl::StrCat("P", *n, " is out of range: ", name, " takes P1-P",
                            ctx.behaviour.extended_offset_count));
      return;
    }
    name = extendedName(ctx, *n);
  }
  ctx.next.work_name = name;
  ctx.next.work_value = ctx.core.tables.workOffset(name);
  ctx.next.modal.work_offset = name;
}

// G53: a rapid in machine coordinates; the frame is untouched.
void machineCoordinateMove(BlockContext& ctx, const GWord& g) {
  AxisValues target = ctx.next.position;
  for (int i = 0; i < ctx.axisCount(); ++i) {
    if (!ctx.words.axes[i]) continue;
    double v = ctx.axisValue(i, *ctx.words.axes[i]);
    if (ctx.words.axes[i]->mode == ir::DistanceMode::Incremental) {
      switch (ctx.behaviour.g53_in_g91) {
        case DialectBehaviour::G53InG91::Incremental: v += ctx.next.position[i]; break;
        case DialectBehaviour::G53InG91::Absolute: break;
        case DialectBehaviour::G53InG91::Ignored:
          ctx.core.diags.warning(std::string(ctx.table.alarm(Alarm::G53Incremental)), g.loc,
                                 "G53 in incremental mode (G91) is ignored");
          return;
      }
    }
    target[i] = v;
  }
  if (!ctx.samePosition(target, ctx.next.position))
    ctx.ops.push_back(ir::Rapid{target, ir::Space::Machine, ctx.settings.rapid_type});
  ctx.next.position = programmedAt(ctx, target);  // under a transform: the point that maps there
}

// G52: the local shift of the selected work system (or of all, where it is shared).
void localShift(BlockContext& ctx, const GWord& g) {
  if (ctx.behaviour.local_shift_in_extended_is_error && isExtended(ctx.next.work_name)) {
    ctx.fail(Alarm::LocalShiftInExtended, g.loc,
             absl::StrCat("G52 cannot be given while ", ctx.next.work_name.c_str(), " is selected"));
    return;
  }
  AxisValues& local = localOf(ctx.next, ctx.behaviour);
  for (int i = 0; i < ctx.axisCount(); ++i) {
    if (!ctx.words.axes[i]) continue;
    double v = ctx.axisValue(i, *ctx.words.axes[i]);
    local[i] = ctx.words.axes[i]->mode == ir::DistanceMode::Absolute ? v : local[i] + v;
  }
}

// G92: the current point takes the programmed coordinates (G91: current + value).
void setShift(BlockContext& ctx) {
  AxisValues current = ctx.baseWork();
  ir::Frame without = frameOf(ctx.next, ctx.behaviour);
  for (int i = 0; i < ctx.axisCount(); ++i) {
    if (!ctx.words.axes[i]) continue;
    double v = ctx.axisValue(i, *ctx.words.axes[i]);
    double w = ctx.words.axes[i]->mode == ir::DistanceMode::Absolute ? v : current[i] + v;
    double others = without.total()[i] - ctx.next.g92[i];
    ctx.next.g92[i] = ctx.next.position[i] - others - w;
  }
  ctx.lengthChangeTraversed();  // the new shift makes the current point what is programmed
}

// G92.1: the named axes' G92 and G52 shifts back to 0.
void resetShift(BlockContext& ctx, const GWord&) {
  AxisValues& local = localOf(ctx.next, ctx.behaviour);
  for (int i = 0; i < ctx.axisCount(); ++i) {
    if (!ctx.words.axes[i]) continue;
    if (ctx.axisValue(i, *ctx.words.axes[i]) != 0.0) {
      ctx.fail(Alarm::ValueOutOfRange, ctx.words.axes[i]->loc,
               absl::StrCat("G92.1 resets an axis with the value 0; ", std::string(ctx.words.axes[i]->address),
                            " is given another value"));
      return;
    }
    ctx.next.g92[i] = 0.0;
    local[i] = 0.0;
  }
}

// G10 L2 P0-P6 (external, G54-G59) and G10 L20 P (additional work systems). The external
// offset is state and changes at once; work offsets are tables, written at the commit.
void dataSetWork(BlockContext& ctx, const GWord& g, int l, bool add) {
  TableWrite w;
  w.add = add;
  if (l == 2) {
    int64_t p = ctx.next.last_g10_l2_p;
    if (ctx.words.p) {
      ctx.used_p = true;
      auto n = ctx.integer(*ctx.words.p);
      if (!n) return;
      p = *n;
    } else if (!ctx.behaviour.g10_l2_p_lenient) {
      ctx.fail(Alarm::DataSetFormat, g.loc, "G10 L2 needs P0-P6 (P0 external, P1-P6 G54-G59)");
      return;
    }
    if (p < 0 || p > 6) {
      if (!ctx.behaviour.g10_l2_p_lenient) {
        ctx.fail(Alarm::DataSetFormat, ctx.words.p->loc,
                 absl::StrCat("P", p, " is out of range: G10 L2 takes P0-P6"));
        return;
      }
      p = 1;  // Mazak §12-6: outside 0-6 is treated as 1
    }
    ctx.next.last_g10_l2_p = static_cast<int>(p);
    if (p == 0)
      w.target = TableWrite::Target::External;
    else
      w.work_name = gCodeName(530 + 10 * static_cast<int>(p));
  } else {
    std::string name;
    if (ctx.words.p) {
      ctx.used_p = true;
      auto n = ctx.integer(*ctx.words.p);
      if (!n) return;
      if (*n < 1 || *n > ctx.behaviour.extended_offset_count) {
        ctx.fail(Alarm::ExtendedOffsetNumber, ctx.words.p->loc,
                 absl::StrCat("P", *n, " is out of range: G10 L20 takes P1-P",
                              ctx.behaviour.extended_offset_count));
        return;
      }
      name = extendedName(ctx, *n);
    } else if (isExtended(ctx.next.work_name)) {
      name = ctx.next.work_name;
    } else {
      ctx.fail(Alarm::ExtendedOffsetRequired, g.loc,
               absl::StrCat("G10 L20 without P needs an additional work system to be selected (",
                            ctx.next.work_name.c_str(), " is)"));
      return;
    }
    w.work_name = name;
  }
  for (int i = 0; i < ctx.axisCount(); ++i) {
    if (!ctx.words.axes[i]) continue;
    w.values[i] = ctx.axisValue(i, *ctx.words.axes[i]);
    w.axes |= AxisMask(1u << i);
  }
  if (w.target == TableWrite::Target::External) {
    for (int i = 0; i < ctx.axisCount(); ++i)
      if (w.axes & (1u << i))
        ctx.next.external[i] = add ? ctx.next.external[i] + w.values[i] : w.values[i];
    return;
  }
  ctx.table_writes.push_back(std::move(w));
}

}  // namespace ncc::passes
