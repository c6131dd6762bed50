#pragma once
// What the VM needs of a machine configuration before it runs a program on it.
//
// A machine file is checked as it is read (machine_file.h), but an embedder may build a
// MachineConfig in code: a zero interpolation cycle or a zero acceleration there would turn
// every setpoint into NaN or stop the planner forever. Controller::create() refuses such a
// configuration with NCC7115 instead.
#include <optional>

#include "ncc/bytecode/error.h"
#include "ncc/machine/machine_config.h"

namespace ncc::vm {

// The first value the VM cannot run with (finite, and within the machine file's ranges for
// the interpolation cycle, the tolerances, the axis limits and every servo parameter; finite
// pitch tables and start position), as an NCC7115 error naming it; nullopt when all are fine.
std::optional<bytecode::Error> checkMachine(const MachineConfig& machine);

}  // namespace ncc::vm
