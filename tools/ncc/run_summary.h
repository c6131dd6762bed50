#pragma once
// The figures of a simulated run that `ncc run` prints (docs/cli.md, "ncc run summary").
#include <ostream>
#include <string>

#include "ncc/bytecode/program.h"
#include "ncc/driver/simulate.h"
#include "ncc/vm/controller_stats.h"

namespace ncc::cli {

// Samples of the servo model's actual motion beyond the machine's limits, by kind.
std::string limitViolationsLine(const vm::RunStatistics& s, int axis_count);

// How often the look-ahead's depth held the speed down, and the setting that sets it.
std::string lookaheadLine(const vm::RunStatistics& s, int lookahead_segments);

// The text summary, one figure per line.
void printSummary(std::ostream& out, const driver::SimulationResult& sim,
                  const bytecode::Program& program, double tick_seconds, int lookahead_segments);

}  // namespace ncc::cli
