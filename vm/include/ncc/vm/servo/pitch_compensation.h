#pragma once
// Leadscrew pitch-error tables: the value at a machine position, linearly interpolated between
// equidistant support points and held at the end values outside them (LEC, notes §4.1).
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "ncc/machine/axes.h"
#include "ncc/machine/servo_config.h"
#include "ncc/vm/servo/axis_lanes.h"

namespace ncc::vm {

// The position in support-point steps from the table's start: the lookup's division, apart so
// that the servo model can do it for all axes at once.
inline double pitchParameter(double position, double start, double step) {
  return (position - start) / step;
}

// The value at parameter t of a table of values[0..last_index]; `last` is last_index as a
// double.
inline double pitchInterpolate(const double* values, size_t last_index, double last, double t) {
  // `!(t > 0)` also catches NaN: hold the first value rather than index with it.
  if (!(t > 0.0)) return values[0];
  if (t >= last) return values[last_index];
  // 0 < t < last here, so truncation is floor (and much cheaper without SSE4.1).
  const int64_t k = static_cast<int64_t>(t);
  const double frac = t - static_cast<double>(k);
  if (frac == 0.0) return values[k];
  return values[k] + frac * (values[k + 1] - values[k]);
}

// 0 for an empty table. Exact at support points whose offset from `start` is a whole number
// of steps in floating point (e.g. start 0, step 10, position 30).
inline double pitchValue(const PitchTable& table, double position) {
  const size_t n = table.values.size();
  if (n == 0) return 0.0;
  return pitchInterpolate(table.values.data(), n - 1, static_cast<double>(n - 1),
                          pitchParameter(position, table.start, table.step));
}

// A table's values owned by the servo model: copied once at construction (the tick path
// allocates nothing), interpolated with the same arithmetic as pitchValue().
class PitchValues {
 public:
  PitchValues() = default;
  explicit PitchValues(const std::vector<double>& values)
      : values_(values),
        last_index_(values_.empty() ? 0 : values_.size() - 1),
        last_(static_cast<double>(last_index_)) {}

  bool empty() const { return values_.empty(); }
  // At parameter t = pitchParameter(position, start, step); the table must not be empty.
  double at(double t) const { return pitchInterpolate(values_.data(), last_index_, last_, t); }

 private:
  std::vector<double> values_;
  size_t last_index_ = 0;  // of the last support point
  double last_ = 0.0;      // the same as a double
};

// One kind of table (the control's LEC, or the simulated leadscrew's error) for all axes of a
// machine, for the servo model's cycle: the divisions of all axes side by side (a loop the
// compiler vectorises: over the axes' lanes, axis_lanes.h), then the interpolation where an
// axis has a table and has moved. It holds the values it looked up: an axis at rest (its
// parameter bit-identical to the last one) keeps its value without a second interpolation.
class PitchTables {
 public:
  using Values = AxisLanes;

  PitchTables() {
    step_.fill(1.0);  // no table: a harmless division
    last_parameter_.fill(std::numeric_limits<double>::quiet_NaN());  // equal to nothing
  }
  // Each axis at most once; an empty table adds nothing.
  void add(int axis, const PitchTable& table);

  // values()[i] = the value at position[i] for each axis i < n with a table; 0 for the others.
  void lookUp(int n, const Values& position) {
    if (axis_count_ == 0) return;
    const int lanes = laneCount(n);
    Values parameter;
    for (int i = 0; i < lanes; ++i)
      parameter[i] = pitchParameter(position[i], start_[i], step_[i]);
    for (int k = 0; k < axis_count_; ++k) {
      const int i = axes_[k];
      if (parameter[i] == last_parameter_[i]) continue;  // (NaN: never equal, looked up)
      last_parameter_[i] = parameter[i];
      value_[i] = values_[i].at(parameter[i]);
    }
  }
  const Values& values() const { return value_; }
  // The same for one axis (0 without a table), without keeping it.
  double valueAt(int axis, double position) const {
    return values_[axis].empty()
               ? 0.0
               : values_[axis].at(pitchParameter(position, start_[axis], step_[axis]));
  }

 private:
  Values start_{};
  Values step_{};
  std::array<PitchValues, kMaxAxes> values_;  // copies, allocated when added
  std::array<int, kMaxAxes> axes_{};          // the axes with a table, in order
  int axis_count_ = 0;
  Values last_parameter_{};  // of each axis' last lookUp (NaN before the first)
  Values value_{};           // the value there
};

inline void PitchTables::add(int axis, const PitchTable& table) {
  if (table.values.empty()) return;
  start_[axis] = table.start;
  step_[axis] = table.step;
  values_[axis] = PitchValues(table.values);
  axes_[axis_count_++] = axis;
}

}  // namespace ncc::vm
