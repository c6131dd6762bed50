#pragma once
// Axis monitoring of the servo model (notes §4.1; Sinumerik A3): following-error ("contour")
// monitoring, standstill monitoring, and counts of limit violations of the actual motion.
#include <array>
#include <bit>
#include <cstdint>

#include "ncc/machine/machine_config.h"
#include "ncc/vm/servo/axis_lanes.h"
#include "ncc/vm/servo/servo_axes.h"

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

// The monitoring of all axes, stored by quantity like ServoAxes (one array per limit or state,
// indexed by axis, in lanes: axis_lanes.h) so that check() is a loop the compiler vectorises.
// Counts and alarm codes are kept as doubles for that (SSE2 compares doubles into double-wide
// masks); they are whole numbers, exact far beyond any run's length (2^53 ticks).
class ServoMonitors {
 public:
  ServoMonitors() = default;
  // The first `axis_count` axes of `machine` (at most kMaxAxes).
  ServoMonitors(const MachineConfig& machine, int axis_count);
  // Clears the counts and the standstill timers.
  void reset();

  // The last step() of `axes`: counts limit violations and sets alarmCode(axis) to the alarm
  // it trips there (0: none). (`axes` does not overlap this object: __restrict spares the
  // vectorised loop run-time overlap checks.)
  void check(const ServoAxes& __restrict axes);
  int alarmCode(int axis) const { return static_cast<int>(code_[axis]); }
  // Whether any axis tripped an alarm in the last check(). Over every lane (a fixed count; the
  // padding lanes are 0), as an OR of the codes' bits: a code is +0.0 or a positive number,
  // so its bits are 0 exactly when it is none. Integer ORs vectorise; the comparisons of
  // doubles were ten scalar compares, 2 % of a simulation's time.
  bool anyAlarm() const {
    std::uint64_t any = 0;
    for (int i = 0; i < kAxisLanes; ++i) any |= std::bit_cast<std::uint64_t>(code_[i]);
    return any != 0;
  }
  LimitViolations violations(int axis) const {
    return {static_cast<int64_t>(travel_count_[axis]),
            static_cast<int64_t>(velocity_count_[axis]),
            static_cast<int64_t>(acceleration_count_[axis])};
  }

 private:
  using Values = AxisLanes;

  int count_ = 0;
  Values contour_tol_{};
  Values standstill_tol_{};
  Values standstill_delay_ticks_{};
  Values min_travel_{}, max_travel_{};
  Values max_velocity_{};      // mm/s
  Values max_acceleration_{};  // mm/s^2

  Values still_ticks_{};  // ticks the setpoint has not moved
  Values code_{};         // alarm of the last check per axis, 0: none
  Values travel_count_{}, velocity_count_{}, acceleration_count_{};
};

}  // namespace ncc::vm
