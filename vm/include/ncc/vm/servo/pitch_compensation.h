#pragma once
// Leadscrew pitch-error tables: the value at a machine position, linearly interpolated between
// equidistant support points and held at the end values outside them (LEC, notes §4.1).
//
// The support points are x_k = start + k step, computed so by every lookup (ncc::pitchSupport,
// servo_config.h): the grid is the same floating-point numbers everywhere, a position at one
// of them gives its entry exactly, and a position's interval [x_k, x_k+1) is a function of
// the position alone. Within it the value is v_k + (p - x_k) s_k, with the interval's slope
// s_k = (v_k+1 - v_k) / step (ncc::pitchSlope): the servo's cycle keeps each axis's interval
// and, while the axis stays in it, looks up with a subtraction, a product and a sum (no
// division).
#include <array>
#include <cstddef>
#include <vector>

#include "ncc/machine/axes.h"
#include "ncc/machine/servo_config.h"
#include "ncc/vm/servo/axis_lanes.h"

namespace ncc::vm {

// The position held within [first, last], the first and last support points; a NaN goes to
// the first.
inline double pitchClamp(double position, double first, double last) {
  position = position > first ? position : first;  // (false for NaN)
  return position < last ? position : last;
}

// The interval of a clamped position p: the last support point at or before it. The quotient
// finds it up to rounding; the comparisons with the grid itself decide.
inline std::size_t pitchIndex(double p, double start, double step, std::size_t last_index) {
  double t = (p - start) / step;
  t = t > 0.0 ? t : 0.0;
  const double last = static_cast<double>(last_index);
  t = t < last ? t : last;
  std::size_t k = static_cast<std::size_t>(t);
  while (k > 0 && p < pitchSupport(start, step, k)) --k;
  while (k < last_index && p >= pitchSupport(start, step, k + 1)) ++k;
  return k;
}

// The value `distance` (>= 0) past a support point whose entry is `at`. At the point itself,
// the entry as it is: a select, not at + 0 s, which would turn a -0 entry into +0 and an
// infinite slope (two huge neighbours) into a NaN.
inline double pitchAlong(double at, double slope, double distance) {
  const double along = at + distance * slope;
  return distance > 0.0 ? along : at;
}

// 0 for an empty table.
inline double pitchValue(const PitchTable& table, double position) {
  const std::size_t n = table.values.size();
  if (n == 0) return 0.0;
  const std::size_t last_index = n - 1;
  const double p = pitchClamp(position, table.start,
                              pitchSupport(table.start, table.step, last_index));
  const std::size_t k = pitchIndex(p, table.start, table.step, last_index);
  return pitchAlong(table.values[k], pitchSlope(table.values.data(), k, last_index, table.step),
                    p - pitchSupport(table.start, table.step, k));
}

// One kind of table (the control's LEC, or the simulated leadscrew's error) for all axes of a
// machine, for the servo model's cycle: pitchValue() for every lane, bit for bit. Each lane
// keeps the interval of its last lookup; a lane without a table has the table {0} (one
// interval, never left). The cycle clamps and tests every lane, finds a new interval only for
// the lanes that left theirs (a division and a comparison or two each: at most the cost of
// the plain lookup), then interpolates every lane, in loops that vectorise.
class PitchTables {
 public:
  using Values = AxisLanes;

  PitchTables();
  // Each axis at most once; an empty table adds nothing. Copies the values (allocates: at
  // load, never in the cycle).
  void add(int axis, const PitchTable& table);

  // values()[i] = the value at position[i] for each axis i < n with a table; 0 for the others.
  void lookUp(int n, const Values& position) {
    if (!any_) return;
    const int lanes = laneCount(n);
    for (int i = 0; i < lanes; ++i) {
      const double p = pitchClamp(position[i], first_[i], last_[i]);
      clamped_[i] = p;
      left_[i] = int{p < from_[i]} | int{p >= to_[i]} ? 1.0 : 0.0;
    }
    for (int i = 0; i < lanes; ++i)
      if (left_[i] != 0.0) enter(i, clamped_[i]);
    for (int i = 0; i < lanes; ++i)
      value_[i] = pitchAlong(at_[i], slope_[i], clamped_[i] - from_[i]);
  }
  const Values& values() const { return value_; }
  // The same for one axis (0 without a table), without keeping it.
  double valueAt(int axis, double position) const;

 private:
  struct Interval {
    double from, to, at, slope;
  };
  // Lane `axis`'s interval holding the clamped position p.
  Interval intervalAt(int axis, double p) const;
  void enter(int axis, double p);

  // Each lane's table.
  Values start_{};
  Values step_{};
  Values first_{}, last_{};                          // its first and last support points
  std::array<std::size_t, kAxisLanes> last_index_{};  // the last support point's index
  // All tables one after the other: first {0}, every lane's table until one is added.
  // Offsets rather than pointers, so that a copy needs nothing of the original.
  std::vector<double> values_{0.0};
  std::array<std::size_t, kAxisLanes> offset_{};
  bool any_ = false;
  // Each lane's interval [from, to) at its last lookup, its entry and slope; the clamped
  // position and the value there.
  Values from_{}, to_{}, at_{}, slope_{};
  Values clamped_{};
  Values left_{};  // 1 where the clamped position left the interval
  Values value_{};
};

}  // namespace ncc::vm
