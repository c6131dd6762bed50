#include "ncc/vm/servo/servo_monitor.h"

#include <algorithm>
#include <cmath>

namespace ncc::vm {

// Relative slack on the velocity and acceleration limits: a setpoint planned exactly at the
// limit must not count as a violation because of rounding.
constexpr double kLimitSlack = 1e-9;

ServoMonitors::ServoMonitors(const MachineConfig& machine, int axis_count)
    : count_(axis_count) {
  const double cycle = machine.ipo_cycle_seconds;
  for (int i = 0; i < count_; ++i) {
    const AxisConfig& axis = machine.axes[i];
    contour_tol_[i] = axis.servo.contour_tol;
    standstill_tol_[i] = axis.servo.standstill_pos_tol;
    standstill_delay_ticks_[i] = std::ceil(axis.servo.standstill_delay_time / cycle);
    min_travel_[i] = axis.min_travel;
    max_travel_[i] = axis.max_travel;
    max_velocity_[i] =
        std::max(axis.rapid_velocity, axis.max_velocity) / 60.0 * (1.0 + kLimitSlack);
    max_acceleration_[i] = axis.max_acceleration * (1.0 + kLimitSlack);
  }
}

void ServoMonitors::reset() {
  still_ticks_ = {};
  code_ = {};
  travel_count_ = {};
  velocity_count_ = {};
  acceleration_count_ = {};
}

void ServoMonitors::check(const ServoAxes& __restrict axes) {
  const AxisLanes& setpoint_delta = axes.setpointDelta();
  const AxisLanes& actual = axes.actual();
  const AxisLanes& velocity = axes.velocity();
  const AxisLanes& acceleration = axes.acceleration();
  const AxisLanes& following_error = axes.followingError();
  // Written as selects, arithmetic and int | and & rather than branches, ||, && (GCC will not
  // if-convert a conditional floating-point add), so that the loop vectorises. A padding lane
  // (all 0) counts nothing and trips nothing.
  const int lanes = laneCount(count_);
  for (int i = 0; i < lanes; ++i) {
    // Limits, counted per sample.
    const bool outside = int{actual[i] < min_travel_[i]} | int{actual[i] > max_travel_[i]};
    travel_count_[i] += outside ? 1.0 : 0.0;
    velocity_count_[i] += std::fabs(velocity[i]) > max_velocity_[i] ? 1.0 : 0.0;
    acceleration_count_[i] += std::fabs(acceleration[i]) > max_acceleration_[i] ? 1.0 : 0.0;

    // Standstill monitoring starts once the setpoint has rested for STANDSTILL_DELAY_TIME;
    // contour monitoring always applies. The rest counter restarts at 0 when it moves.
    const double resting = setpoint_delta[i] == 0.0 ? 1.0 : 0.0;
    const double still = (still_ticks_[i] + 1.0) * resting;
    still_ticks_[i] = still;
    const double abs_error = std::fabs(following_error[i]);
    const double contour = abs_error > contour_tol_[i] ? kAlarmContour : 0.0;
    const bool standstill =
        int{still > standstill_delay_ticks_[i]} & int{abs_error > standstill_tol_[i]};
    code_[i] = standstill ? kAlarmStandstill : contour;
  }
}

}  // namespace ncc::vm
