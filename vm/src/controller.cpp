#include "ncc/vm/controller.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "ncc/bytecode/loader.h"
#include "ncc/bytecode/verifier.h"
#include "ncc/vm/machine_check.h"
#include "ncc/vm/run_limits.h"

namespace ncc::vm {
namespace {

// Capacity reserved for the alarm strings, so that raising an alarm inside tick() does not
// allocate; longer executor messages are cut to it.
constexpr std::size_t kAlarmCodeCapacity = 32;
constexpr std::size_t kAlarmMessageCapacity = 256;

// Copies `from` into `to` without growing it past its reserved capacity.
void assignBounded(std::string& to, const std::string& from) {
  to.assign(from.data(), std::min(from.size(), to.capacity()));
}

// `to = from`, field by field. As one struct copy GCC emits rep movsq plus an 8-byte load
// overlapping the status byte tick() has just stored, which stalls store forwarding: a
// tenth of a simple tick. The structured binding names every member of TickOutput, so a
// field added there does not compile here until it is copied too.
void copyTick(const TickOutput& from, TickOutput& to) {
  const auto& [tick, time, commanded, actual, following_error, path_velocity, where, file,
               status] = from;
  to.tick = tick;
  to.time = time;
  to.commanded = commanded;
  to.actual = actual;
  to.following_error = following_error;
  to.path_velocity = path_velocity;
  to.where = where;
  to.file = file;
  to.status = status;
}

}  // namespace

std::unique_ptr<Controller> Controller::load(std::span<const uint8_t> bytes,
                                             const MachineConfig& machine,
                                             bytecode::Error& error,
                                             const ControllerOptions& options) {
  bytecode::Program program;
  if (std::optional<bytecode::Error> e = bytecode::load(bytes, program)) {
    error = std::move(*e);
    return nullptr;
  }
  return create(std::move(program), machine, error, options);
}

std::unique_ptr<Controller> Controller::loadFile(const std::filesystem::path& path,
                                                 const MachineConfig& machine,
                                                 bytecode::Error& error,
                                                 const ControllerOptions& options) {
  bytecode::Program program;
  if (std::optional<bytecode::Error> e = bytecode::loadFile(path, program)) {
    error = std::move(*e);
    return nullptr;
  }
  return create(std::move(program), machine, error, options);
}

namespace {

// What create() and createBorrowing() ask before a controller runs `program`: verified code
// for this machine, and a sane machine. False with `error` set otherwise.
bool readyToRun(const bytecode::Program& program, const MachineConfig& machine,
                bytecode::Error& error) {
  bytecode::VerifyOptions verify_options;
  verify_options.machine = &machine;
  std::optional<bytecode::Error> e = bytecode::verify(program, verify_options);
  if (!e) e = checkMachine(machine);
  if (e) error = std::move(*e);
  return !e;
}

}  // namespace

std::unique_ptr<Controller> Controller::create(bytecode::Program program,
                                               const MachineConfig& machine,
                                               bytecode::Error& error,
                                               const ControllerOptions& options) {
  if (!readyToRun(program, machine, error)) return nullptr;
  return std::make_unique<Controller>(std::move(program), machine, options);
}

std::unique_ptr<Controller> Controller::createBorrowing(const bytecode::Program& program,
                                                        const MachineConfig& machine,
                                                        bytecode::Error& error,
                                                        const ControllerOptions& options) {
  if (!readyToRun(program, machine, error)) return nullptr;
  // The constructor is private: make_unique cannot reach it.
  return std::unique_ptr<Controller>(new Controller(nullptr, &program, machine, options));
}

Controller::Controller(bytecode::Program program, const MachineConfig& machine,
                       const ControllerOptions& options)
    : Controller(std::make_unique<const bytecode::Program>(std::move(program)), nullptr, machine,
                 options) {}

Controller::Controller(std::unique_ptr<const bytecode::Program> owned,
                       const bytecode::Program* borrowed, const MachineConfig& machine,
                       const ControllerOptions& options)
    : machine_(machine),
      owned_program_(std::move(owned)),
      program_(owned_program_ ? *owned_program_ : *borrowed),
      options_(options),
      executor_(program_, machine_),
      planner_(machine_, options.window_capacity != 0
                             ? options.window_capacity
                             // The machine file's range, also for a MachineConfig built in code.
                             : static_cast<std::size_t>(std::clamp(
                                   machine_.lookahead_segments, MachineConfig::kMinLookaheadSegments,
                                   MachineConfig::kMaxLookaheadSegments))),
      servo_(machine_),
      stats_(machine_.axisCount()) {
  executor_.setStepLimit(options_.step_limit);
  if (options_.max_seconds > 0.0 && machine_.ipo_cycle_seconds > 0.0) {
    // The first tick at or after the limit; beyond 2^63 ticks there is no limit to enforce.
    const double ticks = std::ceil(options_.max_seconds / machine_.ipo_cycle_seconds);
    max_ticks_ = ticks < 9.2e18 ? static_cast<uint64_t>(ticks) : 0;
  }
  planner_.setOverrides(options_.feed_override, options_.rapid_override,
                        options_.max_feed_override);
  servo_.reset(machine_.start_position);
  last_.commanded = machine_.start_position;
  last_.actual = machine_.start_position;
  alarm_.code.reserve(kAlarmCodeCapacity);
  alarm_.message.reserve(kAlarmMessageCapacity);
}

std::string_view Controller::fileName(uint32_t file) const {
  return file < program_.strings.size() ? std::string_view(program_.strings[file])
                                        : std::string_view();
}

void Controller::prepare() noexcept {
  if (status_ != TickStatus::Running) return;
  // The operator's requests first, at this fixed point of the cycle: the same calls between
  // the same ticks re-plan the same queue in either loop.
  if (pending_feed_hold_) planner_.setFeedHold(*pending_feed_hold_);
  if (pending_feed_override_) planner_.setFeedOverride(*pending_feed_override_);
  if (pending_rapid_override_) planner_.setRapidOverride(*pending_rapid_override_);
  pending_feed_hold_.reset();
  pending_feed_override_.reset();
  pending_rapid_override_.reset();
  pullEvents();
  planner_.planAhead();
}

double Controller::feedOverride() const {
  if (!pending_feed_override_) return planner_.feedOverride();
  return planner_.feedOverrideWithin(*pending_feed_override_);
}

// Feeds the planner while it wants more: motion, S (feed per revolution, dwell in
// revolutions), M00/M01/M02/M30 (stops) all go through MotionPlanner::accept().
void Controller::pullEvents() {
  uint32_t budget = options_.max_events_per_tick;  // 0: unlimited
  executor_.setClock(static_cast<double>(next_tick_) * machine_.ipo_cycle_seconds);
  while (!input_done_ && planner_.canAccept()) {
    if (!event_pending_) {
      if (options_.max_events_per_tick != 0 && budget-- == 0) return;
      if (!executor_.next(event_)) {  // end of program, or an alarm (kept until reached)
        input_done_ = true;
        planner_.endOfProgram();
        return;
      }
      if (!withinTimeLimit(event_)) {  // raised when the queue before it has run
        input_done_ = true;
        planner_.endOfProgram();
        return;
      }
      event_pending_ = true;
    }
    if (!planner_.accept(event_)) return;  // ring full: retried next tick
    event_pending_ = false;
    if (planner_.spindleAlarm()) {  // the planner takes nothing after it
      input_done_ = true;
      return;
    }
    if (options_.observer) options_.observer->onEvent(event_);
  }
}

TickStatus Controller::tick(TickOutput& out) noexcept {
  if (status_ != TickStatus::Running) {
    out = last_;
    return status_;
  }
  if (options_.prepare_in_tick) prepare();

  const uint64_t k = next_tick_;
  if (max_ticks_ != 0 && k >= max_ticks_) {
    raiseTimeLimitAlarm(last_.where, 0.0);
    last_.status = status_;
    out = last_;
    return status_;
  }
  AxisValues setpoint{};
  motion::SetpointInfo info;
  if (waiting_in_position_) {
    setpoint = last_.commanded;
    info = held_info_;
  } else if (!planner_.setpoint(k, setpoint, info)) {
    // Everything queued has run: the program's end, or the block that raised an alarm.
    if (late_block_) {
      raiseTimeLimitAlarm(*late_block_, least_seconds_);
    } else if (executor_.alarm()) {
      raiseExecutorAlarm();
    } else if (planner_.spindleAlarm()) {
      raiseSpindleAlarm();
    } else {
      status_ = TickStatus::Finished;
    }
    last_.status = status_;
    out = last_;
    return status_;
  }

  const ServoSample& sample = servo_.step(setpoint);
  ++next_tick_;
  last_.tick = k;
  last_.time = static_cast<double>(k) * machine_.ipo_cycle_seconds;
  last_.commanded = setpoint;
  last_.actual = sample.actual;
  last_.following_error = sample.following_error;
  last_.path_velocity = info.velocity;
  last_.where = info.where;
  last_.file = fileName(info.where.file);
  if (info.lookahead_limited) ++lookahead_limited_ticks_;
  stats_.add(k, last_.time, setpoint, sample.actual, sample.following_error,
             !info.idle && info.kind == MotionPrimitive::Kind::Rapid, info.velocity, info.where);
  if (servo_.alarm().code != 0) raiseServoAlarm(servo_.alarm(), info.where);
  if (info.in_position_check && !waiting_in_position_) {
    waiting_in_position_ = true;
    wait_start_ = k;
    held_info_ = info;
    held_info_.in_position_check = false;
    held_info_.segments_finished = 0;
  }
  if (waiting_in_position_ && status_ == TickStatus::Running)
    waiting_in_position_ = !inPosition(sample.position_error, k);

  last_.status = status_;
  copyTick(last_, out);
  return status_;
}

void Controller::raiseExecutorAlarm() {
  const Alarm& from = *executor_.alarm();
  assignBounded(alarm_.code, from.code);
  assignBounded(alarm_.message, from.message);
  alarm_.where = from.where;
  has_alarm_ = true;
  status_ = TickStatus::Alarm;
}

bool Controller::inPosition(const AxisValues& position_error, uint64_t tick) {
  int worst = -1;
  double worst_error = 0.0;
  for (int i = 0; i < machine_.axisCount(); ++i) {
    const double error = std::abs(position_error[i]);
    if (error > machine_.axes[static_cast<std::size_t>(i)].servo.stop_limit_fine &&
        error > worst_error) {
      worst = i;
      worst_error = error;
    }
  }
  if (worst < 0) return true;
  const double waited = static_cast<double>(tick - wait_start_) * machine_.ipo_cycle_seconds;
  if (waited > machine_.axes[static_cast<std::size_t>(worst)].servo.positioning_time)
    raisePositioningAlarm(worst, worst_error, held_info_.where);
  return false;
}

void Controller::raisePositioningAlarm(int axis, double error, SourcePosition where) {
  const AxisConfig& a = machine_.axes[static_cast<std::size_t>(axis)];
  char message[kAlarmMessageCapacity];
  std::snprintf(message, sizeof message,
                "positioning monitoring: axis %.14s is %.6f mm from its end point, outside "
                "STOP_LIMIT_FINE %.6f mm after POSITIONING_TIME %.3f s",
                a.name.c_str(), error, a.servo.stop_limit_fine, a.servo.positioning_time);
  alarm_.code.assign("25080");
  alarm_.message.assign(message);
  alarm_.where = where;
  has_alarm_ = true;
  status_ = TickStatus::Alarm;
}

bool Controller::withinTimeLimit(const Event& event) {
  if (event.kind != Event::Kind::Motion) {
    if (event.machine.kind == MachineEvent::Kind::SpindleSpeed) spindle_rpm_ = event.machine.value;
    return true;
  }
  if (options_.max_seconds <= 0.0) return true;
  least_seconds_ += minimumSeconds(event.motion, machine_,
                                   std::max(options_.feed_override, options_.max_feed_override),
                                   spindle_rpm_);
  if (least_seconds_ <= options_.max_seconds) return true;
  late_block_ = event.motion.where;
  return false;
}

void Controller::raiseTimeLimitAlarm(SourcePosition where, double needed) {
  char message[kAlarmMessageCapacity];
  if (needed > 0.0) {
    std::snprintf(message, sizeof message,
                  "simulated time limit %.17g s reached: the run needs at least %.6g s by the "
                  "end of this block (at the machine's top speed)",
                  options_.max_seconds, needed);
  } else {
    std::snprintf(message, sizeof message,
                  "simulated time limit %.17g s reached in this block (tick %llu)",
                  options_.max_seconds, static_cast<unsigned long long>(next_tick_));
  }
  alarm_.code.assign("NCC7208");
  alarm_.message.assign(message);
  alarm_.where = where;
  has_alarm_ = true;
  status_ = TickStatus::Alarm;
}

void Controller::raiseSpindleAlarm() {
  alarm_.code.assign("NCC7207");
  alarm_.message.assign(
      "feed per revolution with the spindle stopped: S is 0 (or not given) or M05 is active");
  alarm_.where = planner_.spindleAlarmWhere();
  has_alarm_ = true;
  status_ = TickStatus::Alarm;
}

void Controller::raiseServoAlarm(const ServoAlarm& a, SourcePosition where) {
  const AxisConfig& axis = machine_.axes[static_cast<std::size_t>(a.axis)];
  const bool contour = a.code == kAlarmContour;
  const double limit = contour ? axis.servo.contour_tol : axis.servo.standstill_pos_tol;
  // snprintf into fixed buffers, then copies within the reserved capacity: no allocation.
  char code[kAlarmCodeCapacity];
  char message[kAlarmMessageCapacity];
  std::snprintf(code, sizeof code, "%d", a.code);
  std::snprintf(message, sizeof message,
                "%s monitoring: axis %.14s following error %.6f mm exceeds %s %.6f mm at tick "
                "%lld",
                contour ? "contour" : "standstill", axis.name.c_str(), a.value,
                contour ? "CONTOUR_TOL" : "STANDSTILL_POS_TOL", limit,
                static_cast<long long>(a.tick));
  alarm_.code.assign(code);
  alarm_.message.assign(message);
  alarm_.where = where;
  has_alarm_ = true;
  status_ = TickStatus::Alarm;
}

RunStatistics Controller::statistics() const {
  RunStatistics s = stats_.statistics();
  s.lookahead_limited_ticks = lookahead_limited_ticks_;
  s.limit_violations = 0;
  for (int i = 0; i < servo_.axisCount(); ++i) {
    s.violations[i] = servo_.violations(i);
    s.limit_violations += s.violations[i].travel + s.violations[i].velocity +
                          s.violations[i].acceleration;
  }
  return s;
}

}  // namespace ncc::vm
