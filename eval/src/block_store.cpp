#include "ncc/eval/block_store.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <tuple>
#include <type_traits>
#include <unordered_map>

#include "absl/strings/str_cat.h"

namespace ncc::eval {

namespace {

constexpr uint8_t kMagic[4] = {'N', 'C', 'B', 'S'};
constexpr uint16_t kVersion = 7;  // 2: the loop limits; 3: the tree written by its schema; 4: DIN nodes; 5: DIN control structures; 6: DIN strings; 7: REPEAT sections, SET/REP

uint64_t zigzag(int64_t v) { return (static_cast<uint64_t>(v) << 1) ^ static_cast<uint64_t>(v >> 63); }
int64_t unzigzag(uint64_t u) { return static_cast<int64_t>((u >> 1) ^ (~(u & 1) + 1)); }

// ---- Writing ------------------------------------------------------------------------------

class Writer {
 public:
  void u8(uint8_t v) { out.push_back(v); }
  void varint(uint64_t v) {
    while (v >= 0x80) {
      out.push_back(static_cast<uint8_t>(v | 0x80));
      v >>= 7;
    }
    out.push_back(static_cast<uint8_t>(v));
  }
  void svarint(int64_t v) { varint(zigzag(v)); }
  void fixed64(uint64_t v) {
    for (int i = 0; i < 8; ++i) out.push_back(static_cast<uint8_t>(v >> (8 * i)));
  }
  void str(std::string_view s) {
    varint(s.size());
    out.insert(out.end(), s.begin(), s.end());
  }
  std::vector<uint8_t> out;
};

// What source locations are coded relative to: the file and line a block starts on, and a
// column near the location (its parent's: the block's, the previous word's, the enclosing
// expression's or statement's), so that most take one byte even on long lines.
struct LineBase {
  uint32_t file = 0;
  uint32_t line = 0;
  uint32_t column = 0;
  LineBase at(const SourceLocation& loc) const { return {file, line, loc.column}; }
};

constexpr int kMaxDecimals = 14;
constexpr double kPowersOf10[kMaxDecimals + 1] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6, 1e7,
                                                  1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14};

bool sameBits(double a, double b) { return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b); }

// A literal as written in a program, `12.5` or `-0.0015`, is the double nearest m / 10^k; so
// is the quotient of the two exact doubles m and 10^k (IEEE division rounds correctly). Such a
// number is written as m and k, checked to give the same bits back (never -0.0). k = 0: an
// integer.
bool asDecimal(double v, int64_t& m, int& k) {
  if (!(std::abs(v) <= 9.0e15) || sameBits(v, -0.0)) return false;  // NaN fails too
  for (k = 0; k <= kMaxDecimals; ++k) {
    const double scaled = v * kPowersOf10[k];
    if (!(std::abs(scaled) < 9.0e15)) return false;
    m = static_cast<int64_t>(std::nearbyint(scaled));
    if (sameBits(static_cast<double>(m) / kPowersOf10[k], v)) return true;
  }
  return false;
}

void writeLoc(Writer& w, const SourceLocation& loc, const LineBase& base) {
  if (loc.file == base.file && loc.line == base.line) {
    w.varint((zigzag(int64_t{loc.column} - int64_t{base.column}) << 1) | 1);
    return;
  }
  w.varint(uint64_t{loc.column} << 1);
  w.varint(loc.file);
  w.varint(loc.line);
}

// ---- The syntax tree, by its schema (ast.h) -------------------------------------------------
// Every node is written member by member in its Schema's order, each member by its type, so a
// member added to a node's schema is written, read, compared and counted in the nesting
// without a line here. A masked node starts with a varint of one bit per member: set when the
// member differs from its default (a bool member is its bit); only those members follow.
// Locations are coded relative to a base that a node's own location moves (its members after
// it are near it), and the elements of a list relative to the previous element's.

using ast::fieldCount;
using ast::forEachField;
template <class T>
concept Node = ast::SchemaNode<T>;
template <class T>
concept Located = requires(const T& t) { t.loc; };

