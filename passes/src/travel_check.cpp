// Travel check: motion targets in machine coordinates against the axes' travel limits.
#include "ncc/passes/travel_check.h"

#include <algorithm>
#include <variant>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace ncc::passes {

namespace {

// The control's alarm for a target beyond the travel limits, per dialect.
struct TravelAlarmEntry {
  Dialect dialect;
  TravelAlarms alarms;
};
constexpr TravelAlarmEntry kTravelAlarms[] = {
    // FANUC: OT0500 + overtravel (soft limit 1), OT0501 - overtravel (soft limit 1).
    {Dialect::FanucM, {"OT0500", "OT0501"}},
    {Dialect::FanucT, {"OT0500", "OT0501"}},
    // Mazak: the EIA/ISO notes give no alarm number for the stored stroke limit.
    {Dialect::MazakM, {"NCC2090", "NCC2090"}},
    // Sinumerik: 10720 "software limit switch + / -" (one number for both directions).
    {Dialect::SiemensIsoM, {"10720", "10720"}},
    {Dialect::SiemensDin, {"10720", "10720"}},
};

AxisValues targetOf(const ir::Operation& op, bool& moves) {
  moves = true;
  if (const auto* r = std::get_if<ir::Rapid>(&op)) return r->to;
  if (const auto* l = std::get_if<ir::Linear>(&op)) return l->to;
  if (const auto* a = std::get_if<ir::Arc>(&op)) return a->to;
  moves = false;
  return {};
}

}  // namespace

TravelAlarms travelAlarms(Dialect dialect) {
  for (const TravelAlarmEntry& e : kTravelAlarms)
    if (e.dialect == dialect) return e.alarms;
  return {"NCC2090", "NCC2090"};
}

void TravelCheckPass::accept(ir::Block block) {
  for (const ir::Operation& op : block.ops) {
    bool moves = false;
    AxisValues to = targetOf(op, moves);
    if (moves) check(to, block.loc);
  }
  next_.accept(std::move(block));
}

void TravelCheckPass::check(const AxisValues& to, SourceLocation where) {
  int n = std::min(machine_.axisCount(), kMaxAxes);
  for (int i = 0; i < n; ++i) {
    const AxisConfig& axis = machine_.axes[i];
    bool above = to[i] > axis.max_travel, below = to[i] < axis.min_travel;
    if (!above && !below) continue;
    const char* unit = axis.kind == AxisKind::Rotary ? "deg" : "mm";
    diags_.error(std::string(above ? alarms_.positive : alarms_.negative), where,
                 absl::StrFormat("%s overtravel: the target %s%.3f %s (machine coordinates) is "
                                 "beyond the travel limit %.3f %s",
                                 above ? "+" : "-", axis.name, to[i], unit,
                                 above ? axis.max_travel : axis.min_travel, unit));
    return;
  }
}

}  // namespace ncc::passes
