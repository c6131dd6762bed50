// G45-G48 tool position offset (Mazak §12-3): a one-shot code that lengthens (G45, G47) or
// shortens (G46, G48) the block's move by once (G45, G46) or twice (G47, G48) the D offset in
// force, on every axis named, the sign of each axis's move kept. A zero incremental move
// takes the sign of its zero (`G45 X0` +l, `G45 X-0` -l); a zero absolute move stays. On a
// quarter, half or three-quarter arc the centre offsets (and R) change the same way, so the
// radius follows the offset.
#include <cmath>

#include "lowering_context.h"

namespace ncc::passes {

namespace {

// G45 +1, G46 -1, G47 +2, G48 -2 (x the offset).
int multiple(int code10) {
  switch (code10) {
    case 450: return 1;
    case 460: return -1;
    case 470: return 2;
    default: return -2;
  }
}

double offsetAmount(const BlockContext& ctx, int d) {
  const OffsetTables& t = ctx.core.tables;
  double v = 0.0;
  if (auto it = t.radius.find(d); it != t.radius.end()) v += it->second;
  if (auto it = t.radius_wear.find(d); it != t.radius_wear.end()) v += it->second;
  return v;
}

}  // namespace

void positionOffsetMove(BlockContext& ctx, const GWord& g) {
  // D in the block, else the last D (§12-3: "D missing -> last D"); D0 offsets nothing.
  ctx.position_offset = multiple(g.entry->code10) * offsetAmount(ctx, ctx.next.d_selected);
  lowerMotion(ctx);
}

void applyPositionOffset(const BlockContext& ctx, const AxisValues& start, AxisValues& target) {
  if (ctx.position_offset == 0.0) return;
  for (int i = 0; i < ctx.axisCount(); ++i) {
    const std::optional<WordValue>& w = ctx.words.axes[i];
    if (!w) continue;
    double move = target[i] - start[i];
    if (std::fabs(move) > kSamePoint)
      target[i] += (move > 0 ? 1.0 : -1.0) * ctx.position_offset;
    else if (w->mode == ir::DistanceMode::Incremental)
      target[i] += (std::signbit(w->value) ? -1.0 : 1.0) * ctx.position_offset;
  }
}

double positionOffsetLength(const BlockContext& ctx, double length) {
  if (ctx.position_offset == 0.0 || length == 0.0) return length;
  return length + (length > 0 ? 1.0 : -1.0) * ctx.position_offset;
}

}  // namespace ncc::passes
