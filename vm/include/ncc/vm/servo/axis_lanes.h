#pragma once
// The servo model's per-axis state, padded to an even number of lanes so that its stages
// vectorise at -O2 (two axes per SSE2 instruction).
//
// At -O2 GCC (12 and later) vectorises only a loop whose trip count is known to be a multiple
// of the vector width (its "very cheap" cost model: no scalar remainder loop). A loop to the
// axis count stays scalar; a loop to laneCount() (the axis count rounded up to even) does not.
// A lane beyond the axis count has all parameters and inputs 0, so every stage leaves it at
// +0.0; each axis does the same operations either way, so the results are the same bits.
#include <array>
#include <cstring>

#include "ncc/machine/axes.h"

namespace ncc::vm {

inline constexpr int kAxisLanes = kMaxAxes + kMaxAxes % 2;
using AxisLanes = std::array<double, kAxisLanes>;

// The lanes the stages run on for `axis_count` axes: even, for GCC to see it.
inline int laneCount(int axis_count) { return (axis_count + 1) & ~1; }

// The axes' values of `from`: a copy of a fixed size (inlined as a few moves, where
// std::copy_n becomes a loop), cheaper than one to the axis count.
inline void copyAxes(const AxisLanes& from, AxisValues& to) {
  static_assert(sizeof to <= sizeof from);
  std::memcpy(to.data(), from.data(), sizeof to);
}

}  // namespace ncc::vm
