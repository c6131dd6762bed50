#include "ncc/vm/servo/pitch_compensation.h"

#include <cmath>

namespace ncc::vm {

double pitchValue(const PitchTable& table, double position) {
  const size_t n = table.values.size();
  if (n == 0) return 0.0;
  const double t = (position - table.start) / table.step;
  // `!(t > 0)` also catches NaN: hold the first value rather than index with it.
  if (!(t > 0.0)) return table.values[0];
  if (t >= static_cast<double>(n - 1)) return table.values[n - 1];
  const double i = std::floor(t);
  const size_t k = static_cast<size_t>(i);
  const double frac = t - i;
  if (frac == 0.0) return table.values[k];
  return table.values[k] + frac * (table.values[k + 1] - table.values[k]);
}

}  // namespace ncc::vm
