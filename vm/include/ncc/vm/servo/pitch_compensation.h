#pragma once
// Leadscrew pitch-error tables: the value at a machine position, linearly interpolated between
// equidistant support points and held at the end values outside them (LEC, notes §4.1).
#include "ncc/machine/servo_config.h"

namespace ncc::vm {

// 0 for an empty table. Exact at support points whose offset from `start` is a whole number
// of steps in floating point (e.g. start 0, step 10, position 30).
double pitchValue(const PitchTable& table, double position);

}  // namespace ncc::vm
