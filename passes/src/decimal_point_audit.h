#pragma once
// Coordinate words written without a decimal point in a program that also writes them with
// one. In standard notation (`decimal_point = "standard"`) `G0 Z3` is 3 least input increments,
// 0.003 mm: what a controller does, and rarely what the CAM output that mixes `Z3` with `Z3.5`
// meant; its times and paths are then meaningless without a word. The audit counts such words
// over a file and reports one warning at the end, at the first of them, with the count.
#include <cstddef>
#include <optional>
#include <string>

#include "block_words.h"
#include "ncc/machine/machine_config.h"
#include "ncc/support/diagnostics.h"
#include "value_rules.h"

namespace ncc::passes {

inline constexpr const char* kMixedDecimalPointWarning = "NCC2034";

class DecimalPointAudit {
 public:
  // The coordinate words of one decoded block: axes (not G04's X, a time), I, J, K and R.
  // A zero reads the same either way and is not counted.
  // `angle_axis`: an axis whose word is an angle in degrees in this block (G16), else -1.
  void block(const DecodedBlock& words, const ValueRules& values, ir::Units units,
             const MachineConfig& machine, int angle_axis = -1);
  // At the end of the file: the warning, when the file has both kinds of coordinate words
  // and the decimal-point mode is standard.
  void finish(DiagnosticEngine& diags, const ValueRules& values) const;

 private:
  void word(const WordValue& w, const ValueRules& values, ir::Units units, bool rotary);

  bool any_point_ = false;
  size_t integers_ = 0;
  SourceLocation first_;
  std::string first_text_;  // "Z3 = 0.003 mm"
};

}  // namespace ncc::passes
