#pragma once
// The dialect tables (one file each: dialect_<name>.cpp): the three ISO-milling dialects, and
// the DIN language of siemens-iso-m after G290.
#include "ncc/passes/dialect_table.h"

namespace ncc::passes {

extern const DialectTable kFanucMTable;
extern const DialectTable kMazakMTable;
extern const DialectTable kSiemensIsoMTable;
const DialectTable& siemensDinTable();

}  // namespace ncc::passes
