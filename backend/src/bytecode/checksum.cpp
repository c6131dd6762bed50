#include "ncc/bytecode/checksum.h"

#include <algorithm>
#include <array>

#include "bytes.h"
#include "header_layout.h"

namespace ncc::bytecode {

namespace {

// Hashes the fixed header with the checksum field as zero bytes.
void hashFixedHeader(Fnv1a64& hash, std::span<const uint8_t> file) {
  std::array<uint8_t, kFixedHeaderSize> fixed;
  std::copy_n(file.begin(), kFixedHeaderSize, fixed.begin());
  std::fill_n(fixed.begin() + kChecksumOffset, 8, uint8_t{0});
  hash.update(fixed);
}

}  // namespace

uint64_t fileChecksum(std::span<const uint8_t> file) {
  Fnv1a64 hash;
  hash.update(file.subspan(kFixedHeaderSize));
  hashFixedHeader(hash, file);
  return hash.value();
}

uint64_t storedChecksum(std::span<const uint8_t> file) {
  return bytes::getU64(file.data() + kChecksumOffset);
}

void sealChecksum(std::span<uint8_t> file) {
  uint8_t* p = file.data() + kChecksumOffset;
  bytes::putU64(p, fileChecksum(file));
}

}  // namespace ncc::bytecode