// Whether a member differs from the default a masked node is read into. A member that is a
// node is always written.
template <class T>
bool differs(const T& v, const T& initial) {
  if constexpr (Node<T>) return true;
  else if constexpr (std::is_same_v<T, double>) return !sameBits(v, initial);
  else if constexpr (ast::kIsList<T>) return !v.empty();
  else if constexpr (ast::kIsOptional<T> || ast::kIsBox<T>) return static_cast<bool>(v);
  else return !(v == initial);
}

template <class N>
const N& defaultNode() {
  static const N node{};
  return node;
}

// A number: m / 10^k (k 0..14) as one varint (zigzag(m) << 4 | k), else the escape 15 and its
// IEEE bit pattern.
constexpr uint64_t kNumberBits = 15;

template <Node N>
void writeNode(Writer& w, const N& node, LineBase base);

template <class T>
void writeValue(Writer& w, const T& v, LineBase& base) {
  if constexpr (Node<T>) {
    writeNode(w, v, base);
  } else if constexpr (ast::kIsBox<T>) {
    writeValue(w, *v, base);
  } else if constexpr (ast::kIsList<T>) {
    w.varint(v.size());
    LineBase element = base;
    for (const auto& e : v) {
      writeValue(w, e, element);
      if constexpr (Located<typename T::value_type>) element = base.at(e.loc);
    }
  } else if constexpr (ast::kIsOptional<T>) {
    writeValue(w, *v, base);
  } else if constexpr (std::is_same_v<T, SourceLocation>) {
    writeLoc(w, v, base);
    base = base.at(v);
  } else if constexpr (std::is_same_v<T, double>) {
    int64_t m = 0;
    int k = 0;
    if (asDecimal(v, m, k)) {
      w.varint(zigzag(m) << 4 | static_cast<uint64_t>(k));
    } else {
      w.varint(kNumberBits);
      w.fixed64(std::bit_cast<uint64_t>(v));
    }
  } else if constexpr (std::is_same_v<T, std::string>) {
    w.str(v);
  } else if constexpr (ast::kIsInline<T>) {
    // One byte for a letter 'A'..'Z' (nearly every address), else 0 and the text.
    if (v.size() == 1 && v[0] >= 'A' && v[0] <= 'Z') {
      w.u8(static_cast<uint8_t>(v[0]));
    } else {
      w.u8(0);
      w.str(v.view());
    }
  } else if constexpr (std::is_enum_v<T> || std::is_same_v<T, uint8_t>) {
    w.u8(static_cast<uint8_t>(v));
  } else if constexpr (std::is_same_v<T, int> || std::is_same_v<T, int64_t>) {
    w.svarint(v);
  } else {
    static_assert(sizeof(T) == 0, "a member type the block store cannot write");
  }
}

template <Node N>
void writeNode(Writer& w, const N& node, LineBase base) {
  if constexpr (ast::Schema<N>::masked) {
    uint64_t mask = 0;
    int bit = 0;
    forEachField<N>([&](const auto& f) {
      if (differs(node.*f.member, defaultNode<N>().*f.member)) mask |= uint64_t{1} << bit;
      ++bit;
    });
    w.varint(mask);
    bit = 0;
    forEachField<N>([&](const auto& f) {
      using T = std::remove_cvref_t<decltype(node.*f.member)>;
      if constexpr (!std::is_same_v<T, bool>)
        if (mask & (uint64_t{1} << bit)) writeValue(w, node.*f.member, base);
      ++bit;
    });
  } else {
    forEachField<N>([&](const auto& f) { writeValue(w, node.*f.member, base); });
  }
}

void writeBlock(Writer& w, const StoredBlock& stored, uint32_t file) {
  w.u8(static_cast<uint8_t>(stored.start));
  writeNode(w, stored.block, LineBase{file, stored.position.line, stored.position.column});
}

// A position's column and language in one varint: column << 1 | (language is DIN).
static_assert(static_cast<int>(frontend::Language::Din) == 1, "one bit holds the language");
void writeColumn(Writer& w, const frontend::BlockPosition& p) {
  w.varint(uint64_t{p.column} << 1 | static_cast<uint64_t>(p.language));
}

