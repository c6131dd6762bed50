#include "run_summary.h"

#include "absl/strings/str_format.h"
#include "ncc/driver/json_output.h"

namespace ncc::cli {

// The planner keeps the commanded setpoints within the limits: what shows here is what the
// servo model adds.
std::string limitViolationsLine(const vm::RunStatistics& s, int axis_count) {
  int64_t travel = 0, velocity = 0, acceleration = 0;
  for (int i = 0; i < axis_count; ++i) {
    travel += s.violations[i].travel;
    velocity += s.violations[i].velocity;
    acceleration += s.violations[i].acceleration;
  }
  return absl::StrFormat("limit violations   %d (servo actual: %d travel, %d velocity, %d acceleration ticks)",
                         s.limit_violations, travel, velocity, acceleration);
}

std::string lookaheadLine(const vm::RunStatistics& s, int lookahead_segments) {
  const double share = s.ticks > 0 ? 100.0 * static_cast<double>(s.lookahead_limited_ticks) /
                                         static_cast<double>(s.ticks)
                                   : 0.0;
  return absl::StrFormat("look-ahead limited %.1f %% of the time (%d segments: [machine] lookahead_segments)",
                         share, lookahead_segments);
}

void printSummary(std::ostream& out, const driver::SimulationResult& sim,
                  const bytecode::Program& program, double tick_seconds, int lookahead_segments) {
  const vm::RunStatistics& s = sim.statistics;
  out << absl::StrFormat("program time       %.3f s (%d ticks of %g ms)\n", s.program_time, s.ticks,
                         tick_seconds * 1000.0)
      << absl::StrFormat("path length        %.3f mm feed, %.3f mm rapid\n", s.feed_length, s.rapid_length)
      << "max following error";
  for (int i = 0; i < program.axisCount(); ++i)
    out << absl::StrFormat("  %s %.4f", program.header.axes[i].name, s.max_following_error[i]);
  out << " mm\n"
      << absl::StrFormat("max contour error  %.4f mm (t = %.3f s)\n", s.max_contour_error,
                         static_cast<double>(s.max_contour_error_tick) * tick_seconds)
      << limitViolationsLine(s, program.axisCount()) << '\n'
      << lookaheadLine(s, lookahead_segments) << '\n'
      << "final position    ";
  for (int i = 0; i < program.axisCount(); ++i)
    out << ' ' << program.header.axes[i].name << driver::jsonNumber(sim.final_commanded[i]);
  out << '\n' << "status             " << (sim.alarm ? "alarm " + sim.alarm->code : std::string("completed")) << '\n';
}

}  // namespace ncc::cli
