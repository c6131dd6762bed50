#include "run_summary.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "ncc/driver/json_output.h"

namespace ncc::cli {

namespace {

// "FILE:LINE" of the worst contour error's block; "" when it is unknown or there is none.
std::string contourErrorSource(const SummaryInput& in) {
  const vm::RunStatistics& s = in.sim.statistics;
  if (s.max_contour_error == 0.0 || s.max_contour_error_where.line == 0) return {};
  const std::string file = driver::sourceFileName(in.program, s.max_contour_error_where.file);
  return absl::StrCat(file.empty() ? "?" : file, ":", s.max_contour_error_where.line);
}

// "X 0.000 .. 20.000  Y ... mm", or "none" when there was no such motion.
std::string extentsText(const vm::AxisExtents& e, const bytecode::Program& program) {
  if (e.empty) return "none";
  std::string text;
  for (int i = 0; i < program.axisCount(); ++i)
    absl::StrAppendFormat(&text, "%s%s %.3f .. %.3f", i ? "  " : "", program.header.axes[i].name,
                          e.min[i], e.max[i]);
  return text + " mm";
}

// {"X": 1.0, ...}
std::string axisObject(const AxisValues& values, const bytecode::Program& program) {
  std::string text = "{";
  for (int i = 0; i < program.axisCount(); ++i)
    absl::StrAppend(&text, i ? ", " : "", driver::jsonString(program.header.axes[i].name), ": ",
                    driver::jsonNumber(values[i]));
  return text + "}";
}

// {"X": {"min": 0.0, "max": 20.0}, ...}, or null when there was no such motion.
std::string extentsObject(const vm::AxisExtents& e, const bytecode::Program& program) {
  if (e.empty) return "null";
  std::string text = "{";
  for (int i = 0; i < program.axisCount(); ++i)
    absl::StrAppend(&text, i ? ", " : "", driver::jsonString(program.header.axes[i].name),
                    ": {\"min\": ", driver::jsonNumber(e.min[i]),
                    ", \"max\": ", driver::jsonNumber(e.max[i]), "}");
  return text + "}";
}

// The servo model's limit violations of all axes, by kind.
struct ViolationCounts {
  int64_t travel = 0, velocity = 0, acceleration = 0;
};
ViolationCounts violationsByKind(const vm::RunStatistics& s, int axis_count) {
  ViolationCounts sum;
  for (int i = 0; i < axis_count; ++i) {
    sum.travel += s.violations[i].travel;
    sum.velocity += s.violations[i].velocity;
    sum.acceleration += s.violations[i].acceleration;
  }
  return sum;
}

double lookaheadPercent(const vm::RunStatistics& s) {
  return s.ticks > 0 ? 100.0 * static_cast<double>(s.lookahead_limited_ticks) /
                           static_cast<double>(s.ticks)
                     : 0.0;
}

}  // namespace

// The planner keeps the commanded setpoints within the limits: what shows here is what the
// servo model adds.
std::string limitViolationsLine(const vm::RunStatistics& s, int axis_count) {
  const ViolationCounts by_kind = violationsByKind(s, axis_count);
  return absl::StrFormat("limit violations   %d (servo actual: %d travel, %d velocity, %d acceleration ticks)",
                         s.limit_violations, by_kind.travel, by_kind.velocity,
                         by_kind.acceleration);
}

std::string lookaheadLine(const vm::RunStatistics& s, int lookahead_segments) {
  return absl::StrFormat("look-ahead limited %.1f %% of the time (%d segments: [machine] lookahead_segments)",
                         lookaheadPercent(s), lookahead_segments);
}

std::string hoursMinutesSeconds(double seconds) {
  const long long total = std::llround(std::max(seconds, 0.0));
  return absl::StrFormat("%d:%02d:%02d", total / 3600, total / 60 % 60, total % 60);
}

void printSummary(std::ostream& out, const SummaryInput& in) {
  const vm::RunStatistics& s = in.sim.statistics;
  const bytecode::Program& program = in.program;
  out << absl::StrFormat("program time       %.3f s (%d ticks of %g ms) = %s\n", s.program_time,
                         s.ticks, in.tick_seconds * 1000.0, hoursMinutesSeconds(s.program_time))
      << absl::StrFormat("path length        %.3f mm feed, %.3f mm rapid\n", s.feed_length, s.rapid_length)
      << "extents feed       " << extentsText(s.feed_extents, program) << '\n'
      << "extents rapid      " << extentsText(s.rapid_extents, program) << '\n'
      << "max following error";
  for (int i = 0; i < program.axisCount(); ++i)
    out << absl::StrFormat("  %s %.4f", program.header.axes[i].name, s.max_following_error[i]);
  out << " mm\n" << absl::StrFormat("max contour error  %.4f mm", s.max_contour_error);
  if (s.max_contour_error > 0.0) {
    const std::string source = contourErrorSource(in);
    out << absl::StrFormat(" (t = %.3f s%s)",
                           static_cast<double>(s.max_contour_error_tick) * in.tick_seconds,
                           source.empty() ? "" : ", " + source);
  }
  out << '\n'
      << limitViolationsLine(s, program.axisCount()) << '\n'
      << lookaheadLine(s, in.lookahead_segments) << '\n'
      << "final position    ";
  for (int i = 0; i < program.axisCount(); ++i)
    out << ' ' << program.header.axes[i].name << driver::jsonNumber(in.sim.final_commanded[i]);
  out << '\n' << "status             " << (in.sim.alarm ? "alarm " + in.sim.alarm->code : std::string("completed")) << '\n';
}

void printSummaryJson(std::ostream& out, const SummaryInput& in) {
  const vm::RunStatistics& s = in.sim.statistics;
  const bytecode::Program& program = in.program;
  using driver::jsonNumber;
  const ViolationCounts by_kind = violationsByKind(s, program.axisCount());
  const bool has_worst = s.max_contour_error > 0.0;
  const std::string worst_file = driver::sourceFileName(program, s.max_contour_error_where.file);
  const bool has_source = has_worst && s.max_contour_error_where.line != 0;
  out << "{\"status\": " << (in.sim.alarm ? "\"alarm\"" : "\"completed\"")
      << ", \"alarm\": " << (in.sim.alarm ? driver::jsonString(in.sim.alarm->code) : "null")
      << ", \"program_time\": " << jsonNumber(s.program_time)
      << ", \"program_time_hms\": " << driver::jsonString(hoursMinutesSeconds(s.program_time))
      << ", \"ticks\": " << s.ticks
      << ", \"tick_seconds\": " << jsonNumber(in.tick_seconds)
      << ", \"feed_length\": " << jsonNumber(s.feed_length)
      << ", \"rapid_length\": " << jsonNumber(s.rapid_length)
      << ", \"feed_extents\": " << extentsObject(s.feed_extents, program)
      << ", \"rapid_extents\": " << extentsObject(s.rapid_extents, program)
      << ", \"max_following_error\": " << axisObject(s.max_following_error, program)
      << ", \"max_contour_error\": " << jsonNumber(s.max_contour_error)
      << ", \"max_contour_error_time\": "
      << (has_worst ? jsonNumber(static_cast<double>(s.max_contour_error_tick) * in.tick_seconds)
                    : "null")
      << ", \"max_contour_error_file\": "
      << (has_source && !worst_file.empty() ? driver::jsonString(worst_file) : "null")
      << ", \"max_contour_error_line\": "
      << (has_source ? std::to_string(s.max_contour_error_where.line) : "null")
      << ", \"limit_violations\": " << s.limit_violations
      << ", \"limit_violations_travel\": " << by_kind.travel
      << ", \"limit_violations_velocity\": " << by_kind.velocity
      << ", \"limit_violations_acceleration\": " << by_kind.acceleration
      << ", \"lookahead_limited_percent\": " << jsonNumber(lookaheadPercent(s))
      << ", \"lookahead_segments\": " << in.lookahead_segments
      << ", \"final_position\": " << axisObject(in.sim.final_commanded, program) << "}\n";
}

}  // namespace ncc::cli
