#include "decimal_point_audit.h"

#include <algorithm>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace ncc::passes {

void DecimalPointAudit::word(const WordValue& w, double as_read, const char* unit) {
  if (w.point) {
    any_point_ = true;
    return;
  }
  if (w.value == 0.0) return;
  if (integers_++ == 0) {
    first_ = w.loc;
    first_text_ = absl::StrCat(std::string(w.address), absl::StrFormat("%.0f", w.value), " = ",
                               absl::StrFormat("%g", as_read), " ", unit);
  }
}

void DecimalPointAudit::block(const DecodedBlock& words, const ValueRules& values,
                              ir::Units units, const MachineConfig& machine, int angle_axis) {
  if (!values.standard) return;  // calculator notation: `Z3` is 3 mm, as meant
  bool dwell = words.one_shot && words.one_shot->entry->action == GAction::Dwell;
  int x = machine.axisIndex("X");
  int count = std::min(machine.axisCount(), kMaxAxes);
  for (int i = 0; i < count; ++i) {
    const auto& w = words.axes[i];
    if (!w || (dwell && i == x)) continue;
    if (machine.axes[i].kind == AxisKind::Rotary || i == angle_axis)
      word(*w, values.rotary(w->value, w->point), "deg");
    else
      word(*w, values.linear(w->value, w->point, units), "mm");
  }
  for (const auto* w : {&words.i, &words.j, &words.k, &words.r, &words.q})
    if (*w) word(**w, values.linear((*w)->value, (*w)->point, units), "mm");
}

void DecimalPointAudit::finish(DiagnosticEngine& diags, const ValueRules& values) const {
  if (!values.standard || !any_point_ || integers_ == 0) return;
  diags.warning(kMixedDecimalPointWarning, first_,
                absl::StrCat(integers_, integers_ == 1 ? " coordinate word" : " coordinate words",
                             " without a decimal point ", integers_ == 1 ? "is" : "are",
                             " read as least input increments (the first: ", first_text_,
                             ") in a program that also writes decimal points; write the point "
                             "(`Z3.`) for whole units, or set decimal_point = \"calculator\""));
}

}  // namespace ncc::passes
