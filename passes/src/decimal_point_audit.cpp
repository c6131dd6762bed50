#include "decimal_point_audit.h"

#include <algorithm>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace ncc::passes {

// Most words have a point, or another integer word came first: only the first integer word is
// converted and written out, for the warning.
void DecimalPointAudit::word(const WordValue& w, const ValueRules& values, ir::Units units,
                             bool rotary) {
  if (w.point) {
    any_point_ = true;
    return;
  }
  if (w.value == 0.0) return;
  if (integers_++ != 0) return;
  first_ = w.loc;
  const double as_read = rotary ? values.rotary(w.value, w.point)
                                : values.linear(w.value, w.point, units);
  first_text_ = absl::StrCat(std::string(w.address), absl::StrFormat("%.0f", w.value), " = ",
                             absl::StrFormat("%g", as_read), " ", rotary ? "deg" : "mm");
}

void DecimalPointAudit::block(const DecodedBlock& words, const ValueRules& values,
                              ir::Units units, const MachineConfig& machine, int angle_axis) {
  if (!values.standard) return;  // calculator notation: `Z3` is 3 mm, as meant
  const int x = words.timeAxis(machine);
  const int count = std::min(machine.axisCount(), kMaxAxes);
  for (int i = 0; i < count; ++i) {
    const auto& w = words.axes[i];
    if (!w || i == x) continue;
    word(*w, values, units, machine.axes[i].kind == AxisKind::Rotary || i == angle_axis);
  }
  for (const auto* w : {&words.i, &words.j, &words.k, &words.r, &words.q})
    if (*w) word(**w, values, units, false);
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
