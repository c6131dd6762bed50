#include "ncc/vm/servo/servo_axes.h"

#include "ncc/vm/servo/backlash.h"
#include "ncc/vm/servo/speed_loop.h"

namespace ncc::vm {

// Siemens gives Kv in (m/min)/mm: 1 (m/min)/mm = 1000/60 1/s.
constexpr double kKvToPerSecond = 1000.0 / 60.0;

ServoAxes::ServoAxes(const MachineConfig& machine, int axis_count)
    : count_(axis_count), cycle_(machine.ipo_cycle_seconds), rate_(1.0 / cycle_) {
  for (int i = 0; i < count_; ++i) {
    const ServoConfig& s = machine.axes[i].servo;
    kv_[i] = s.kv * kKvToPerSecond;
    velocity_ffw_[i] = s.ffw_mode == FeedForwardMode::None ? 0.0 : s.velo_ffw_weight;
    // q T_eq, the weight of the setpoint's acceleration (q = 1 with torque feed-forward).
    torque_ffw_[i] = (s.ffw_mode == FeedForwardMode::Torque ? 1.0 : 0.0) * s.equiv_speedctrl_time;
    const SpeedLoopLag lag = SpeedLoopLag::of(s.equiv_speedctrl_time, cycle_);
    decay_[i] = lag.decay;
    lag_distance_[i] = lag.lag_distance;
    // Velocity feed-forward reaches the motor through the speed loop's lag, so the position
    // setpoint is delayed by the same lag before the comparison. Torque feed-forward cancels
    // that lag (the current loop, MD 32800, is not modelled: its delay is 0): nothing to delay.
    const bool symmetrise =
        s.ffw_mode == FeedForwardMode::Velocity && s.equiv_speedctrl_time > 0.0;
    symmetrise_[i] = symmetrise ? 1.0 : 0.0;
    backlash_half_[i] = 0.5 * s.backlash_compensation;
    play_half_[i] = 0.5 * (s.backlash < 0.0 ? -s.backlash : s.backlash);
    play_sign_[i] = s.backlash < 0.0 ? -1.0 : 1.0;
    compensation_tables_.add(i, s.pitch_compensation);
    pitch_error_tables_.add(i, s.pitch_error);
  }
}

void ServoAxes::reset(const AxisValues& position) {
  for (int i = 0; i < count_; ++i) setpoint_[i] = position[i];
  compensation_tables_.lookUp(count_, setpoint_);
  const AxisLanes& compensation = compensation_tables_.values();
  for (int i = 0; i < count_; ++i) {
    setpoint_delta_[i] = 0.0;
    const double command = position[i] - compensation[i];
    command_[i] = command;
    target_[i] = command;
    ffw_velocity_[i] = 0.0;
    backlash_[i] = 0.0;
    reference_[i] = command;
    reference_speed_[i] = 0.0;
    motor_[i] = command;
    speed_[i] = 0.0;
    last_speed_[i] = 0.0;
    play_lag_[i] = 0.0;
  }
  pitch_error_tables_.lookUp(count_, motor_);
  const AxisLanes& pitch_error = pitch_error_tables_.values();
  for (int i = 0; i < count_; ++i) last_nut_[i] = motor_[i] + pitch_error[i];
}

void ServoAxes::step(const AxisValues& __restrict setpoint, ServoSample& __restrict out) {
  const int n = count_;
  const int lanes = laneCount(n);  // the loops to it vectorise; a padding lane stays 0
  const double cycle = cycle_, rate = rate_;

  // The setpoint into the axes' lanes (only those: an entry beyond them is not an axis), a
  // pair of lanes at a time, so that each pair is stored as one vector: the loops below load
  // them as pairs, and a pair written as two scalars cannot be forwarded to such a load (it
  // waits for the stores to retire; 10 ns a cycle on the 3-axis mill).
  for (int i = 0; i < lanes; i += 2) {
    const double first = setpoint[i];
    const double second = i + 1 < n ? setpoint[i + 1] : 0.0;  // the padding lane stays 0
    setpoint_delta_[i] = first - setpoint_[i];
    setpoint_delta_[i + 1] = second - setpoint_[i + 1];
    setpoint_[i] = first;
    setpoint_[i + 1] = second;
  }

  // 1. Compensation (notes §4.1). LEC: the table holds the error it corrects (a positive value
  // moves the axis negative). Backlash: the step acts on the position loop only, as Siemens
  // corrects the actual value, so it is neither differentiated into the feed-forward nor
  // symmetrised.
  compensation_tables_.lookUp(n, setpoint_);
  const AxisLanes& compensation = compensation_tables_.values();
  for (int i = 0; i < lanes; ++i)
    backlash_[i] = backlashCompensation(backlash_[i], setpoint_delta_[i], backlash_half_[i]);

  // 2. Control. The command is where the axis should be at the end of this cycle. The
  // position loop acts on the error at the cycle's start (against the previous target); the
  // feed-forward is the speed (and the speed change) this cycle's move needs.
  for (int i = 0; i < lanes; ++i) {
    const double command = setpoint_[i] - compensation[i];
    // Per cycle to per second by a product with 1/T rather than a division by T: three
    // divisions a lane were a tenth of the servo model's time (the last bit may differ).
    const double ffw_velocity = (command - command_[i]) * rate;
    const double ffw_acceleration = (ffw_velocity - ffw_velocity_[i]) * rate;
    const double speed_setpoint = kv_[i] * (target_[i] - motor_[i]) +
                                  velocity_ffw_[i] * ffw_velocity +
                                  torque_ffw_[i] * ffw_acceleration;
    command_[i] = command;
    ffw_velocity_[i] = ffw_velocity;
    // Symmetrisation: the command through the same lag the feed-forward speed goes through,
    // driven by the same speed, so that with weight 1 it is where the motor is. (Run for every
    // axis, used where enabled: the loop stays branch-free.)
    advanceSpeedLoop(reference_[i], reference_speed_[i], ffw_velocity, cycle, decay_[i],
                     lag_distance_[i]);
    target_[i] = (symmetrise_[i] != 0.0 ? reference_[i] : command) + backlash_[i];
    last_speed_[i] = speed_[i];
    advanceSpeedLoop(motor_[i], speed_[i], speed_setpoint, cycle, decay_[i], lag_distance_[i]);
  }

  // 3. Mechanics between the motor and the table, and the sample at the cycle's end.
  pitch_error_tables_.lookUp(n, motor_);
  const AxisLanes& pitch_error = pitch_error_tables_.values();
  for (int i = 0; i < lanes; ++i) {
    const double nut = motor_[i] + pitch_error[i];
    play_lag_[i] = takeUpPlay(play_lag_[i], nut - last_nut_[i], play_half_[i]);
    last_nut_[i] = nut;
    actual_[i] = nut - play_sign_[i] * play_lag_[i];
    following_error_[i] = target_[i] - motor_[i];
    position_error_[i] = command_[i] + backlash_[i] - motor_[i];
    acceleration_[i] = (speed_[i] - last_speed_[i]) * rate;
  }
  // All kMaxAxes entries: those beyond the axes are 0 (their lanes are never set).
  copyAxes(setpoint_, out.setpoint);
  copyAxes(actual_, out.actual);
  copyAxes(following_error_, out.following_error);
  copyAxes(position_error_, out.position_error);
  copyAxes(speed_, out.velocity);
  copyAxes(acceleration_, out.acceleration);
}

}  // namespace ncc::vm
