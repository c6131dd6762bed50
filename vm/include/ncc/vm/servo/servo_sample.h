#pragma once
// What the servo model reports for one IPO cycle, per axis.
#include <cstdint>

#include "ncc/machine/machine_config.h"

namespace ncc::vm {

struct ServoSample {
  int64_t tick = 0;              // ticks since reset
  AxisValues setpoint{};         // what step() was given
  AxisValues actual{};           // table positions
  AxisValues following_error{};  // position controller error per axis, mm
  // Compensated setpoint (not delayed) minus encoder, mm: how far the axis is from where the
  // control wants it; exact stop fine (STOP_LIMIT_FINE) compares this.
  AxisValues position_error{};
  AxisValues velocity{};         // motor speed, mm/s (deg/s)
  AxisValues acceleration{};     // mm/s^2 (deg/s^2)
};

}  // namespace ncc::vm
