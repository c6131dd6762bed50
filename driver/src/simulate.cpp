#include "ncc/driver/simulate.h"

#include "absl/strings/str_cat.h"
#include "ncc/vm/controller.h"

namespace ncc::driver {

SimulationResult simulate(const bytecode::Program& program, const MachineConfig& machine,
                          TraceWriter* trace, const SimulationOptions& settings) {
  SimulationResult result;
  vm::ControllerOptions options;
  options.step_limit = settings.max_steps;
  options.feed_override = settings.feed_override;
  options.rapid_override = settings.rapid_override;
  bytecode::Error error;
  std::unique_ptr<vm::Controller> controller = vm::Controller::create(program, machine, error, options);
  if (!controller) {
    result.error = absl::StrCat(error.code, ": ", error.message);
    return result;
  }
  vm::TickOutput tick;
  uint64_t written = 0;  // ticks in the trace so far
  vm::TickStatus status;
  while ((status = controller->tick(tick)) == vm::TickStatus::Running) {
    if (trace) trace->sample(tick.tick, tick.commanded, tick.actual);
    ++written;
  }
  result.statistics = controller->statistics();
  // A servo alarm comes with the new tick that tripped it (an executor alarm or the end repeats
  // the last one): that tick belongs in the trace too.
  if (trace && status == vm::TickStatus::Alarm && tick.tick == written &&
      result.statistics.ticks > written) {
    trace->sample(tick.tick, tick.commanded, tick.actual);
  }
  if (trace) trace->finish();
  result.final_commanded = tick.commanded;
  if (const vm::Alarm* alarm = controller->alarm()) result.alarm = *alarm;
  return result;
}

}  // namespace ncc::driver
