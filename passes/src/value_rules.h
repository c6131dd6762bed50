#pragma once
// Turns a number as written into a normalised value (mm, degrees, seconds, mm/min): the
// decimal-point rule (calculator vs standard with the increment system), Mazak's x10 input
// unit, and inch input. One place for every address's unit rule (docs/semantics.md, Values).
#include "ncc/ir/ir.h"
#include "ncc/machine/params.h"

namespace ncc::passes {

struct ValueRules {
  bool standard = true;          // decimal_point = "standard": no point = least increments
  double mm_increment = 0.001;   // IS-B 0.001 mm, IS-C 0.0001 mm
  double inch_increment = 0.0001;
  double deg_increment = 0.001;
  double time_increment = 0.001;  // G04 X without a point
  double x10 = 1.0;              // Mazak input_unit_x10: coordinates x10 (not offsets)
  int digits = 8;                // the dialect's format_digits

  // The largest number of least increments (or integer) a word can hold: 10^digits - 1.
  double maxCount() const;
  // The least input increment of a length (mm or inch) and of a feed in its input unit.
  double lengthIncrement(ir::Units units) const;
  // F in its input unit (mm or inch per minute/revolution, 1/min): notation applied, inch not
  // converted. `feed` is this value converted to mm.
  double feedInput(double v, bool point, ir::Units units, ir::FeedMode mode) const;

  // Reads decimal_point, increment_system and input_unit_x10 with the dialect's default
  // decimal-point mode.
  static ValueRules fromParams(const ParameterSet& params, std::string_view decimal_default);

  // Axis coordinates, I/J/K, R, G52/G92/G10 L2 values: mm for a linear axis.
  double linear(double v, bool point, ir::Units units) const;
  // Rotary axis coordinates: degrees, never converted by G20.
  double rotary(double v, bool point) const;
  // Offset register values (G10 L10-L13 R): like `linear` but without the x10 input unit.
  double offset(double v, bool point, ir::Units units) const;
  // G04 X: seconds (or revolutions).
  double dwellX(double v, bool point) const;
  // F: mm/min (G94), mm/rev (G95) or 1/min (G93). Standard notation without a point:
  // 1 mm/min or 0.01 in/min per minute, 0.01 mm/rev or 0.0001 in/rev per revolution.
  double feed(double v, bool point, ir::Units units, ir::FeedMode mode) const;
};

}  // namespace ncc::passes