void writePosition(Writer& w, const frontend::BlockPosition& p) {
  w.varint(p.offset);
  w.varint(p.line);
  writeColumn(w, p);
}

void writePoint(Writer& w, const ProgramPoint& p) {
  w.varint(p.file);
  writePosition(w, p.position);
}

// ---- Reading ------------------------------------------------------------------------------

class Reader {
 public:
  Reader(std::span<const uint8_t> bytes, std::string& error) : bytes_(bytes), error_(error) {}

  bool fail(const std::string& what) {
    if (error_.empty()) error_ = absl::StrCat("block store: ", what, " (at byte ", pos_, ")");
    return false;
  }
  size_t remaining() const { return bytes_.size() - pos_; }
  bool atEnd() const { return pos_ == bytes_.size(); }

  bool u8(uint8_t& v) {
    if (pos_ >= bytes_.size()) return fail("truncated");
    v = bytes_[pos_++];
    return true;
  }
  bool varint(uint64_t& v) {
    v = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      uint8_t b = 0;
      if (!u8(b)) return false;
      if (shift == 63 && b > 1) return fail("varint out of range");
      v |= uint64_t{b & 0x7fu} << shift;
      if (!(b & 0x80)) return true;
    }
    return fail("varint too long");
  }
  bool svarint(int64_t& v) {
    uint64_t u = 0;
    if (!varint(u)) return false;
    v = unzigzag(u);
    return true;
  }
  bool u32(uint32_t& v, const char* what) {
    uint64_t u = 0;
    if (!varint(u)) return false;
    if (u > std::numeric_limits<uint32_t>::max()) return fail(absl::StrCat(what, " out of range"));
    v = static_cast<uint32_t>(u);
    return true;
  }
  bool int32(int& v, const char* what) {
    int64_t s = 0;
    if (!svarint(s)) return false;
    if (s < std::numeric_limits<int>::min() || s > std::numeric_limits<int>::max())
      return fail(absl::StrCat(what, " out of range"));
    v = static_cast<int>(s);
    return true;
  }
  bool fixed64(uint64_t& v) {
    if (remaining() < 8) return fail("truncated");
    v = 0;
    for (int i = 0; i < 8; ++i) v |= uint64_t{bytes_[pos_ + static_cast<size_t>(i)]} << (8 * i);
    pos_ += 8;
    return true;
  }
  // A count of items that take at least `min_size` bytes each: never more than the rest allows.
  // Items are appended as they are read (never allocated ahead from a count), so a damaged
  // count at each of many nesting levels cannot multiply what is allocated.
  bool count(uint64_t& n, size_t min_size = 1) {
    if (!varint(n)) return false;
    if (n > remaining() / min_size) return fail("count beyond the remaining bytes");
    return true;
  }
  bool str(std::string& s) {
    uint64_t n = 0;
    if (!count(n)) return false;
    s.assign(reinterpret_cast<const char*>(bytes_.data() + pos_), n);
    pos_ += n;
    return true;
  }
  bool raw(const uint8_t* expected, size_t n) {
    if (remaining() < n || !std::equal(expected, expected + n, bytes_.data() + pos_)) return false;
    pos_ += n;
    return true;
  }

 private:
  std::span<const uint8_t> bytes_;
  size_t pos_ = 0;
  std::string& error_;
};

bool readLoc(Reader& r, SourceLocation& loc, const LineBase& base) {
  uint64_t head = 0;
  if (!r.varint(head)) return false;
  if (head & 1) {
    const int64_t column = int64_t{base.column} + unzigzag(head >> 1);  // |delta| < 2^62
    if (column < 0 || column > std::numeric_limits<uint32_t>::max())
      return r.fail("column out of range");
    loc = {base.file, base.line, static_cast<uint32_t>(column)};
    return true;
  }
  if ((head >> 1) > std::numeric_limits<uint32_t>::max()) return r.fail("column out of range");
  loc.column = static_cast<uint32_t>(head >> 1);
  return r.u32(loc.file, "file id") && r.u32(loc.line, "line");
}

template <Node N>
bool readNode(Reader& r, N& node, LineBase base, int depth);

