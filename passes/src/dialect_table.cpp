#include "ncc/passes/dialect_table.h"

#include "absl/strings/str_cat.h"
#include "dialect_tables.h"

namespace ncc::passes {

const GCodeEntry* DialectTable::findG(int code10) const {
  for (const GCodeEntry& e : gcodes)
    if (e.code10 == code10) return &e;
  return nullptr;
}

const GCodeEntry* DialectTable::powerOnDefault(GGroup group) const {
  for (const GCodeEntry& e : gcodes)
    if (e.group == group && e.power_on_default) return &e;
  return nullptr;
}

const DialectTable* dialectTable(Dialect dialect) {
  switch (dialect) {
    case Dialect::FanucM: return &kFanucMTable;
    case Dialect::MazakM: return &kMazakMTable;
    case Dialect::SiemensIsoM: return &kSiemensIsoMTable;
    case Dialect::FanucT:
    case Dialect::SiemensDin: return nullptr;
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
