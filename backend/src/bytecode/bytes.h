#pragma once
// Little-endian reads and writes of fixed-width integers and binary64 doubles (private to the
// bytecode library). Byte by byte, so the result does not depend on the host's endianness.
#include <bit>
#include <cstdint>

namespace ncc::bytecode::bytes {

inline void putU8(uint8_t*& p, uint8_t v) { *p++ = v; }
inline void putU16(uint8_t*& p, uint16_t v) {
  for (int i = 0; i < 2; ++i) *p++ = static_cast<uint8_t>(v >> (8 * i));
}
inline void putU32(uint8_t*& p, uint32_t v) {
  for (int i = 0; i < 4; ++i) *p++ = static_cast<uint8_t>(v >> (8 * i));
}
inline void putU64(uint8_t*& p, uint64_t v) {
  for (int i = 0; i < 8; ++i) *p++ = static_cast<uint8_t>(v >> (8 * i));
}
inline void putF64(uint8_t*& p, double v) { putU64(p, std::bit_cast<uint64_t>(v)); }

inline uint16_t getU16(const uint8_t* p) {
  return static_cast<uint16_t>(p[0] | (p[1] << 8));
}
inline uint32_t getU32(const uint8_t* p) {
  uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}
inline uint64_t getU64(const uint8_t* p) {
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}
inline double getF64(const uint8_t* p) { return std::bit_cast<double>(getU64(p)); }

}  // namespace ncc::bytecode::bytes