// The fewest bytes a value of each type takes: a count of them is checked against the rest,
// so a damaged count cannot make the reader allocate more than the input could hold.
template <class T>
constexpr size_t minimumSize() {
  if constexpr (Node<T>) {
    if constexpr (ast::Schema<T>::masked) {
      return 1;
    } else {
      size_t sum = 0;
      std::apply([&](const auto&... f) { ((sum += minimumSize<std::remove_cvref_t<decltype(T{}.*f.member)>>()), ...); },
                 ast::Schema<T>::fields);
      return sum;
    }
  } else {
    return 1;
  }
}

template <class T>
bool readValue(Reader& r, T& v, LineBase& base, int depth) {
  if constexpr (Node<T>) {
    return readNode(r, v, base, depth);
  } else if constexpr (ast::kIsBox<T>) {
    return readValue(r, v.emplace(), base, depth);
  } else if constexpr (ast::kIsList<T>) {
    uint64_t n = 0;
    if (!r.count(n, minimumSize<typename T::value_type>())) return false;
    if (n == 0) return r.fail("an empty list written");
    LineBase element = base;
    for (uint64_t i = 0; i < n; ++i) {
      auto& e = v.emplace_back();
      if (!readValue(r, e, element, depth)) return false;
      if constexpr (Located<typename T::value_type>) element = base.at(e.loc);
    }
    return true;
  } else if constexpr (ast::kIsOptional<T>) {
    return readValue(r, v.emplace(), base, depth);
  } else if constexpr (std::is_same_v<T, SourceLocation>) {
    if (!readLoc(r, v, base)) return false;
    base = base.at(v);
    return true;
  } else if constexpr (std::is_same_v<T, double>) {
    uint64_t head = 0;
    if (!r.varint(head)) return false;
    const uint64_t k = head & 15;
    if (k == kNumberBits) {
      if (head != kNumberBits) return r.fail("bad number");
      uint64_t bits = 0;
      if (!r.fixed64(bits)) return false;
      v = std::bit_cast<double>(bits);
      return true;
    }
    if (k > kMaxDecimals) return r.fail("bad decimal scale");
    v = static_cast<double>(unzigzag(head >> 4)) / kPowersOf10[k];
    return true;
  } else if constexpr (std::is_same_v<T, std::string>) {
    return r.str(v);
  } else if constexpr (ast::kIsInline<T>) {
    uint8_t letter = 0;
    if (!r.u8(letter)) return false;
    if (letter == 0) {
      std::string text;
      if (!r.str(text)) return false;
      if (text.size() > T::kCapacity || (text.size() == 1 && text[0] >= 'A' && text[0] <= 'Z'))
        return r.fail("bad address");
      v = T(text);
      return true;
    }
    if (letter < 'A' || letter > 'Z') return r.fail("bad address");
    v = T(static_cast<char>(letter));
    return true;
  } else if constexpr (std::is_enum_v<T>) {
    uint8_t u = 0;
    if (!r.u8(u)) return false;
    if (u >= ast::kEnumValues<T>) return r.fail("unknown kind");
    v = static_cast<T>(u);
    return true;
  } else if constexpr (std::is_same_v<T, uint8_t>) {
    return r.u8(v);
  } else if constexpr (std::is_same_v<T, int>) {
    return r.int32(v, "number");
  } else if constexpr (std::is_same_v<T, int64_t>) {
    return r.svarint(v);
  } else {
    static_assert(sizeof(T) == 0, "a member type the block store cannot read");
  }
}

template <Node N>
bool readNode(Reader& r, N& node, LineBase base, int depth) {
  if constexpr (ast::Schema<N>::nests)
    if (++depth > kMaxStoredNesting) return r.fail("expressions nested too deep");
  bool ok = true;
  if constexpr (ast::Schema<N>::masked) {
    static_assert(fieldCount<N>() <= 63, "the mask is one varint");
    uint64_t mask = 0;
    if (!r.varint(mask)) return false;
    if (mask >> fieldCount<N>()) return r.fail("unknown members");
    int bit = 0;
    forEachField<N>([&](const auto& f) {
      using T = std::remove_cvref_t<decltype(node.*f.member)>;
      const bool present = (mask & (uint64_t{1} << bit++)) != 0;
      if (!ok) return;
      if constexpr (std::is_same_v<T, bool>) {
        node.*f.member = present;
      } else if (present) {
        // One encoding per tree: a member written must differ from its default.
        ok = readValue(r, node.*f.member, base, depth) &&
             (differs(node.*f.member, defaultNode<N>().*f.member) || r.fail("a default value written"));
      }
    });
  } else {
    forEachField<N>([&](const auto& f) { ok = ok && readValue(r, node.*f.member, base, depth); });
  }
  return ok;
}

