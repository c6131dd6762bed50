#include "ncc/bytecode/program.h"

#include <algorithm>

namespace ncc::bytecode {

const LineEntry* Program::lineFor(uint32_t offset) const {
  // First entry after `offset`, then step back: binary search, no allocation.
  auto after = std::upper_bound(lines.begin(), lines.end(), offset,
                                [](uint32_t o, const LineEntry& e) { return o < e.offset; });
  return after == lines.begin() ? nullptr : &*(after - 1);
}

}  // namespace ncc::bytecode
