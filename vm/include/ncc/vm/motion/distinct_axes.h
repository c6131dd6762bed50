#pragma once
// The per-axis bounds a limit search checks (TangentialBudget, RampEnvelope), each held once.
// Two axes with bit-identical bounds pass and fail every check together and give the same
// largest value, so the second adds nothing but work: a chain moves all its axes with the
// same bounds on a machine whose axes share their limits (six axes cost six times one), and
// the plane axes of an arc often do.
#include <array>
#include <cstddef>
#include <cstring>
#include <type_traits>

namespace ncc::vm::motion {

// Appends `axis` unless one with the same bytes is held or the array is full.
template <class Axis, std::size_t N>
void addDistinctAxis(std::array<Axis, N>& axes, int& count, const Axis& axis) {
  // Compared as bytes (so +0 and -0, which may divide differently, stay apart): only structs
  // of doubles, which have no padding.
  static_assert(std::is_trivially_copyable_v<Axis> && sizeof(Axis) % sizeof(double) == 0);
  for (int k = 0; k < count; ++k)
    if (std::memcmp(&axes[static_cast<std::size_t>(k)], &axis, sizeof(Axis)) == 0) return;
  if (static_cast<std::size_t>(count) >= N) return;
  axes[static_cast<std::size_t>(count++)] = axis;
}

}  // namespace ncc::vm::motion
