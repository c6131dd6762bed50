#pragma once
// The header's byte layout (docs/bytecode.md, "Header"), shared by writer and loader.
//   0  magic "NCCB"          4  u16 major   6 u16 minor   8 u8 dialect   9 u8 axis count
//  10  u16 reserved (0)     12  u32 variable count      16 u64 machine-config hash
//  24  section table: code, lines, strings, units; each u32 offset + u32 size
//  56  u64 checksum (checksum.h)
//  64  axis table: per axis u8 kind, u8 name length, 14 bytes name (zero padded)
#include <array>
#include <cstdint>
#include <vector>

#include "ncc/bytecode/program.h"

namespace ncc::bytecode {

struct SectionRange {
  uint32_t offset = 0;
  uint32_t size = 0;
};
using SectionTable = std::array<SectionRange, kSectionCount>;

inline constexpr uint32_t kSectionTableOffset = 24;

inline uint32_t headerSize(int axis_count) {
  return kFixedHeaderSize + kAxisEntrySize * static_cast<uint32_t>(axis_count);
}

// The fixed header and the axis table; `checksum` goes into its field as given.
std::vector<uint8_t> encodeHeader(const Header& header, const SectionTable& sections,
                                  uint64_t checksum = 0);

}  // namespace ncc::bytecode
