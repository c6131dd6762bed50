// Dwell and machine functions: G04 (time in X or P, or spindle revolutions in G95), the
// spindle speed S, the tool number T and the M codes, with their order around the block's
// motion (spindle, tool and coolant start before it; stops, ends and other M codes after it).
// None of them moves an axis or changes the frame.
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include "absl/strings/str_cat.h"
#include "lowering_context.h"

namespace ncc::passes {

namespace {

// Siemens §3.3.1: the dwell block holds G04 and its X or P only. The first other command of
// the block, in written order (nullopt when there is none).
// `its_f_s`: F and S are the dwell's (DIN G4 F / G4 S).
std::optional<std::pair<SourceLocation, std::string>> otherThanDwell(const BlockContext& ctx,
                                                                     bool its_f_s = false) {
  const DecodedBlock& w = ctx.words;
  std::optional<std::pair<SourceLocation, std::string>> first;
  int first_order = 0;
  auto consider = [&](SourceLocation loc, int order, std::string what) {
    if (!first || order < first_order) {
      first = {loc, std::move(what)};
      first_order = order;
    }
  };
  for (const auto& g : w.modal)
    if (g) consider(g->loc, g->order, gCodeName(g->entry->code10));
  if (w.exact_stop) consider(w.exact_stop->loc, w.exact_stop->order, "G09");
  for (const auto* v : {&w.f, &w.s, &w.h, &w.d})
    if (*v && !(its_f_s && (v == &w.f || v == &w.s)))
      consider((*v)->loc, (*v)->order, std::string((*v)->address));
  for (const auto* list : {&w.t, &w.m})
    for (const WordValue& v : *list) consider(v.loc, v.order, std::string(v.address));
  return first;
}

}  // namespace

void dwell(BlockContext& ctx, const GWord& g) {
  if (ctx.behaviour.dwell_block_alone) {
    if (auto other = otherThanDwell(ctx)) {
      ctx.fail(Alarm::AddressWithoutMeaning, other->first,
               absl::StrCat(other->second, " cannot be given in a dwell (G04) block: the block "
                                           "holds nothing but G04 X or G04 P"));
      return;
    }
  }
  int x = ctx.axisNamed("X");
  std::optional<WordValue> xw = x >= 0 ? ctx.words.axes[x] : std::nullopt;
  for (int i = 0; i < ctx.axisCount(); ++i) {
    if (ctx.words.axes[i] && i != x) {
      ctx.fail(Alarm::AddressWithoutMeaning, ctx.words.axes[i]->loc,
               absl::StrCat("address ", std::string(ctx.words.axes[i]->address),
                            " has no meaning in a dwell (G04) block"));
      return;
    }
  }
  if (xw && ctx.words.p) {
    ctx.fail(Alarm::AddressWithoutMeaning, ctx.words.p->loc,
             "G04 takes the time in X or in P, not both");
    return;
  }
  double value = 0.0;
  if (ctx.words.p) {
    ctx.used_p = true;
    if (ctx.words.p->point && ctx.behaviour.dwell_p_point_is_error) {
      ctx.fail(Alarm::DecimalPointNotAllowed, ctx.words.p->loc,
               "G04 P is in milliseconds and takes no decimal point");
      return;
    }
    value = std::trunc(ctx.words.p->value) / 1000.0;  // ms, fraction ignored
  } else if (xw && ctx.behaviour.dwell_x_before_g04_is_coordinate && xw->order < g.order) {
    // Mazak §8-1: X before G04 is read as a coordinate, in least input increments of the
    // length unit, and those count 0.001 s: in inch `X5. G04` = X50000 = 50 s.
    const ValueRules& v = ctx.settings.values;
    double count = (v.standard && !xw->point)
                       ? xw->value
                       : xw->value / v.lengthIncrement(ctx.next.modal.units);
    value = std::round(count) * v.time_increment;
  } else if (xw) {
    value = ctx.settings.values.dwellX(xw->value, xw->point);
  } else {
    return;  // G04 alone: no dwell
  }
  if (value < 0) {
    ctx.fail(Alarm::ValueOutOfRange, g.loc, "a dwell time cannot be negative");
    return;
  }
  bool revs =
      ctx.settings.dwell_revolutions && ctx.next.modal.feed_mode == ir::FeedMode::PerRevolution;
  ctx.ops.push_back(ir::Dwell{value, revs});
}

void dwellFeedOrSpindle(BlockContext& ctx, const GWord& g) {
  // Fundamentals, "Dwell time (G4)": G4 in a block of its own, with F (seconds) or S
  // (revolutions of the spindle); the F and S in force stay.
  if (auto other = otherThanDwell(ctx, /*its_f_s=*/true)) {
    ctx.fail(Alarm::AddressWithoutMeaning, other->first,
             absl::StrCat("address ", other->second,
                          " cannot be given in a G4 block: it holds G4 F.. or G4 S.. alone"));
    return;
  }
  for (int i = 0; i < ctx.axisCount(); ++i)
    if (ctx.words.axes[i]) {
      ctx.fail(Alarm::AddressWithoutMeaning, ctx.words.axes[i]->loc,
               absl::StrCat("address ", std::string(ctx.words.axes[i]->address),
                            " has no meaning in a G4 block (G4 F seconds, G4 S revolutions)"));
      return;
    }
  const std::optional<WordValue>& f = ctx.words.f;
  const std::optional<WordValue>& s = ctx.words.s;
  if (f && s) {
    ctx.fail(Alarm::AddressWithoutMeaning, s->loc, "G4 takes the time in F or the revolutions in S, not both");
    return;
  }
  if (!f && !s) {
    ctx.fail(Alarm::AddressWithoutMeaning, g.loc, "G4 needs F (seconds) or S (spindle revolutions)");
    return;
  }
  const WordValue& w = f ? *f : *s;
  if (w.value < 0 || !std::isfinite(w.value)) {
    ctx.fail(Alarm::ValueOutOfRange, w.loc, "a dwell cannot be negative");
    return;
  }
  ctx.ops.push_back(ir::Dwell{w.value, /*revolutions=*/!f});
}

void applySpindleAndToolWords(BlockContext& ctx) {
  if (ctx.words.s && !dwellTakesFeedAndSpindle(ctx.words)) {
    auto n = ctx.integer(*ctx.words.s);
    if (n && *n < 0)
      ctx.fail(Alarm::ValueOutOfRange, ctx.words.s->loc, "a spindle speed cannot be negative");
    else if (n)
      ctx.next.modal.spindle_speed = static_cast<double>(*n);
  }
  for (size_t i = 0; i < ctx.words.t.size(); ++i) {
    auto n = ctx.integer(ctx.words.t[i]);
    if (n && *n < 0)
      ctx.fail(Alarm::ValueOutOfRange, ctx.words.t[i].loc, "a tool number cannot be negative");
    else if (n && i == 0)
      ctx.next.modal.tool = static_cast<int>(*n);
  }
}

void machineFunctions(BlockContext& ctx, LowerResult& result) {
  using K = ir::MachineFunction::Kind;
  std::span<const WordValue> ms = ctx.words.m;
  if (static_cast<int>(ms.size()) > ctx.behaviour.max_m_codes) {
    if (ctx.behaviour.m_overflow_keeps_last) {
      ctx.core.diags.warning(std::string(ctx.table.alarm(Alarm::TooManyMCodes)), ms.front().loc,
                             absl::StrCat("more than ", ctx.behaviour.max_m_codes,
                                          " M codes in a block: only the last ",
                                          ctx.behaviour.max_m_codes, " are effective"));
      ms = ms.last(static_cast<size_t>(ctx.behaviour.max_m_codes));
    } else {
      ctx.fail(
          Alarm::TooManyMCodes, ms[ctx.behaviour.max_m_codes].loc,
          absl::StrCat("at most ", ctx.behaviour.max_m_codes, " M codes may be given in a block"));
      return;
    }
  }
  std::vector<ir::Operation> before, after;
  if (ctx.words.s && !dwellTakesFeedAndSpindle(ctx.words))
    before.push_back(ir::MachineFunction{K::SpindleSpeed, 0, ctx.next.modal.spindle_speed});
  for (const WordValue& t : ctx.words.t)
    before.push_back(
        ir::MachineFunction{K::ToolSelect, static_cast<int64_t>(std::trunc(t.value)), 0.0});
  for (const WordValue& w : ms) {
    auto n = ctx.integer(w);
    if (!n) return;
    if (*n < 0) {
      ctx.fail(Alarm::ValueOutOfRange, w.loc, "an M code cannot be negative");
      return;
    }
    ir::MachineFunction f{K::OtherM, *n, 0.0};
    bool pre = false;
    switch (*n) {
      case 0: f.kind = K::ProgramStop; break;
      case 1: f.kind = K::OptionalStop; break;
      case 2:
        f.kind = K::ProgramEnd;
        result.program_end = true;
        break;
      case 30:
        f.kind = K::ProgramEndRewind;
        result.program_end = true;
        break;
      case 3:
        f.kind = K::SpindleCW;
        pre = true;
        break;
      case 4:
        f.kind = K::SpindleCCW;
        pre = true;
        break;
      case 5: f.kind = K::SpindleStop; break;
      case 6:
        f.kind = K::ToolChange;
        pre = true;
        break;
      case 8:
        f.kind = K::CoolantOn;
        pre = true;
        break;
      case 9: f.kind = K::CoolantOff; break;
      case 19:
        f.kind = K::SpindleOrient;
        pre = true;
        break;
      case 96:
      case 97:
        ctx.fail(Alarm::CodeNotSupported, w.loc,
                 absl::StrCat("M", *n, " (macro interrupt) is not supported yet"));
        return;
      case 98:
        ctx.fail(Alarm::CodeNotSupported, w.loc, "M98 (subprogram call) is not supported yet");
        return;
      case 99:
        ctx.fail(Alarm::CodeNotSupported, w.loc, "M99 (subprogram return) is not supported yet");
        return;
      default: break;
    }
    (pre ? before : after).push_back(f);
  }
  // Spindle, tool and coolant start before the block's motion; stops, ends and the other
  // (machine-builder) M codes after it.
  ctx.ops.insert(ctx.ops.begin(), before.begin(), before.end());
  ctx.ops.insert(ctx.ops.end(), after.begin(), after.end());
}

}  // namespace ncc::passes
