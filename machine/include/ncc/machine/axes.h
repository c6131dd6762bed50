#pragma once
// Fixed-capacity per-axis values. Axes are addressed by their index in MachineConfig::axes;
// a fixed array (not a map) keeps IR blocks, bytecode operands and VM state allocation-free.
#include <array>
#include <cstdint>

namespace ncc {

inline constexpr int kMaxAxes = 9;  // X Y Z A B C U V W
using AxisValues = std::array<double, kMaxAxes>;
using AxisMask = uint16_t;  // bit i set = axis i named

inline constexpr AxisValues zeroAxes() { return AxisValues{}; }

}  // namespace ncc
