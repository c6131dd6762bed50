// GridCell: the planner's grid rounding with the last cell kept gives the computed rounding
// bit for bit, for values inside the cell, on and next to its grid values, and for values
// that are not positive and finite.
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