bool readBlock(Reader& r, StoredBlock& stored, uint32_t file) {
  uint8_t start = 0;
  if (!r.u8(start)) return false;
  if (start > static_cast<uint8_t>(StoredBlock::Start::Program)) return r.fail("unknown block start");
  stored.start = static_cast<StoredBlock::Start>(start);
  ast::Block& b = stored.block;
  if (!readNode(r, b, LineBase{file, stored.position.line, stored.position.column}, 0)) return false;
  if ((stored.start == StoredBlock::Start::Sequence && !b.sequence) ||
      (stored.start == StoredBlock::Start::Program && !b.program_number))
    return r.fail("block start without its number");
  return true;
}

bool readColumn(Reader& r, frontend::BlockPosition& p) {
  uint64_t v = 0;
  if (!r.varint(v)) return false;
  if ((v >> 1) > std::numeric_limits<uint32_t>::max()) return r.fail("column out of range");
  p.column = static_cast<uint32_t>(v >> 1);
  p.language = static_cast<frontend::Language>(v & 1);
  return true;
}

bool readPosition(Reader& r, frontend::BlockPosition& p) {
  return r.varint(p.offset) && r.u32(p.line, "line") && readColumn(r, p);
}

bool readPoint(Reader& r, ProgramPoint& p) {
  return r.u32(p.file, "file id") && readPosition(r, p.position);
}

bool readFile(Reader& r, StoredFile& f) {
  if (!r.u32(f.id, "file id") || !r.str(f.name)) return false;
  uint64_t n = 0;
  if (!r.count(n, 5)) return false;  // position (3), start, mask
  frontend::BlockPosition previous{0, 0, 0};
  for (uint64_t i = 0; i < n; ++i) {
    StoredBlock& b = f.blocks.emplace_back();
    // Positions: offset and line as differences from the previous block's (wrapping), the
    // column (and language) as it is. Order is checked below, so a difference cannot lie.
    int64_t offset_delta = 0, line_delta = 0;
    if (!r.svarint(offset_delta) || !r.svarint(line_delta) || !readColumn(r, b.position))
      return false;
    b.position.offset = previous.offset + static_cast<uint64_t>(offset_delta);
    const int64_t line = int64_t{previous.line} + line_delta;
    if (line < 0 || line > std::numeric_limits<uint32_t>::max()) return r.fail("line out of range");
    b.position.line = static_cast<uint32_t>(line);
    if (i > 0 && !(previous < b.position)) return r.fail("block positions out of order");
    previous = b.position;
    if (!readBlock(r, b, f.id)) return false;
  }
  if (!readPosition(r, f.record_end)) return false;
  if (!f.blocks.empty() && f.record_end < f.blocks.back().position)
    return r.fail("a block after the end of the record");
  return true;
}

}  // namespace

// ---- Nesting ------------------------------------------------------------------------------

namespace {
// The levels of nodes that nest (Schema::nests) on the deepest path below `v`, as the decoder
// counts them.
template <class T>
int nesting(const T& v) {
  if constexpr (Node<T>) {
    int deepest = 0;
    forEachField<T>([&](const auto& f) { deepest = std::max(deepest, nesting(v.*f.member)); });
    return deepest + (ast::Schema<T>::nests ? 1 : 0);
  } else if constexpr (ast::kIsBox<T>) {
    return v ? nesting(*v) : 0;
  } else if constexpr (ast::kIsList<T>) {
    int deepest = 0;
    for (const auto& e : v) deepest = std::max(deepest, nesting(e));
    return deepest;
  } else {
    return 0;
  }
}
}  // namespace

