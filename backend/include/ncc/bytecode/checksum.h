#pragma once
// The file checksum of bytecode 2.0 (docs/bytecode.md, "Checksum"): 64-bit FNV-1a over the
// file from the end of the fixed header to the end of the file (axis table, code, line table,
// strings, units), then over the fixed header with its checksum field read as zero. This order
// lets the streaming writer hash every byte as it writes it and patch the header last.
//
// FNV-1a steps are bijective in the state (xor a byte, multiply by an odd prime modulo 2^64),
// so any change to a single byte, anywhere, always changes the checksum; other changes slip
// through with a chance of about 2^-64.
#include <cstddef>
#include <cstdint>
#include <span>

namespace ncc::bytecode {

class Fnv1a64 {
 public:
  void update(std::span<const uint8_t> bytes) {
    // A local state (through the byte pointer, which may alias anything, the member would be
    // stored and reloaded at every byte), eight bytes a turn (the loop's own count and branch
    // no longer cost as much as the hash).
    uint64_t s = state_;
    const uint8_t* p = bytes.data();
    const size_t n = bytes.size();
    size_t i = 0;
    for (; i + 8 <= n; i += 8) {
      s = (s ^ p[i]) * kPrime;
      s = (s ^ p[i + 1]) * kPrime;
      s = (s ^ p[i + 2]) * kPrime;
      s = (s ^ p[i + 3]) * kPrime;
      s = (s ^ p[i + 4]) * kPrime;
      s = (s ^ p[i + 5]) * kPrime;
      s = (s ^ p[i + 6]) * kPrime;
      s = (s ^ p[i + 7]) * kPrime;
    }
    for (; i < n; ++i) s = (s ^ p[i]) * kPrime;
    state_ = s;
  }
  uint64_t value() const { return state_; }

 private:
  static constexpr uint64_t kPrime = 0x100000001B3ull;
  uint64_t state_ = 0xCBF29CE484222325ull;  // the FNV offset basis
};

// The checksum `file` should carry; `file` holds at least the fixed header.
uint64_t fileChecksum(std::span<const uint8_t> file);
// The checksum stored in the header of `file` (at least the fixed header).
uint64_t storedChecksum(std::span<const uint8_t> file);
// Writes fileChecksum(file) into its header: for tests and fuzzers that edit a file on purpose
// and want it to reach the checks after the checksum.
void sealChecksum(std::span<uint8_t> file);

}  // namespace ncc::bytecode
