// Tool offsets: tool length compensation (H with G43/G44/G49, on the length axis chosen by
// tool_length_mode), the radius offset number D, and the G10 L10-L13 writes to the length and
// radius (wear) registers. A length change can move the length axis in a block of its own;
// that is recorded here (BlockContext::length_delta*) and carried out by the block's motion.
#include <cmath>

#include "absl/strings/str_cat.h"
#include "lowering_context.h"

namespace ncc::passes {

namespace {

// The axis carrying the length offset: Z (mode A), or the axis normal to the plane (mode B).
int lengthAxis(const BlockContext& ctx) {
  if (ctx.settings.tool_length_mode == ToolLengthMode::B) {
    switch (ctx.next.modal.plane) {
      case ir::Plane::XY: return ctx.axisNamed("Z");
      case ir::Plane::ZX: return ctx.axisNamed("Y");
      case ir::Plane::YZ: return ctx.axisNamed("X");
    }
  }
  return ctx.axisNamed("Z");
}

// Siemens §3.5.2: G43/G44/G49 (and a new H in G43/G44) only in G00/G01 mode.
bool lengthChangeAllowed(BlockContext& ctx, const std::optional<GWord>& g, int sign) {
  bool arc = ctx.next.motion == GAction::ArcCW || ctx.next.motion == GAction::ArcCCW;
  if (!ctx.behaviour.length_comp_in_arc_is_error || !arc) return true;
  if (!g && (!ctx.words.h || sign == 0)) return true;
  std::string what = g ? gCodeName(g->entry->code10)
                       : absl::StrCat("H", static_cast<int64_t>(std::trunc(ctx.words.h->value)));
  ctx.fail(Alarm::LengthCompInArc, g ? g->loc : ctx.words.h->loc,
           absl::StrCat(what, " is not allowed while ",
                        ctx.next.motion == GAction::ArcCW ? "G02" : "G03",
                        " is in force: tool length compensation changes only in G00/G01 mode"));
  return false;
}

// DIN D n: edge n's length on the axis normal to the plane (DialectBehaviour::d_selects_length).
int edgeLengthAxis(const BlockContext& ctx) {
  switch (ctx.next.modal.plane) {
    case ir::Plane::XY: return ctx.axisNamed("Z");
    case ir::Plane::ZX: return ctx.axisNamed("Y");
    case ir::Plane::YZ: return ctx.axisNamed("X");
  }
  return -1;
}

// The length in force becomes `length` on `axis` (-1: none); the change it makes on the
// length axis is traversed now or when the axis is next programmed (length_change_moves).
void setLength(BlockContext& ctx, int axis, double length) {
  double old = ctx.core.cs().tool_length_axis >= 0 ? ctx.core.cs().tool_length : 0.0;
  int changed_axis = axis >= 0 ? axis : ctx.core.cs().tool_length_axis;
  if (changed_axis >= 0 && length != old) {
    if (ctx.settings.length_change_moves) {
      ctx.length_delta_axis = changed_axis;
      ctx.length_delta = length - old;
    } else {
      // Traversed when the axis is next programmed (Siemens MD20382 = FALSE).
      ControllerState& n = ctx.next;
      if (n.length_pending_axis != changed_axis) n.length_pending = 0.0;
      n.length_pending_axis = changed_axis;
      n.length_pending += length - old;
    }
  }
  ctx.next.tool_length_axis = axis;
  ctx.next.tool_length = length;
}

void changeEdgeLength(BlockContext& ctx) {
  if (!ctx.words.d) return;
  auto n = ctx.integer(*ctx.words.d);
  if (!n || *n < 0 || *n > ctx.settings.offset_count) return;  // applyRadiusOffsetNumber reports
  const int sign = *n != 0 ? 1 : 0;
  int axis = -1;
  if (sign != 0) {
    axis = edgeLengthAxis(ctx);
    if (axis < 0) {
      ctx.fail(Alarm::AxisMissing, ctx.words.d->loc,
               "the tool length needs the axis normal to the plane, which the machine does not have");
      return;
    }
  }
  ctx.next.h_selected = static_cast<int>(*n);
  setLength(ctx, axis, sign != 0 ? ctx.core.tables.toolLength(static_cast<int>(*n)) : 0.0);
  ctx.next.modal.length_offset_sign = sign;
  ctx.next.modal.length_offset_h = sign != 0 ? static_cast<int>(*n) : 0;
}

// H with G43/G44/G49: the new length, and the change it makes on the length axis.
void changeLengthOffset(BlockContext& ctx) {
  if (ctx.behaviour.d_selects_length) return changeEdgeLength(ctx);
  const auto& g = ctx.words.group(GGroup::LengthComp);
  if (ctx.words.h) {
    auto n = ctx.integer(*ctx.words.h);
    if (!n) return;
    if (*n < 0 || *n > ctx.settings.offset_count) {
      ctx.fail(Alarm::OffsetNumberOutOfRange, ctx.words.h->loc,
               absl::StrCat("H", *n, " is out of range: offset numbers are 1-",
                            ctx.settings.offset_count, " (offset_count)"));
      return;
    }
    ctx.next.h_selected = static_cast<int>(*n);
  }
  if (!g && !ctx.words.h) return;
  int sign = ctx.next.modal.length_offset_sign;
  if (g) {
    GAction a = g->entry->action;
    sign = a == GAction::LengthPlus ? 1 : a == GAction::LengthMinus ? -1 : 0;
  }
  if (!lengthChangeAllowed(ctx, g, sign)) return;
  if (sign != 0 && ctx.settings.tool_length_mode == ToolLengthMode::C) {
    ctx.fail(Alarm::CodeNotSupported, g ? g->loc : ctx.words.h->loc,
             "tool length mode C (offset on the axis programmed with H) is not supported yet");
    return;
  }
  int axis = -1;
  double length = 0.0;
  if (sign != 0) {
    axis = lengthAxis(ctx);
    if (axis < 0) {
      ctx.fail(Alarm::AxisMissing, g ? g->loc : ctx.words.h->loc,
               "tool length compensation needs the length axis, which the machine does not have");
      return;
    }
    length = sign * ctx.core.tables.toolLength(ctx.next.h_selected);
  }
  setLength(ctx, axis, length);
  ctx.next.modal.length_offset_sign = sign;
  ctx.next.modal.length_offset_h = sign != 0 ? ctx.next.h_selected : 0;
}

}  // namespace

void applyLengthOffset(BlockContext& ctx) {
  changeLengthOffset(ctx);
  if (ctx.failed || ctx.next.length_pending_axis < 0) return;
  ctx.length_delta_axis = ctx.next.length_pending_axis;
  ctx.length_delta = ctx.next.length_pending;
  ctx.length_delta_deferred = true;
}

void applyRadiusOffsetNumber(BlockContext& ctx) {
  if (ctx.words.d) {
    auto n = ctx.integer(*ctx.words.d);
    if (n && (*n < 0 || *n > ctx.settings.offset_count))
      ctx.fail(Alarm::OffsetNumberOutOfRange, ctx.words.d->loc,
               absl::StrCat("D", *n, " is out of range: offset numbers are 1-",
                            ctx.settings.offset_count, " (offset_count)"));
    else if (n)
      ctx.next.d_selected = static_cast<int>(*n);
  }
}

void dataSetRegister(BlockContext& ctx, const GWord& g, int l, bool add) {
  for (int i = 0; i < ctx.axisCount(); ++i) {
    if (ctx.words.axes[i]) {
      ctx.fail(Alarm::AddressWithoutMeaning, ctx.words.axes[i]->loc,
               absl::StrCat("address ", std::string(ctx.words.axes[i]->address), " has no meaning in G10 L", l));
      return;
    }
  }
  if (!ctx.words.p || !ctx.words.r) {
    ctx.fail(Alarm::DataSetFormat, g.loc,
             absl::StrCat("G10 L", l, " needs P (offset number) and R (value)"));
    return;
  }
  ctx.used_p = ctx.used_r = true;
  auto n = ctx.integer(*ctx.words.p);
  if (!n) return;
  if (*n < 1 || *n > ctx.settings.offset_count) {
    ctx.fail(Alarm::OffsetNumberOutOfRange, ctx.words.p->loc,
             absl::StrCat("P", *n, " is out of range: offset numbers are 1-",
                          ctx.settings.offset_count, " (offset_count)"));
    return;
  }
  TableWrite w;
  w.target = l == 10   ? TableWrite::Target::Length
             : l == 11 ? TableWrite::Target::LengthWear
             : l == 12 ? TableWrite::Target::Radius
                       : TableWrite::Target::RadiusWear;
  w.number = static_cast<int>(*n);
  w.values[0] =
      ctx.settings.values.offset(ctx.words.r->value, ctx.words.r->point, ctx.next.modal.units);
  w.add = add;
  ctx.table_writes.push_back(std::move(w));
}

}  // namespace ncc::passes