int blockNesting(const ast::Block& block) { return nesting(block); }

// ---- Encoding -----------------------------------------------------------------------------

std::vector<uint8_t> encodeBlockStore(const BlockStore& store) {
  Writer w;
  for (uint8_t c : kMagic) w.u8(c);
  w.u8(static_cast<uint8_t>(kVersion & 0xff));
  w.u8(static_cast<uint8_t>(kVersion >> 8));
  w.varint(store.main_file);
  w.varint(store.ahead_blocks);
  w.varint(store.limits.max_back_jumps);
  w.varint(store.limits.max_idle_blocks);
  w.varint(store.saved_variables.size());
  for (const auto& [n, v] : store.saved_variables) {
    w.svarint(n);
    w.fixed64(std::bit_cast<uint64_t>(v));
  }
  w.varint(store.files.size());
  for (const StoredFile& f : store.files) {
    w.varint(f.id);
    w.str(f.name);
    w.varint(f.blocks.size());
    frontend::BlockPosition previous{0, 0, 0};
    for (const StoredBlock& b : f.blocks) {
      w.svarint(static_cast<int64_t>(b.position.offset - previous.offset));
      w.svarint(int64_t{b.position.line} - int64_t{previous.line});
      writeColumn(w, b.position);
      previous = b.position;
      writeBlock(w, b, f.id);
    }
    writePosition(w, f.record_end);
  }
  w.varint(store.folder_programs.size());
  for (const auto& [n, point] : store.folder_programs) {
    w.svarint(n);
    writePoint(w, point);
  }
  w.varint(store.named_programs.size());
  for (const auto& [name, point] : store.named_programs) {
    w.str(name);
    writePoint(w, point);
  }
  return std::move(w.out);
}

std::optional<BlockStore> decodeBlockStore(std::span<const uint8_t> bytes, std::string& error) {
  error.clear();
  Reader r(bytes, error);
  if (!r.raw(kMagic, sizeof kMagic)) {
    r.fail("not a block store (no NCBS mark)");
    return std::nullopt;
  }
  uint8_t lo = 0, hi = 0;
  if (!r.u8(lo) || !r.u8(hi)) return std::nullopt;
  if (const uint16_t version = static_cast<uint16_t>(lo | hi << 8); version != kVersion) {
    r.fail(absl::StrCat("version ", version, " (this build reads version ", kVersion, ")"));
    return std::nullopt;
  }
  BlockStore store;
  uint64_t n = 0;
  if (!r.u32(store.main_file, "file id") || !r.varint(store.ahead_blocks) ||
      !r.varint(store.limits.max_back_jumps) || !r.varint(store.limits.max_idle_blocks) ||
      !r.count(n, 9))
    return std::nullopt;
  for (uint64_t i = 0; i < n; ++i) {
    int64_t key = 0;
    uint64_t bits = 0;
    if (!r.svarint(key) || !r.fixed64(bits)) return std::nullopt;
    if (!store.saved_variables.emplace(key, std::bit_cast<double>(bits)).second) {
      r.fail("a variable saved twice");
      return std::nullopt;
    }
  }
  if (!r.count(n, 4)) return std::nullopt;  // id, name, block count, record end
  std::set<uint32_t> ids;
  for (uint64_t i = 0; i < n; ++i) {
    StoredFile& f = store.files.emplace_back();
    if (!readFile(r, f)) return std::nullopt;
    if (!ids.insert(f.id).second) {
      r.fail("a file stored twice");
      return std::nullopt;
    }
  }
  const auto known = [&](const ProgramPoint& p) {
    return ids.count(p.file) ? true : r.fail("a program point in a file not stored");
  };
  if (!store.files.empty() && !ids.count(store.main_file)) {
    r.fail("the main file is not stored");
    return std::nullopt;
  }
  if (!r.count(n, 5)) return std::nullopt;
  for (uint64_t i = 0; i < n; ++i) {
    int64_t number = 0;
    ProgramPoint point;
    if (!r.svarint(number) || !readPoint(r, point) || !known(point)) return std::nullopt;
    if (!store.folder_programs.emplace(number, point).second) {
      r.fail("a folder program stored twice");
      return std::nullopt;
    }
  }
  if (!r.count(n, 5)) return std::nullopt;
  for (uint64_t i = 0; i < n; ++i) {
    std::string name;
    ProgramPoint point;
    if (!r.str(name) || !readPoint(r, point) || !known(point)) return std::nullopt;
    if (!store.named_programs.emplace(std::move(name), point).second) {
      r.fail("a named program stored twice");
      return std::nullopt;
    }
  }
  if (!r.atEnd()) {
    r.fail("bytes after the end of the store");
    return std::nullopt;
  }
  return store;
}

