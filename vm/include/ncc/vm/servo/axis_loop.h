#pragma once
// A per-axis loop that GCC can vectorise at -O2: `body(i)` for each axis i < n, in order.
//
// At -O2 GCC (12 and later) vectorises only a loop whose trip count is known to be a multiple
// of the vector width (its "very cheap" cost model: no scalar remainder loop). A loop to a
// run-time axis count stays scalar, so the axes are run in pairs (a count GCC can see is even:
// two axes per SSE2 instruction) and an odd last axis on its own. Every axis still does the
// same operations, so the results are the same bits either way. Only for loops whose
// iterations are independent (no sum over the axes) and whose body is small enough to be
// inlined twice.
namespace ncc::vm {

template <class Body>
inline void forEachAxis(int n, Body&& body) {
  const int pairs_end = n & ~1;
  for (int i = 0; i < pairs_end; ++i) body(i);
  if (n & 1) body(pairs_end);
}

}  // namespace ncc::vm
