#pragma once
// Leadscrew pitch-error tables: the value at a machine position, linearly interpolated between
// equidistant support points and held at the end values outside them (LEC, notes §4.1).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ncc/machine/axes.h"
#include "ncc/machine/servo_config.h"
#include "ncc/vm/servo/axis_lanes.h"

namespace ncc::vm {

// The position in support-point steps from the table's start.
inline double pitchParameter(double position, double start, double step) {
  return (position - start) / step;
}

// The clamped parameter of a lookup: t held within [0, last], a NaN at 0 (the first value).
inline double pitchClamp(double t, double last) {
  t = t > 0.0 ? t : 0.0;  // (false for NaN)
  return t < last ? t : last;
}

// Value `at` plus the fraction `frac` of the step to `next`; at a support point (frac 0) the
// value itself, as it is: a select, not a branch, and not at + 0 (next - at), which would
// turn a -0 entry into +0 and two huge neighbours' inf difference into a NaN.
inline double pitchBetween(double at, double next, double frac) {
  const double between = at + frac * (next - at);
  return frac != 0.0 ? between : at;
}

// The value at parameter t of a table of values[0..last_index]; `last` is last_index as a
// double. The same arithmetic at every t, with no branch on where t lies (the last value
// again as the next one past the end).
inline double pitchInterpolate(const double* values, size_t last_index, double last, double t) {
  t = pitchClamp(t, last);
  // 0 <= t <= last here, so truncation is floor (and much cheaper without SSE4.1).
  const int64_t k = static_cast<int64_t>(t);
  const double frac = t - static_cast<double>(k);
  const double next = values[static_cast<size_t>(k) < last_index ? k + 1 : k];
  return pitchBetween(values[k], next, frac);
}

// 0 for an empty table. Exact at support points whose offset from `start` is a whole number
// of steps in floating point (e.g. start 0, step 10, position 30).
inline double pitchValue(const PitchTable& table, double position) {
  const size_t n = table.values.size();
  if (n == 0) return 0.0;
  return pitchInterpolate(table.values.data(), n - 1, static_cast<double>(n - 1),
                          pitchParameter(position, table.start, table.step));
}

// One kind of table (the control's LEC, or the simulated leadscrew's error) for all axes of a
// machine, for the servo model's cycle. Every lane has a table (0 where the axis has none,
// and on the padding lane), so that one loop with no branch looks up every lane with
// pitchValue()'s arithmetic: a fixed cost per cycle.
class PitchTables {
 public:
  using Values = AxisLanes;

  PitchTables() {
    step_.fill(1.0);  // no table: a harmless division
    offset_.fill(0);  // the table of 0 at the start of values_
  }
  // Each axis at most once; an empty table adds nothing. Copies the values (allocates: at
  // load, never in the cycle).
  void add(int axis, const PitchTable& table);

  // values()[i] = the value at position[i] for each axis i < n with a table; 0 for the others.
  void lookUp(int n, const Values& position) {
    if (!any_) return;
    const int lanes = laneCount(n);
    for (int i = 0; i < lanes; ++i) value_[i] = valueAt(i, position[i]);
  }
  const Values& values() const { return value_; }
  // The same for one axis (0 without a table), without keeping it.
  double valueAt(int axis, double position) const {
    return pitchInterpolate(values_.data() + offset_[axis], last_index_[axis], last_[axis],
                            pitchParameter(position, start_[axis], step_[axis]));
  }

 private:
  Values start_{};
  Values step_{};
  std::array<size_t, kAxisLanes> last_index_{};  // the last support point's index
  Values last_{};                                // the same as a double
  // All tables one after the other: first {0}, every lane's table until one is added.
  // Offsets rather than pointers, so that a copy needs nothing of the original.
  std::vector<double> values_{0.0};
  std::array<size_t, kAxisLanes> offset_{};
  bool any_ = false;
  Values value_{};  // each lane's value at the last lookUp
};

inline void PitchTables::add(int axis, const PitchTable& table) {
  if (table.values.empty()) return;
  start_[axis] = table.start;
  step_[axis] = table.step;
  last_index_[axis] = table.values.size() - 1;
  last_[axis] = static_cast<double>(last_index_[axis]);
  offset_[axis] = values_.size();
  values_.insert(values_.end(), table.values.begin(), table.values.end());
  any_ = true;
}

}  // namespace ncc::vm
