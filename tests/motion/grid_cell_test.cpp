// GridCell: the planner's grid rounding with the last cell kept gives the computed rounding
// bit for bit, for values inside the cell, on and next to its grid values, and for values
// that are not positive and finite.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "gtest/gtest.h"
#include "ncc/vm/motion/grid_cell.h"

namespace ncc::vm::motion {
namespace {

// Values that walk slowly (most stay in the cell of the one before), jump, and sit on and
// within a few units in the last place of grid values, where log2's rounding decides.
template <int kSteps>
std::vector<double> values() {
  std::vector<double> v;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> step(-0.004, 0.004), jump(-30.0, 30.0);
  double x = 1.3;
  for (int i = 0; i < 20000; ++i) {
    x *= 1.0 + step(random);
    if (i % 97 == 0) x = std::exp2(jump(random));
    v.push_back(x);
  }
  for (int m = -200; m <= 200; ++m) {
    const double g = std::exp2(static_cast<double>(m) / kSteps);
    double below = g, above = g;
    for (int k = 0; k < 4; ++k) {
      below = std::nextafter(below, 0.0);
      above = std::nextafter(above, 1e300);
      v.insert(v.end(), {g * (1.0 - 1e-9), below, g, above, g * (1.0 + 1e-9), g * 1.001});
    }
  }
  const double inf = std::numeric_limits<double>::infinity();
  v.insert(v.end(), {0.0, -0.0, -1.0, inf, -inf, std::nan(""), 1.3, 5e-324, 1e308});
  // The ends of the range, each walk after a value that may set a cell next to it: the top
  // octave (where log2 rounds to 1024 just below DBL_MAX) and the subnormals (whose grid
  // steps have few digits).
  const double top = std::numeric_limits<double>::max();
  for (double x = 1.7e308; x < top; x = std::nextafter(x * (1.0 + 1e-4), inf)) v.push_back(x);
  for (double x = top, k = 0; k < 2000; ++k, x = std::nextafter(x, 0.0)) v.push_back(x);
  v.push_back(1.75e308);
  v.push_back(top);
  const double tiny = std::numeric_limits<double>::denorm_min();
  for (int k = 1; k < 3000; k += 7) v.push_back(k * tiny);
  for (int k = 400; k < 600; ++k) v.insert(v.end(), {k * tiny, (k + 80) * tiny});
  for (double x = std::numeric_limits<double>::min() * 4; x > tiny;
       x = std::min(x * 0.93, std::nextafter(x, 0.0)))  // (a subnormal's product may not fall)
    v.push_back(x);
  return v;
}

template <int kSteps, bool kUp>
void expectComputedRounding() {
  GridCell<kSteps, kUp> cell;
  int same_cell = 0;
  double last = 0.0;
  for (double x : values<kSteps>()) {
    const double expected = kUp ? roundUpToGrid(x, kSteps) : roundDownToGrid(x, kSteps);
    const double got = cell.round(x);
    if (std::isnan(expected)) {
      EXPECT_TRUE(std::isnan(got));
    } else {
      ASSERT_EQ(std::bit_cast<uint64_t>(got), std::bit_cast<uint64_t>(expected))
          << "x = " << x << " steps " << kSteps << (kUp ? " up" : " down");
    }
    same_cell += got == last;
    last = got;
  }
  // The walk stays in one cell for most values: the kept cell answers them.
  EXPECT_GT(same_cell, 5000);
}

TEST(GridCell, RoundsAsComputedOnEveryGrid) {
  expectComputedRounding<16, false>();
  expectComputedRounding<64, true>();
  expectComputedRounding<4, true>();
  expectComputedRounding<1, true>();
  expectComputedRounding<64, false>();
  expectComputedRounding<4, false>();
  expectComputedRounding<1, false>();
}

// Found in review: a rounding-down cell set in the top octave returned 2^(1024 - 1/16) for
// DBL_MAX, whose computed rounding is DBL_MAX itself (log2 rounds to 1024 there).
TEST(GridCell, TheTopOctaveIsComputed) {
  GridCell<16, false> down;
  const double top = std::numeric_limits<double>::max();
  EXPECT_EQ(down.round(1.75e308), roundDownToGrid(1.75e308, 16));
  EXPECT_EQ(down.round(top), roundDownToGrid(top, 16));
  EXPECT_EQ(roundDownToGrid(top, 16), top);
}

TEST(GridCell, RoundsToTheGrid) {
  GridCell<4, true> up;
  GridCell<16, false> down;
  EXPECT_EQ(up.round(1.0), 1.0);  // on the grid
  EXPECT_DOUBLE_EQ(up.round(1.1), std::exp2(0.25));
  EXPECT_DOUBLE_EQ(up.round(1.15), std::exp2(0.25));  // the kept cell
  EXPECT_EQ(up.round(1.5), std::exp2(0.75));
  EXPECT_EQ(down.round(3.0), std::exp2(25.0 / 16.0));
  EXPECT_EQ(down.round(2.99), std::exp2(25.0 / 16.0));
  EXPECT_EQ(down.round(-2.0), -2.0);  // not positive: as it is
}

}  // namespace
}  // namespace ncc::vm::motion
