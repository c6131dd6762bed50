#pragma once
// Numbers in messages: as short as they read (2.5, -5, 1e+47), no trailing zeros.
#include <string>

namespace ncc::eval {

std::string formatNumber(double v);

}  // namespace ncc::eval
