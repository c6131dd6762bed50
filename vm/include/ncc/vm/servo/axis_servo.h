#pragma once
// One axis of the servo model (docs/servo.md): pitch-error and backlash compensation of the
// setpoint, a position controller with gain Kv and feed-forward, the closed speed loop as a
// first-order lag, and the mechanics (leadscrew pitch error, backlash) between the motor and
// the table. Discrete at the IPO cycle T; the speed loop is integrated exactly for a speed
// setpoint held over the cycle, so the model is stable and exact for any T.
#include "ncc/machine/machine_config.h"
#include "ncc/vm/servo/backlash.h"

namespace ncc::vm {

struct AxisServoOutput {
  double actual = 0.0;           // table position, machine coordinates
  double following_error = 0.0;  // compensated setpoint - motor position (encoder)
  double velocity = 0.0;         // motor speed, mm/s (deg/s)
  double acceleration = 0.0;     // change of the motor speed over the last cycle, mm/s^2
};

class AxisServo {
 public:
  AxisServo() = default;
  AxisServo(const AxisConfig& axis, double cycle_seconds);

  // At rest at `position`: the following error is 0, the table is where the mechanics put it.
  void reset(double position);
  // One IPO cycle: `setpoint` is the position for the end of the cycle; `out` is the sample
  // there.
  void step(double setpoint, AxisServoOutput& out);

 private:
  // Parameters (constant after construction).
  PitchTable pitch_error_;         // copies: allocated at construction only
  PitchTable pitch_compensation_;
  double cycle_ = 0.001;
  double kv_ = 0.0;            // 1/s
  double velocity_ffw_ = 0.0;  // weight of d(command)/dt in the speed setpoint
  double torque_ffw_ = 0.0;    // weight of T_eq * d2(command)/dt2
  double t_eq_ = 0.0;          // speed loop equivalent time constant, s
  double decay_ = 0.0;         // exp(-T / T_eq): speed loop state after one cycle
  double lag_distance_ = 0.0;  // T_eq * (1 - decay): position lost to the lag per unit step
  MechanicalPlay play_;
  BacklashCompensation backlash_comp_;

  // State.
  double setpoint_ = 0.0;      // last setpoint
  double command_ = 0.0;       // last command without the backlash step (the feed-forward's)
  double target_ = 0.0;        // last command with it: the position loop's setpoint
  double ffw_velocity_ = 0.0;  // last d(command)/dt
  double motor_ = 0.0;         // motor position (encoder), mm
  double speed_ = 0.0;         // motor speed, mm/s
};

}  // namespace ncc::vm