// ---- The program store ---------------------------------------------------------------------

struct StoredProgramStore::FileIndex {
  const StoredFile* file = nullptr;
  std::vector<size_t> programs;  // blocks that start with O n, in file order
  // Blocks that start with N n, by n, in file order: made on the first GOTO into the file.
  bool sequences_made = false;
  std::unordered_map<int64_t, std::vector<size_t>> sequences;
  // Blocks with a DIN label, by label: made on the first jump to a label.
  bool labels_made = false;
  std::unordered_map<std::string, std::vector<size_t>> labels;

  const frontend::BlockPosition& at(size_t i) const { return file->blocks[i].position; }
};

class StoredProgramStore::Cursor final : public BlockCursor {
 public:
  Cursor(const StoredFile* file, uint32_t id) : file_(file), id_(id) {}

  const ast::Block* next() override {
    if (!file_ || i_ >= file_->blocks.size()) return nullptr;
    last_ = file_->blocks[i_].position;
    return &file_->blocks[i_++].block;
  }
  ProgramPoint lastPoint() const override { return {id_, last_}; }
  void seek(const ProgramPoint& point) override {
    if (!file_) return;
    auto it = std::lower_bound(
        file_->blocks.begin(), file_->blocks.end(), point.position,
        [](const StoredBlock& b, const frontend::BlockPosition& p) { return b.position < p; });
    i_ = static_cast<size_t>(it - file_->blocks.begin());
  }
  uint64_t rejectedBlocks() const override { return 0; }  // every stored block was parsed
  uint32_t file() const override { return id_; }

 private:
  const StoredFile* file_;
  uint32_t id_;
  size_t i_ = 0;
  frontend::BlockPosition last_;  // {0, 1, 1} before the first block, as a BlockReader's
};

StoredProgramStore::StoredProgramStore(const BlockStore& store) : store_(store) {
  for (const StoredFile& f : store.files) {
    auto index = std::make_unique<FileIndex>();
    index->file = &f;
    for (size_t i = 0; i < f.blocks.size(); ++i)
      if (f.blocks[i].start == StoredBlock::Start::Program) index->programs.push_back(i);
    files_.emplace(f.id, std::move(index));
  }
}

StoredProgramStore::~StoredProgramStore() = default;

StoredProgramStore::FileIndex* StoredProgramStore::fileIndex(uint32_t file) {
  auto it = files_.find(file);
  return it == files_.end() ? nullptr : it->second.get();
}

std::unique_ptr<BlockCursor> StoredProgramStore::open(uint32_t file) {
  const FileIndex* index = fileIndex(file);
  return std::make_unique<Cursor>(index ? index->file : nullptr, file);
}

std::optional<ProgramPoint> StoredProgramStore::findProgram(int64_t number, uint32_t calling_file) {
  if (number < 0) return std::nullopt;
  if (const FileIndex* index = fileIndex(calling_file))
    for (size_t i : index->programs)
      if (index->file->blocks[i].block.program_number == number)
        return ProgramPoint{calling_file, index->at(i)};
  auto it = store_.folder_programs.find(number);
  if (it == store_.folder_programs.end()) return std::nullopt;
  return it->second;
}

std::optional<ProgramPoint> StoredProgramStore::findProgramNamed(std::string_view name) {
  auto it = store_.named_programs.find(std::string(name));
  if (it == store_.named_programs.end()) return std::nullopt;
  return it->second;
}

