#pragma once
// Axis monitoring of the servo model (notes §4.1; Sinumerik A3): following-error ("contour")
// monitoring, standstill monitoring, and counts of limit violations of the actual motion.
#include <cstdint>

#include "ncc/machine/machine_config.h"

namespace ncc::vm {

// Sinumerik alarm numbers.
inline constexpr int kAlarmStandstill = 25040;  // standstill monitoring
inline constexpr int kAlarmContour = 25050;     // contour (following-error) monitoring

// The first alarm since reset; code 0: none.
struct ServoAlarm {
  int code = 0;
  int axis = -1;        // index in MachineConfig::axes
  int64_t tick = 0;     // ticks since reset (the first step is tick 0)
  double value = 0.0;   // the following error that tripped it, mm
};

// Samples of the actual motion over the axis's limits (a sample is counted once per limit).
struct LimitViolations {
  int64_t travel = 0;        // table outside [min_travel, max_travel]
  int64_t velocity = 0;      // motor speed above max(rapid_velocity, max_velocity)
  int64_t acceleration = 0;  // motor acceleration above max_acceleration
  friend bool operator==(const LimitViolations&, const LimitViolations&) = default;
};

class AxisMonitor {
 public:
  AxisMonitor() = default;
  AxisMonitor(const AxisConfig& axis, double cycle_seconds);
  void reset() { still_ticks_ = 0; }

  // Returns the alarm code this sample trips (0: none) and counts limit violations.
  int check(double setpoint_delta, double actual, double following_error, double velocity,
            double acceleration, LimitViolations& violations);

 private:
  double contour_tol_ = 1.0;
  double standstill_tol_ = 0.2;
  int64_t standstill_delay_ticks_ = 0;
  double min_travel_ = 0.0, max_travel_ = 0.0;
  double max_velocity_ = 0.0;      // mm/s
  double max_acceleration_ = 0.0;  // mm/s^2
  int64_t still_ticks_ = 0;        // ticks the setpoint has not moved
};

}  // namespace ncc::vm
