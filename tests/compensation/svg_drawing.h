#pragma once
// Draws a compensation case for the docs (docs/compensation/*.svg): the programmed path thin,
// grey and dashed, the tool centre's path solid (feed moves blue, rapids light blue), the end
// point of every compensated move as a dot with the tool's circle about it (faint). Plane
// coordinates X Y, Y up. Deterministic: fixed formatting, two decimals.
#include <string>
#include <vector>

#include "ncc/ir/ir.h"

namespace ncc::passes::testing {

std::string drawSvg(const std::string& title, const std::vector<ir::Block>& programmed,
                    const std::vector<ir::Block>& compensated);

}  // namespace ncc::passes::testing
