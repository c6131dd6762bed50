#include "ncc/driver/run.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "ncc/bytecode/format.h"
#include "ncc/bytecode/loader.h"
#include "ncc/bytecode/verifier.h"
#include "ncc/driver/compile.h"
#include "ncc/vm/executor.h"

namespace ncc::driver {

bool isBytecodeFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  if (in.read(magic, 4) && std::string_view(magic, 4) == "NCCB") return true;
  return absl::EndsWithIgnoreCase(path.string(), ".ncb");
}

bool loadProgram(Session& session, bytecode::Program& program, bool check_machine) {
  std::optional<bytecode::Error> error;
  if (isBytecodeFile(session.input())) {
    error = bytecode::loadFile(session.input(), program);
  } else {
    std::stringstream buffer;
    if (!emitBytecode(session, buffer)) return false;
    std::string bytes = buffer.str();
    error = bytecode::load(
        std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()), program);
  }
  if (!error) {
    bytecode::VerifyOptions options;
    options.machine = &session.machine();
    options.check_config_hash = check_machine;
    error = bytecode::verify(program, options);
  }
  if (error) {
    session.diagnostics().error(error->code, SourceLocation{session.mainFile(), 0, 0},
                                absl::StrCat("invalid bytecode: ", error->message));
    return false;
  }
  return true;
}

namespace {

// Angle swept by an arc from `from` to `to` about `center` on plane axes (a, b), in radians,
// in its direction of travel; equal end points mean a full circle.
double arcSweep(const vm::MotionPrimitive& m) {
  const int a = m.axis1, b = m.axis2;
  double start = std::atan2(m.from[b] - m.center[b], m.from[a] - m.center[a]);
  double end = std::atan2(m.to[b] - m.center[b], m.to[a] - m.center[a]);
  double sweep = m.cw ? start - end : end - start;
  const double two_pi = 2.0 * std::numbers::pi;
  while (sweep <= 1e-12) sweep += two_pi;
  return sweep + two_pi * m.extra_turns;
}

}  // namespace

double motionLength(const vm::MotionPrimitive& m, int axis_count) {
  if (m.kind == vm::MotionPrimitive::Kind::Dwell) return 0.0;
  if (m.kind == vm::MotionPrimitive::Kind::Arc) {
    const int a = m.axis1, b = m.axis2;
    double radius = std::hypot(m.from[a] - m.center[a], m.from[b] - m.center[b]);
    double planar = radius * arcSweep(m);
    double other = 0.0;  // helical: the axes outside the plane move linearly
    for (int i = 0; i < axis_count; ++i)
      if (i != a && i != b) other += (m.to[i] - m.from[i]) * (m.to[i] - m.from[i]);
    return std::sqrt(planar * planar + other);
  }
  double sum = 0.0;
  for (int i = 0; i < axis_count; ++i) sum += (m.to[i] - m.from[i]) * (m.to[i] - m.from[i]);
  return std::sqrt(sum);
}

namespace {

double rapidSeconds(const vm::MotionPrimitive& m, const MachineConfig& machine) {
  double seconds = 0.0;
  for (int i = 0; i < machine.axisCount(); ++i) {
    double speed = machine.axes[i].rapid_velocity / 60.0;  // per second
    if (speed > 0.0) seconds = std::max(seconds, std::fabs(m.to[i] - m.from[i]) / speed);
  }
  return seconds;
}

void account(RunSummary& s, const vm::MotionPrimitive& m, const MachineConfig& machine,
             double spindle_rpm) {
  double length = motionLength(m, machine.axisCount());
  switch (m.kind) {
    case vm::MotionPrimitive::Kind::Rapid:
      ++s.rapids;
      s.rapid_length += length;
      s.estimated_seconds += rapidSeconds(m, machine);
      break;
    case vm::MotionPrimitive::Kind::Line:
    case vm::MotionPrimitive::Kind::Arc: {
      (m.kind == vm::MotionPrimitive::Kind::Line ? s.lines : s.arcs) += 1;
      s.cutting_length += length;
      double per_minute = m.feed_per_rev ? m.feed * spindle_rpm : m.feed;
      if (per_minute > 0.0) s.estimated_seconds += length / per_minute * 60.0;
      break;
    }
    case vm::MotionPrimitive::Kind::Dwell:
      ++s.dwells;
      if (!m.revolutions) s.estimated_seconds += m.seconds;
      else if (spindle_rpm > 0.0) s.estimated_seconds += m.seconds / spindle_rpm * 60.0;
      break;
  }
  s.final_position = m.to;
}

}  // namespace

RunResult runProgram(const bytecode::Program& program, const MachineConfig& machine,
                     const EventHandler& on_event, uint64_t max_steps) {
  RunResult result;
  result.summary.final_position = machine.start_position;
  vm::Executor executor(program, machine);
  executor.setStepLimit(max_steps);
  vm::Event event;
  double spindle_rpm = 0.0;
  while (executor.next(event)) {
    if (event.kind == vm::Event::Kind::Motion) {
      account(result.summary, event.motion, machine, spindle_rpm);
    } else {
      ++result.summary.machine_events;
      if (event.machine.kind == vm::MachineEvent::Kind::SpindleSpeed) spindle_rpm = event.machine.value;
    }
    if (on_event) on_event(event);
  }
  result.alarm = executor.alarm();
  result.variables = executor.variables();
  return result;
}

}  // namespace ncc::driver
