#include "ncc/passes/dialect_table.h"

#include <array>
#include <vector>

#include "absl/strings/str_cat.h"
#include "dialect_tables.h"

namespace ncc::passes {

namespace {

// Codes below G200 are found by index: findG runs for every G word of every block, and a table
// holds about a hundred codes. Higher codes (none in the ISO tables today) are scanned.
constexpr int kIndexedCodes = 2000;
constexpr int kDialects = static_cast<int>(Dialect::SiemensDin) + 1;

using CodeIndex = std::vector<const GCodeEntry*>;

const std::array<CodeIndex, kDialects>& codeIndexes() {
  static const std::array<CodeIndex, kDialects> indexes = [] {
    std::array<CodeIndex, kDialects> out;
    for (int d = 0; d < kDialects; ++d) {
      const DialectTable* t = dialectTable(static_cast<Dialect>(d));
      if (!t) continue;
      out[d].assign(kIndexedCodes, nullptr);
      for (const GCodeEntry& e : t->gcodes)
        if (e.code10 >= 0 && e.code10 < kIndexedCodes && !out[d][e.code10]) out[d][e.code10] = &e;
    }
    return out;
  }();
  return indexes;
}

}  // namespace

const GCodeEntry* DialectTable::findG(int code10) const {
  if (code10 >= 0 && code10 < kIndexedCodes && dialectTable(dialect) == this)
    return codeIndexes()[static_cast<size_t>(dialect)][static_cast<size_t>(code10)];
  for (const GCodeEntry& e : gcodes)
    if (e.code10 == code10) return &e;
  return nullptr;
}

const GCodeEntry* DialectTable::powerOnDefault(GGroup group) const {
  for (const GCodeEntry& e : gcodes)
    if (e.group == group && e.power_on_default) return &e;
  return nullptr;
}

LanguageTables languageTables(Dialect dialect) {
  LanguageTables t;
  switch (dialect) {
    case Dialect::SiemensIsoM:
      t.iso = &kSiemensIsoMTable;
      t.din = &siemensDinTable();
      break;
    case Dialect::SiemensDin:
      t.iso = &kSiemensIsoMTable;
      t.din = &siemensDinTable();
      t.initial = frontend::Language::Din;
      break;
    default:
      t.iso = dialectTable(dialect);
      break;
  }
  return t;
}

const DialectTable* dialectTable(Dialect dialect) {
  switch (dialect) {
    case Dialect::FanucM: return &kFanucMTable;
    case Dialect::MazakM: return &kMazakMTable;
    case Dialect::SiemensIsoM: return &kSiemensIsoMTable;
    case Dialect::SiemensDin: return &siemensDinTable();
    case Dialect::FanucT: return nullptr;
  }
  return nullptr;
}

std::string gCodeName(int code10) {
  int whole = code10 / 10, tenth = code10 % 10;
  std::string name = whole < 10 ? absl::StrCat("G0", whole) : absl::StrCat("G", whole);
  if (tenth != 0) absl::StrAppend(&name, ".", tenth);
  return name;
}

}  // namespace ncc::passes
