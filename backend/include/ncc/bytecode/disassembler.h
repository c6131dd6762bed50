#pragma once
// `ncc dis FILE.ncb`: the header, then one instruction per line with its code offset, source
// position, mnemonic and operands (coordinates with axis names). Numbers print in the shortest
// form that reads back to the same double, so the listing is exact and stable for golden tests.
#include <ostream>
#include <string>

#include "ncc/bytecode/program.h"

namespace ncc::bytecode {

void disassemble(const Program& program, std::ostream& out);
std::string disassemble(const Program& program);

// The shortest text that parses back to `v` ("10", "-0.5", "1e+30").
std::string formatNumber(double v);

}  // namespace ncc::bytecode