namespace {

// The block of `candidates` (indices of the blocks that match, in file order) a jump from `from`
// reaches, searching in `order` within [begin, end), as ProgramIndex::findSequence does.
template <class At>
std::optional<size_t> searchCandidates(const std::vector<size_t>& candidates, At at,
                                       const ProgramPoint& from, SequenceSearch order,
                                       const ProgramPoint& begin, const ProgramPoint& end) {
  // The first candidate at or after `p` (strictly after when `after`).
  const auto firstFrom = [&](const frontend::BlockPosition& p, bool after) {
    return std::partition_point(candidates.begin(), candidates.end(), [&](size_t i) {
      return after ? at(i) <= p : at(i) < p;
    });
  };
  const auto within = [&](auto it) { return it != candidates.end() && at(*it) < end.position; };
  const auto first = firstFrom(begin.position, false);
  switch (order) {
    case SequenceSearch::ForwardThenFromStart:
    case SequenceSearch::Forward: {
      const auto forward = std::max(first, firstFrom(from.position, true));
      if (within(forward)) return *forward;
      if (order == SequenceSearch::ForwardThenFromStart && within(first) &&
          at(*first) <= from.position)
        return *first;
      return std::nullopt;
    }
    case SequenceSearch::Backward: {
      // The last candidate at or before `from` (and at or after `begin`).
      const auto past = firstFrom(from.position, true);
      if (past == first) return std::nullopt;
      const size_t i = *(past - 1);
      if (at(i) < end.position) return i;
      return std::nullopt;
    }
    case SequenceSearch::FromStart:
      if (within(first)) return *first;
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace

std::optional<ProgramPoint> StoredProgramStore::findSequence(int64_t n, const ProgramPoint& from,
                                                             SequenceSearch order,
                                                             const ProgramPoint& begin,
                                                             const ProgramPoint& end) {
  FileIndex* index = fileIndex(from.file);
  if (!index) return std::nullopt;
  if (!index->sequences_made) {
    index->sequences_made = true;
    const std::vector<StoredBlock>& blocks = index->file->blocks;
    for (size_t i = 0; i < blocks.size(); ++i)
      if (blocks[i].start == StoredBlock::Start::Sequence)
        index->sequences[*blocks[i].block.sequence].push_back(i);
  }
  auto it = index->sequences.find(n);
  if (it == index->sequences.end()) return std::nullopt;
  std::optional<size_t> i = searchCandidates(
      it->second, [&](size_t k) { return index->at(k); }, from, order, begin, end);
  if (!i) return std::nullopt;
  return ProgramPoint{from.file, index->at(*i)};
}

std::optional<ProgramPoint> StoredProgramStore::findLabel(std::string_view label,
                                                          const ProgramPoint& from,
                                                          SequenceSearch order,
                                                          const ProgramPoint& begin,
                                                          const ProgramPoint& end) {
  FileIndex* index = fileIndex(from.file);
  if (!index) return std::nullopt;
  if (!index->labels_made) {
    index->labels_made = true;
    const std::vector<StoredBlock>& blocks = index->file->blocks;
    for (size_t i = 0; i < blocks.size(); ++i)
      for (const ast::Statement& st : blocks[i].block.statements)
        if (st.kind == ast::Statement::Kind::Label && st.target.text)
          index->labels[*st.target.text].push_back(i);
  }
  auto it = index->labels.find(std::string(label));
  if (it == index->labels.end()) return std::nullopt;
  std::optional<size_t> i = searchCandidates(
      it->second, [&](size_t k) { return index->at(k); }, from, order, begin, end);
  if (!i) return std::nullopt;
  return ProgramPoint{from.file, index->at(*i)};
}

ProgramPoint StoredProgramStore::programEnd(const ProgramPoint& start) {
  const FileIndex* index = fileIndex(start.file);
  if (!index) return start;
  auto next = std::partition_point(index->programs.begin(), index->programs.end(),
                                   [&](size_t i) { return index->at(i) <= start.position; });
  if (next != index->programs.end()) return {start.file, index->at(*next)};
  return {start.file, index->file->record_end};
}

}  // namespace ncc::eval
