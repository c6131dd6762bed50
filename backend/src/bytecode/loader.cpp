#include "ncc/bytecode/loader.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <functional>
#include <iterator>

#include "absl/strings/str_cat.h"
#include "bytes.h"
#include "ncc/bytecode/checksum.h"
#include "ncc/bytecode/code_view.h"
#include "header_layout.h"

namespace ncc::bytecode {

namespace {

constexpr const char* kSectionNames[kSectionCount] = {"code", "line table", "string pool",
                                                           "unit table"};

Error problem(std::string code, std::string message) {
  return Error{std::move(code), std::move(message)};
}

std::optional<Error> readAxes(std::span<const uint8_t> bytes, int axis_count, Header& header) {
  header.axes.clear();
  for (int i = 0; i < axis_count; ++i) {
    const uint8_t* entry = bytes.data() + kFixedHeaderSize + kAxisEntrySize * i;
    const std::string where = absl::StrCat("axis table entry ", i);
    if (entry[0] > static_cast<uint8_t>(AxisKind::Rotary))
      return problem("NCC7005", absl::StrCat(where, ": unknown axis kind ", entry[0]));
    const uint8_t length = entry[1];
    if (length == 0 || length > kMaxAxisNameLength)
      return problem("NCC7005", absl::StrCat(where, ": name length ", length, " (1 to ",
                                             kMaxAxisNameLength, " allowed)"));
    for (uint32_t k = 0; k < kMaxAxisNameLength; ++k) {
      const uint8_t c = entry[2 + k];
      const bool ok = k < length ? (c > 0x20 && c < 0x7F) : c == 0;
      if (!ok)
        return problem("NCC7005", absl::StrCat(where, ": invalid name byte 0x",
                                               absl::Hex(c, absl::kZeroPad2), " at ", k));
    }
    AxisInfo axis{std::string(reinterpret_cast<const char*>(entry + 2), length),
                  static_cast<AxisKind>(entry[0])};
    for (const AxisInfo& earlier : header.axes)
      if (earlier.name == axis.name)
        return problem("NCC7005", absl::StrCat(where, ": axis name '", axis.name, "' repeated"));
    header.axes.push_back(std::move(axis));
  }
  return std::nullopt;
}

std::optional<Error> readStrings(std::span<const uint8_t> s, std::vector<std::string>& out) {
  if (s.size() < 4) return problem("NCC7007", "string pool: missing the string count");
  const uint32_t count = bytes::getU32(s.data());
  // Each string takes at least its 4-byte length: a larger count cannot fit.
  if (count > (s.size() - 4) / 4)
    return problem("NCC7007", absl::StrCat("string pool: count ", count, " does not fit in ",
                                           s.size(), " bytes"));
  out.clear();
  out.reserve(count);
  size_t at = 4;
  for (uint32_t i = 0; i < count; ++i) {
    if (s.size() - at < 4)
      return problem("NCC7007", absl::StrCat("string pool: string ", i, " truncated"));
    const uint32_t length = bytes::getU32(s.data() + at);
    at += 4;
    if (length > s.size() - at)
      return problem("NCC7007", absl::StrCat("string pool: string ", i, " (", length,
                                             " bytes) runs past the section"));
    out.emplace_back(reinterpret_cast<const char*>(s.data() + at), length);
    at += length;
  }
  if (at != s.size())
    return problem("NCC7007", absl::StrCat("string pool: ", s.size() - at,
                                           " bytes after the last string"));
  return std::nullopt;
}

std::optional<Error> readLines(std::span<const uint8_t> s, std::vector<LineEntry>& out) {
  if (s.size() % kLineEntrySize != 0)
    return problem("NCC7008", absl::StrCat("line table: size ", s.size(),
                                           " is not a multiple of ", kLineEntrySize));
  out.clear();
  out.reserve(s.size() / kLineEntrySize);
  for (size_t at = 0; at < s.size(); at += kLineEntrySize) {
    const uint8_t* p = s.data() + at;
    out.push_back(LineEntry{bytes::getU32(p), bytes::getU32(p + 4), bytes::getU32(p + 8),
                            bytes::getU32(p + 12)});
  }
  return std::nullopt;
}

// The unit table, and from 2.3 the variable names after it.
std::optional<Error> readUnits(std::span<const uint8_t> s, uint16_t minor, std::vector<Unit>& out,
                               std::vector<VariableName>& names) {
  if (s.size() < 4) return problem("NCC7009", "unit table: missing the unit count");
  const uint32_t count = bytes::getU32(s.data());
  if (count == 0) return problem("NCC7009", "unit table: no program unit");
  const uint64_t units_end = uint64_t{count} * kUnitEntrySize + 4;
  const bool with_names = minor >= kFirstMinorWithNames;
  if (with_names ? units_end + 4 > s.size() : units_end != s.size())
    return problem("NCC7009", absl::StrCat("unit table: ", count, " units need ", units_end,
                                           " bytes", with_names ? " and the name count" : "",
                                           ", the section has ", s.size()));
  out.clear();
  out.reserve(count);
  for (uint32_t i = 0; i < count; ++i) {
    const uint8_t* p = s.data() + 4 + kUnitEntrySize * i;
    out.push_back(Unit{bytes::getU32(p), bytes::getU32(p + 4)});
  }
  names.clear();
  if (!with_names) return std::nullopt;
  const uint32_t name_count = bytes::getU32(s.data() + units_end);
  if (units_end + 4 + uint64_t{name_count} * kVariableNameEntrySize != s.size())
    return problem("NCC7009", absl::StrCat("variable names: ", name_count, " names do not fill ",
                                           "the rest of the unit section (", s.size(), " bytes)"));
  names.reserve(name_count);
  for (uint32_t i = 0; i < name_count; ++i) {
    const uint8_t* p = s.data() + units_end + 4 + kVariableNameEntrySize * i;
    names.push_back(VariableName{bytes::getU32(p), bytes::getU32(p + 4)});
  }
  return std::nullopt;
}

// The file's first bytes (at least its header, or the whole file when shorter) and its size.
struct Head {
  std::span<const uint8_t> bytes;
  uint64_t file_size = 0;
};

// The checksum the file's contents give, or an error when they cannot be read.
using ChecksumOf = std::function<std::optional<uint64_t>()>;

// Everything before the sections: magic, version, checksum, header fields, axis table and the
// section table, whose sections must tile the rest of the file exactly, in order.
// Since 2.2 the bytes after the unit table are the block store (`blocks`; empty before).
std::optional<Error> readHeader(const Head& head, const ChecksumOf& checksum, Header& header,
                                SectionTable& sections, SectionRange& blocks) {
  const uint64_t file_size = head.file_size;
  if (file_size < kFixedHeaderSize)
    return problem("NCC7001", absl::StrCat("file of ", file_size, " bytes is shorter than the ",
                                           kFixedHeaderSize, "-byte header"));
  if (!std::equal(std::begin(kMagic), std::end(kMagic), head.bytes.begin()))
    return problem("NCC7002", "not an ncc bytecode file (magic is not 'NCCB')");
  const uint8_t* p = head.bytes.data();
  header.version_major = bytes::getU16(p + 4);
  header.version_minor = bytes::getU16(p + 6);
  if (header.version_major != kVersionMajor || header.version_minor > kVersionMinor)
    return problem("NCC7003", absl::StrCat("bytecode version ", header.version_major, ".",
                                           header.version_minor, " is not supported (this is ",
                                           kVersionMajor, ".", kVersionMinor, ")"));
  // Before any other field is trusted: a file changed after it was written (a flipped bit,
  // a hand edit) is refused as a whole rather than run with different moves.
  const std::optional<uint64_t> actual = checksum();
  if (!actual) return problem("NCC7015", "cannot read the file");
  if (const uint64_t stored = storedChecksum(head.bytes); stored != *actual)
    return problem("NCC7016", absl::StrCat("checksum mismatch: the header says ",
                                           absl::Hex(stored, absl::kZeroPad16),
                                           ", the contents give ",
                                           absl::Hex(*actual, absl::kZeroPad16),
                                           " (the file was changed or damaged after it "
                                           "was written)"));
  if (p[8] > static_cast<uint8_t>(Dialect::SiemensDin))
    return problem("NCC7004", absl::StrCat("header: unknown dialect ", p[8]));
  header.dialect = static_cast<Dialect>(p[8]);
  const int axis_count = p[9];
  if (axis_count < 1 || axis_count > kMaxAxes)
    return problem("NCC7004", absl::StrCat("header: axis count ", axis_count, " (1 to ", kMaxAxes,
                                           " allowed)"));
  if (bytes::getU16(p + 10) != 0) return problem("NCC7004", "header: reserved field is not zero");
  header.variable_count = bytes::getU32(p + 12);
  if (header.variable_count < 1 || header.variable_count > kMaxVariableCount)
    return problem("NCC7004", absl::StrCat("header: variable count ", header.variable_count,
                                           " (1 to ", kMaxVariableCount, " allowed)"));
  header.config_hash = bytes::getU64(p + 16);

  const uint32_t header_size = headerSize(axis_count);
  if (file_size < header_size)
    return problem("NCC7001", absl::StrCat("file of ", file_size, " bytes ends inside the ",
                                           header_size, "-byte header"));
  if (std::optional<Error> e = readAxes(head.bytes, axis_count, header)) return e;

  uint64_t expected = header_size;
  for (int i = 0; i < kSectionCount; ++i) {
    sections[i].offset = bytes::getU32(p + kSectionTableOffset + 8 * i);
    sections[i].size = bytes::getU32(p + kSectionTableOffset + 8 * i + 4);
    if (sections[i].offset != expected)
      return problem("NCC7006", absl::StrCat(kSectionNames[i], " section starts at ",
                                             sections[i].offset, ", expected ", expected));
    expected += sections[i].size;
    if (expected > file_size)
      return problem("NCC7006", absl::StrCat(kSectionNames[i], " section (", sections[i].size,
                                             " bytes at ", sections[i].offset,
                                             ") runs past the end of the file (", file_size,
                                             " bytes)"));
  }
  blocks = {static_cast<uint32_t>(expected), 0};
  if (expected == file_size) return std::nullopt;
  if (header.version_minor < kFirstMinorWithBlocks)
    return problem("NCC7006", absl::StrCat(file_size - expected,
                                           " bytes after the last section"));
  blocks.size = static_cast<uint32_t>(file_size - expected);
  return std::nullopt;
}

const SectionRange& range(const SectionTable& sections, Section s) {
  return sections[static_cast<int>(s)];
}

// Reads a whole (small) section of `file`.
std::optional<std::vector<uint8_t>> readSection(const ProgramFile& file, const SectionRange& r) {
  std::vector<uint8_t> out(r.size);
  if (file.read(r.offset, out.data(), out.size()) != out.size()) return std::nullopt;
  return out;
}

// The streaming form of fileChecksum(): the file from the end of the fixed header, a window
// at a time, then the fixed header with the checksum field as zero.
std::optional<uint64_t> streamChecksum(const ProgramFile& file, uint64_t file_size,
                                       std::span<const uint8_t> fixed_header) {
  Fnv1a64 hash;
  std::vector<uint8_t> buffer(CodeView::kPageSize);
  for (uint64_t at = kFixedHeaderSize; at < file_size;) {
    const std::size_t want = static_cast<std::size_t>(std::min<uint64_t>(buffer.size(),
                                                                          file_size - at));
    if (file.read(at, buffer.data(), want) != want) return std::nullopt;
    hash.update(std::span<const uint8_t>(buffer.data(), want));
    at += want;
  }
  std::array<uint8_t, kFixedHeaderSize> zeroed;
  std::copy_n(fixed_header.begin(), kFixedHeaderSize, zeroed.begin());
  std::fill_n(zeroed.begin() + kChecksumOffset, 8, uint8_t{0});
  hash.update(zeroed);
  return hash.value();
}

}  // namespace

std::optional<Error> load(std::span<const uint8_t> bytes, Program& program) {
  Program result;
  SectionTable sections;
  SectionRange blocks;
  if (std::optional<Error> e = readHeader(Head{bytes, bytes.size()},
                                          [&] { return std::optional(fileChecksum(bytes)); },
                                          result.header, sections, blocks))
    return e;
  auto section = [&](Section s) {
    const SectionRange& r = range(sections, s);
    return bytes.subspan(r.offset, r.size);
  };
  std::span<const uint8_t> code = section(Section::Code);
  result.code.assign(code.begin(), code.end());
  if (std::optional<Error> e = readLines(section(Section::Lines), result.lines)) return e;
  if (std::optional<Error> e = readStrings(section(Section::Strings), result.strings)) return e;
  if (std::optional<Error> e = readUnits(section(Section::Units), result.header.version_minor,
                                         result.units, result.variable_names))
    return e;
  std::span<const uint8_t> store = bytes.subspan(blocks.offset, blocks.size);
  result.blocks.assign(store.begin(), store.end());
  program = std::move(result);
  return std::nullopt;
}

std::optional<Error> loadPaged(std::shared_ptr<const ProgramFile> file, Program& program) {
  const int64_t size = file->size();
  if (size < 0) return problem("NCC7015", "cannot read the file");
  const uint64_t file_size = static_cast<uint64_t>(size);
  std::array<uint8_t, kFixedHeaderSize + kAxisEntrySize * kMaxAxes> head_bytes{};
  const std::size_t head_size =
      static_cast<std::size_t>(std::min<uint64_t>(head_bytes.size(), file_size));
  if (file->read(0, head_bytes.data(), head_size) != head_size)
    return problem("NCC7015", "cannot read the file");
  const Head head{std::span<const uint8_t>(head_bytes.data(), head_size), file_size};
  Program result;
  SectionTable sections;
  SectionRange blocks;
  if (std::optional<Error> e = readHeader(
          head, [&] { return streamChecksum(*file, file_size, head.bytes); }, result.header,
          sections, blocks))
    return e;
  const SectionRange& lines = range(sections, Section::Lines);
  if (lines.size % kLineEntrySize != 0)
    return problem("NCC7008", absl::StrCat("line table: size ", lines.size,
                                           " is not a multiple of ", kLineEntrySize));
  std::optional<std::vector<uint8_t>> strings = readSection(*file, range(sections, Section::Strings));
  std::optional<std::vector<uint8_t>> units = readSection(*file, range(sections, Section::Units));
  // The block store is parsed by the run-time preparation as a whole: held in memory.
  std::optional<std::vector<uint8_t>> store = readSection(*file, blocks);
  if (!strings || !units || !store) return problem("NCC7015", "cannot read the file");
  result.blocks = std::move(*store);
  if (std::optional<Error> e = readStrings(*strings, result.strings)) return e;
  if (std::optional<Error> e = readUnits(*units, result.header.version_minor, result.units,
                                         result.variable_names))
    return e;
  const SectionRange& code = range(sections, Section::Code);
  result.paged = PagedSections{std::move(file), code.offset, code.size, lines.offset,
                               lines.size / kLineEntrySize};
  program = std::move(result);
  return std::nullopt;
}

std::optional<Error> loadFilePaged(const std::filesystem::path& path, Program& program) {
  std::shared_ptr<const ProgramFile> file = ProgramFile::open(path);
  if (!file) return problem("NCC7015", absl::StrCat("cannot open '", path.string(), "'"));
  std::optional<Error> e = loadPaged(std::move(file), program);
  if (e && e->code == "NCC7015") e->message = absl::StrCat("cannot read '", path.string(), "'");
  return e;
}

std::optional<Error> loadFile(const std::filesystem::path& path, Program& program) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return problem("NCC7015", absl::StrCat("cannot open '", path.string(), "'"));
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return problem("NCC7015", absl::StrCat("cannot read '", path.string(), "'"));
  return load(bytes, program);
}

}  // namespace ncc::bytecode
