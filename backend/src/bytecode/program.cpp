#include "ncc/bytecode/program.h"

#include <algorithm>

namespace ncc::bytecode {

const LineEntry* Program::lineFor(uint32_t offset) const {
  // First entry after `offset`, then step back: binary search, no allocation.
  auto after = std::upper_bound(lines.begin(), lines.end(), offset,
                                [](uint32_t o, const LineEntry& e) { return o < e.offset; });
  return after == lines.begin() ? nullptr : &*(after - 1);
}

const LineEntry* Program::lineFor(uint32_t offset, std::size_t& hint) const {
  // Entry i is the answer when it starts at or before `offset` and the next one after it.
  auto answers = [&](std::size_t i) {
    return i < lines.size() && lines[i].offset <= offset &&
           (i + 1 == lines.size() || offset < lines[i + 1].offset);
  };
  if (answers(hint)) return &lines[hint];
  if (answers(hint + 1)) return &lines[++hint];
  const LineEntry* e = lineFor(offset);
  if (e != nullptr) hint = static_cast<std::size_t>(e - lines.data());
  return e;
}

}  // namespace ncc::bytecode
