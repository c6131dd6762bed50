#pragma once
// The figures of a simulated run that `ncc run` prints (docs/cli.md, "ncc run summary"): as
// text for people (--emit=summary) and as one JSON object for tools (--emit=summary-json).
#include <ostream>
#include <string>

#include "ncc/bytecode/program.h"
#include "ncc/driver/simulate.h"
#include "ncc/vm/controller_stats.h"

namespace ncc::cli {

// What a summary is made of: the run, its program, and the machine settings it names.
struct SummaryInput {
  const driver::SimulationResult& sim;
  const bytecode::Program& program;
  double tick_seconds = 0.001;
  int lookahead_segments = 0;
};

// Samples of the servo model's actual motion beyond the machine's limits, by kind.
std::string limitViolationsLine(const vm::RunStatistics& s, int axis_count);

// How often the look-ahead's depth held the speed down, and the setting that sets it.
std::string lookaheadLine(const vm::RunStatistics& s, int lookahead_segments);

// Seconds as h:mm:ss, rounded to the second ("1:02:03").
std::string hoursMinutesSeconds(double seconds);

// The text summary, one figure per line.
void printSummary(std::ostream& out, const SummaryInput& in);

// The same figures as one JSON object on one line, stable key names (docs/cli.md).
void printSummaryJson(std::ostream& out, const SummaryInput& in);

}  // namespace ncc::cli
