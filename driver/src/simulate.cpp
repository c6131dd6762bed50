#include "ncc/driver/simulate.h"

#include <algorithm>

#include "absl/strings/str_cat.h"
#include "ncc/vm/controller.h"

namespace ncc::driver {

SimulationResult simulate(const bytecode::Program& program, const MachineConfig& machine,
                          TraceWriter* trace, const SimulationOptions& settings) {
  SimulationResult result;
  vm::ControllerOptions options;
  options.step_limit = settings.max_steps;
  options.max_seconds = settings.max_seconds;
  options.feed_override = settings.feed_override;
  options.rapid_override = settings.rapid_override;
  options.max_feed_override = settings.feed_override;
  options.observer = settings.observer;
  for (const FeedOverrideTurn& turn : settings.feed_override_turns)
    options.max_feed_override = std::max(options.max_feed_override, turn.feed);
  bytecode::Error error;
  std::unique_ptr<vm::Controller> controller =
      vm::Controller::createBorrowing(program, machine, error, options);  // no copy of the code
  if (!controller) {
    result.error = absl::StrCat(error.code, ": ", error.message);
    return result;
  }
  vm::TickOutput tick;
  uint64_t written = 0;  // ticks in the trace so far
  vm::TickStatus status;
  // The knob turns and feed holds due by the next tick's time (ticks_taken * T), in order.
  std::size_t next_turn = 0, next_rapid_turn = 0, next_hold = 0;
  bool holding = false;
  uint64_t ticks_taken = 0;
  const std::vector<FeedOverrideTurn>& turns = settings.feed_override_turns;
  const std::vector<RapidOverrideTurn>& rapid_turns = settings.rapid_override_turns;
  const std::vector<FeedHoldSpan>& holds = settings.feed_holds;
  for (;;) {
    const double now = static_cast<double>(ticks_taken++) * controller->cycleSeconds();
    while (next_turn < turns.size() && turns[next_turn].seconds <= now)
      controller->setFeedOverride(turns[next_turn++].feed);
    while (next_rapid_turn < rapid_turns.size() && rapid_turns[next_rapid_turn].seconds <= now)
      controller->setRapidOverride(rapid_turns[next_rapid_turn++].rapid);
    while (next_hold < holds.size()) {
      const FeedHoldSpan& hold = holds[next_hold];
      if (!holding && hold.seconds <= now) {
        controller->setFeedHold(holding = true);
      } else if (holding && hold.seconds + hold.duration <= now) {
        controller->setFeedHold(holding = false);
        ++next_hold;
      } else {
        break;
      }
    }
    status = controller->tick(tick);
    if (status != vm::TickStatus::Running) break;
    if (trace) trace->sample(tick.tick, tick.commanded, tick.actual, tick.where.line);
    ++written;
    if (settings.progress && written % kProgressTicks == 0) settings.progress(tick);
  }
  result.statistics = controller->statistics();
  // A servo alarm comes with the new tick that tripped it (an executor alarm or the end repeats
  // the last one): that tick belongs in the trace too.
  if (trace && status == vm::TickStatus::Alarm && tick.tick == written &&
      result.statistics.ticks > written) {
    trace->sample(tick.tick, tick.commanded, tick.actual, tick.where.line);
  }
  if (trace) trace->finish();
  result.final_commanded = tick.commanded;
  if (const vm::Alarm* alarm = controller->alarm()) result.alarm = *alarm;
  result.variables = controller->variables();
  return result;
}

}  // namespace ncc::driver
