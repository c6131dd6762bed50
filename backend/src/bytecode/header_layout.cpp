#include "header_layout.h"

#include <algorithm>

#include "bytes.h"

namespace ncc::bytecode {

std::vector<uint8_t> encodeHeader(const Header& header, const SectionTable& sections,
                                  uint64_t checksum) {
  const int axis_count = static_cast<int>(header.axes.size());
  std::vector<uint8_t> out(headerSize(axis_count), 0);
  uint8_t* p = out.data();
  for (char c : kMagic) bytes::putU8(p, static_cast<uint8_t>(c));
  bytes::putU16(p, header.version_major);
  bytes::putU16(p, header.version_minor);
  bytes::putU8(p, static_cast<uint8_t>(header.dialect));
  bytes::putU8(p, static_cast<uint8_t>(axis_count));
  bytes::putU16(p, 0);
  bytes::putU32(p, header.variable_count);
  bytes::putU64(p, header.config_hash);
  for (const SectionRange& s : sections) {
    bytes::putU32(p, s.offset);
    bytes::putU32(p, s.size);
  }
  bytes::putU64(p, checksum);
  for (const AxisInfo& axis : header.axes) {
    uint8_t* entry = p;
    const size_t length = std::min<size_t>(axis.name.size(), kMaxAxisNameLength);
    bytes::putU8(p, static_cast<uint8_t>(axis.kind));
    bytes::putU8(p, static_cast<uint8_t>(length));
    std::copy_n(axis.name.begin(), length, p);
    p = entry + kAxisEntrySize;
  }
  return out;
}

}  // namespace ncc::bytecode
