#pragma once
// The servo loops of all axes (docs/servo.md, "Model"): per axis the control's pitch-error and
// backlash compensation of the setpoint, a position controller with gain Kv and feed-forward
// (with velocity feed-forward the position setpoint is first delayed by the speed loop's lag,
// as on the Sinumerik), the closed speed loop as a first-order lag, and the mechanics
// (leadscrew pitch error, backlash) between the motor and the table. Discrete at the IPO cycle
// T; the lags are integrated exactly for a speed held over the cycle, so the model is stable
// and exact for any T.
//
// Stored by quantity (one array per parameter or state, indexed by axis, padded to an even
// number of lanes: axis_lanes.h) and stepped one stage at a time over all axes: the axes are
// independent, so each stage is a loop the compiler vectorises and the CPU overlaps, instead
// of one long chain of divisions per axis. The arithmetic of every axis is the same,
// operation for operation, whatever the layout.
#include <array>

#include "ncc/machine/machine_config.h"
#include "ncc/vm/servo/axis_lanes.h"
#include "ncc/vm/servo/pitch_compensation.h"
#include "ncc/vm/servo/servo_sample.h"

namespace ncc::vm {

class ServoAxes {
 public:
  ServoAxes() = default;
  // The first `axis_count` axes of `machine` (at most kMaxAxes). Allocates here only.
  ServoAxes(const MachineConfig& machine, int axis_count);

  // At rest at `position`: the following error is 0, the table is where the mechanics put it.
  void reset(const AxisValues& position);
  // One IPO cycle: `setpoint` is the position for the end of the cycle; writes the setpoint,
  // actual, following error, velocity and acceleration of the sample there. (Neither argument
  // overlaps this object: __restrict spares the vectorised loops run-time overlap checks.)
  void step(const AxisValues& __restrict setpoint, ServoSample& __restrict out);
  // The last step()'s quantities by lane (those of the sample, for the monitoring), and each
  // axis's setpoint change in it.
  const AxisLanes& setpointDelta() const { return setpoint_delta_; }
  const AxisLanes& actual() const { return actual_; }
  const AxisLanes& followingError() const { return following_error_; }
  const AxisLanes& velocity() const { return speed_; }
  const AxisLanes& acceleration() const { return acceleration_; }

 private:
  using Values = AxisLanes;
  using Flags = AxisLanes;  // 0 or 1 as doubles: selects on them vectorise

  int count_ = 0;
  double cycle_ = 0.001;  // T, s
  double rate_ = 1000.0;  // 1/T, 1/s: differences per cycle become per second by a product

  // Parameters (constant after construction).
  Values kv_{};            // 1/s
  Values velocity_ffw_{};  // weight of d(command)/dt in the speed setpoint
  Values torque_ffw_{};    // weight of d2(command)/dt2: T_eq with torque feed-forward
  Values decay_{};         // speed loop: exp(-T / T_eq)
  Values lag_distance_{};  // speed loop: T_eq (1 - decay)
  Flags symmetrise_{};     // delay the position setpoint by the speed loop's lag
  Values backlash_half_{};  // MD 32450 / 2
  Values play_half_{};     // |mechanical play| / 2
  Values play_sign_{};     // +1: encoder ahead of the table, -1: behind
  // The tables, and their values at the last lookup (0 without a table): compensation at the
  // setpoint, error at the motor position.
  PitchTables compensation_tables_;  // the control's LEC
  PitchTables pitch_error_tables_;   // the simulated leadscrew's error

  // State.
  Values setpoint_{};           // last setpoint
  Values setpoint_delta_{};     // its change in the last cycle
  Values backlash_{};           // backlash compensation now: +-half or 0
  Values command_{};            // last command without the backlash step (the feed-forward's)
  Values target_{};             // position controller's setpoint: the (symmetrised) command
                                // plus the backlash step
  Values ffw_velocity_{};       // last d(command)/dt
  Values reference_{};          // symmetrisation: the command through the speed loop's lag
  Values reference_speed_{};
  Values motor_{};              // motor position (encoder)
  Values speed_{};              // motor speed
  Values last_speed_{};         // motor speed at the cycle's start
  Values play_lag_{};           // nut - table (for positive play), within +-play_half
  Values last_nut_{};
  // The sample's quantities that are not state, by lane (copied into the sample).
  Values actual_{}, following_error_{}, position_error_{}, acceleration_{};
};

}  // namespace ncc::vm
