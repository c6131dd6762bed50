#include "ncc/vm/servo/pitch_compensation.h"

#include <limits>

namespace ncc::vm {

PitchTables::PitchTables() {
  step_.fill(1.0);
  offset_.fill(0);  // the table of 0 at the start of values_
  for (int i = 0; i < kAxisLanes; ++i) enter(i, 0.0);
}

void PitchTables::add(int axis, const PitchTable& table) {
  if (table.values.empty()) return;
  start_[axis] = table.start;
  step_[axis] = table.step;
  last_index_[axis] = table.values.size() - 1;
  first_[axis] = table.start;
  last_[axis] = pitchSupport(table.start, table.step, last_index_[axis]);
  offset_[axis] = values_.size();
  values_.insert(values_.end(), table.values.begin(), table.values.end());
  any_ = true;
  enter(axis, first_[axis]);
}

PitchTables::Interval PitchTables::intervalAt(int axis, double p) const {
  const double start = start_[axis], step = step_[axis];
  const std::size_t last_index = last_index_[axis];
  const double* values = values_.data() + offset_[axis];
  const std::size_t k = pitchIndex(p, start, step, last_index);
  return Interval{pitchSupport(start, step, k),
                  k < last_index ? pitchSupport(start, step, k + 1)
                                 : std::numeric_limits<double>::infinity(),
                  values[k], pitchSlope(values, k, last_index, step)};
}

void PitchTables::enter(int axis, double p) {
  const Interval in = intervalAt(axis, p);
  from_[axis] = in.from;
  to_[axis] = in.to;
  at_[axis] = in.at;
  slope_[axis] = in.slope;
}

double PitchTables::valueAt(int axis, double position) const {
  const double p = pitchClamp(position, first_[axis], last_[axis]);
  const Interval in = intervalAt(axis, p);
  return pitchAlong(in.at, in.slope, p - in.from);
}

}  // namespace ncc::vm
