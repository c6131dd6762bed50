#pragma once
// The three ISO-milling dialect tables (one file each: dialect_<name>.cpp).
#include "ncc/passes/dialect_table.h"

namespace ncc::passes {

extern const DialectTable kFanucMTable;
extern const DialectTable kMazakMTable;
extern const DialectTable kSiemensIsoMTable;

}  // namespace ncc::passes
