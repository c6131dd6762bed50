#pragma once
// Rounding a positive value up or down to the geometric grid 2^(m / steps) (steps cells per
// octave), as the planner does with a chain's shape and limits so that neighbouring lines
// share them. Computed, that is one log2 and one exp2 (about 150 instructions); a chain's
// values mostly fall in the cell of the value before, and GridCell answers those from the
// bounds it kept, with the same result bit for bit.
#include <algorithm>
#include <cmath>
#include <limits>

namespace ncc::vm::motion {

// The grid value at or below x (x itself if not positive and finite).
inline double roundDownToGrid(double x, double steps) {
  if (!(x > 0.0) || !std::isfinite(x)) return x;
  return std::min(x, std::exp2(std::floor(steps * std::log2(x)) / steps));
}

// The grid value at or above x (x itself if not positive and finite).
inline double roundUpToGrid(double x, double steps) {
  if (!(x > 0.0) || !std::isfinite(x)) return x;
  return std::max(x, std::exp2(std::ceil(steps * std::log2(x)) / steps));
}

// One quantity's last cell of the grid of kSteps cells per octave, rounding up (kUp) or down.
// A value well inside it (by a relative margin of 1e-9) has the same m as the value that set
// it: steps log2 x lies at least steps 1e-9 / ln 2 from the cell's integers, and log2's error
// and the products' are near 1e-15 of it. A value nearer a bound, or outside, is computed and
// sets the cell.
template <int kSteps, bool kUp>
class GridCell {
 public:
  // roundUpToGrid(x, kSteps) or roundDownToGrid(x, kSteps), bit for bit.
  double round(double x) {
    if (x > inner_low_ && x < inner_high_) return grid_value_;
    const double rounded = kUp ? roundUpToGrid(x, kSteps) : roundDownToGrid(x, kSteps);
    // Kept only where x lies strictly inside the cell (not on a grid value, not a NaN). The
    // other bound is a step of the grid away, within a few units in the last place: so only
    // a cell of normal doubles (a subnormal's step loses those digits, and past DBL_MAX the
    // bound is inf, where log2 itself rounds to 1024 and the computed grid value is x).
    if (kUp ? rounded > x : rounded < x) {
      const double low = kUp ? rounded * kOctaveShare : rounded;
      const double high = kUp ? rounded : rounded / kOctaveShare;
      if (low >= std::numeric_limits<double>::min() && high <= kLargestKept) {
        grid_value_ = rounded;
        inner_low_ = low * (1.0 + kMargin);
        inner_high_ = high * (1.0 - kMargin);
      }
    }
    return rounded;
  }

 private:
  static constexpr double kMargin = 1e-9;
  // Cells up to here only: far from DBL_MAX, where log2 rounds to 1024.
  static constexpr double kLargestKept = 1e300;
  // 2^(-1/kSteps), from one grid value to the next one down (only the margins use it).
  static inline const double kOctaveShare = std::exp2(-1.0 / kSteps);

  double grid_value_ = 0.0;  // the cell's: its upper bound rounding up, its lower rounding down
  // Empty until a value is computed: no x lies above +inf and below -inf.
  double inner_low_ = std::numeric_limits<double>::infinity();
  double inner_high_ = -std::numeric_limits<double>::infinity();
};

}  // namespace ncc::vm::motion
