#pragma once
// A run always ends: the simulated-time limit of vm::Controller (ControllerOptions::
// max_seconds, `ncc run --max-time`). Two checks, both alarm NCC7208 naming the block:
// - the clock: the tick at the limit stops the run in the block being interpolated;
// - the look-ahead: a block that cannot end before the limit even at the machine's top speed
//   (a G04 of 1e300 s, an arc of a million turns) stops the run as soon as the moves before it
//   have run, instead of simulating for hours of wall time first.
#include "ncc/machine/machine_config.h"
#include "ncc/vm/events.h"

namespace ncc::vm {

// The default of `ncc run --max-time`: 100 hours of simulated time, which no real program
// reaches (and about 100 s of wall time to simulate).
inline constexpr double kDefaultMaxRunSeconds = 100.0 * 3600.0;

// A lower bound of the time `motion` takes on `machine`, s: a dwell its seconds (0 in spindle
// revolutions), a move its path length at the fastest it can go: the programmed feed (mm/min)
// times `max_feed_override` for a line or arc in feed per minute, in feed per revolution the
// feed times `spindle_rpm` (the S in force; 0: unknown) times the override, and never more than
// the fastest any axis combination can go (topPathSpeed). An arc's length is taken at its
// smaller radius. O(1), no allocation.
double minimumSeconds(const MotionPrimitive& motion, const MachineConfig& machine,
                      double max_feed_override, double spindle_rpm = 0.0);

// The fastest path speed of `machine`, mm/s: the Euclidean sum of every axis' larger of
// rapid_velocity and max_velocity.
double topPathSpeed(const MachineConfig& machine);

}  // namespace ncc::vm
