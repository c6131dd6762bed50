#include "ncc/vm/servo/servo_monitor.h"

#include <algorithm>
#include <cmath>

namespace ncc::vm {

// Relative slack on the velocity and acceleration limits: a setpoint planned exactly at the
// limit must not count as a violation because of rounding.
constexpr double kLimitSlack = 1e-9;

AxisMonitor::AxisMonitor(const AxisConfig& axis, double cycle_seconds)
    : contour_tol_(axis.servo.contour_tol),
      standstill_tol_(axis.servo.standstill_pos_tol),
      standstill_delay_ticks_(
          static_cast<int64_t>(std::ceil(axis.servo.standstill_delay_time / cycle_seconds))),
      min_travel_(axis.min_travel),
      max_travel_(axis.max_travel),
      max_velocity_(std::max(axis.rapid_velocity, axis.max_velocity) / 60.0 * (1.0 + kLimitSlack)),
      max_acceleration_(axis.max_acceleration * (1.0 + kLimitSlack)) {}

int AxisMonitor::check(double setpoint_delta, double actual, double following_error,
                       double velocity, double acceleration, LimitViolations& violations) {
  if (actual < min_travel_ || actual > max_travel_) ++violations.travel;
  if (std::fabs(velocity) > max_velocity_) ++violations.velocity;
  if (std::fabs(acceleration) > max_acceleration_) ++violations.acceleration;

  const double abs_error = std::fabs(following_error);
  still_ticks_ = setpoint_delta == 0.0 ? still_ticks_ + 1 : 0;
  // Standstill monitoring starts once the setpoint has rested for STANDSTILL_DELAY_TIME.
  if (still_ticks_ > standstill_delay_ticks_ && abs_error > standstill_tol_)
    return kAlarmStandstill;
  if (abs_error > contour_tol_) return kAlarmContour;
  return 0;
}

}  // namespace ncc::vm
