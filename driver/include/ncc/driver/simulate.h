#pragma once
// `ncc run`'s simulation: the program through the VM's planner, interpolator and servo model
// (vm::Controller), tick by tick, optionally writing a trace.
#include <cstdint>
#include <optional>
#include <string>

#include "ncc/bytecode/program.h"
#include "ncc/driver/trace.h"
#include "ncc/machine/machine_config.h"
#include "ncc/vm/controller_stats.h"
#include "ncc/vm/events.h"

namespace ncc::driver {

struct SimulationResult {
  vm::RunStatistics statistics;
  std::optional<vm::Alarm> alarm;  // the alarm that stopped the run
  AxisValues final_commanded{};    // the last setpoint
  std::string error;               // the program could not be loaded into the controller
};

// Runs `program` to its end (or an alarm, or `max_steps` VM instructions: 0 = no limit).
SimulationResult simulate(const bytecode::Program& program, const MachineConfig& machine,
                          TraceWriter* trace, uint64_t max_steps);

}  // namespace ncc::driver
