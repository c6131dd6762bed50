#pragma once
// A macro value: a number or vacant (<null> in the manuals). Vacant is not 0: `#1=#0` keeps
// #1 vacant, and EQ/NE tell vacant from 0; arithmetic and the other comparisons read vacant
// as 0 (docs/macro.md, Vacant).
#include <cstdint>

namespace ncc::eval {

struct Value {
  double number = 0.0;
  bool vacant = true;

  static Value of(double v) { return Value{v, false}; }
  static Value none() { return Value{}; }
  // The value in arithmetic: vacant counts as 0.
  double arithmetic() const { return vacant ? 0.0 : number; }
  friend bool operator==(const Value&, const Value&) = default;
};

}  // namespace ncc::eval
