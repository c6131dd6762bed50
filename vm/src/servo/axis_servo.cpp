#include "ncc/vm/servo/axis_servo.h"

#include <cmath>

#include "ncc/vm/servo/pitch_compensation.h"

namespace ncc::vm {

// Siemens gives Kv in (m/min)/mm: 1 (m/min)/mm = 1000/60 1/s.
constexpr double kKvToPerSecond = 1000.0 / 60.0;

AxisServo::AxisServo(const AxisConfig& axis, double cycle_seconds)
    : pitch_error_(axis.servo.pitch_error),
      pitch_compensation_(axis.servo.pitch_compensation),
      cycle_(cycle_seconds),
      kv_(axis.servo.kv * kKvToPerSecond),
      t_eq_(axis.servo.equiv_speedctrl_time),
      play_(axis.servo.backlash),
      backlash_comp_(axis.servo.backlash_compensation) {
  const ServoConfig& s = axis.servo;
  velocity_ffw_ = s.ffw_mode == FeedForwardMode::None ? 0.0 : s.velo_ffw_weight;
  torque_ffw_ = s.ffw_mode == FeedForwardMode::Torque ? 1.0 : 0.0;
  decay_ = t_eq_ > 0.0 ? std::exp(-cycle_ / t_eq_) : 0.0;
  lag_distance_ = t_eq_ * (1.0 - decay_);
}

void AxisServo::reset(double position) {
  setpoint_ = position;
  command_ = position - pitchValue(pitch_compensation_, position);
  target_ = command_;
  ffw_velocity_ = 0.0;
  motor_ = command_;
  speed_ = 0.0;
  backlash_comp_.reset();
  play_.reset(motor_ + pitchValue(pitch_error_, motor_));
}

void AxisServo::step(double setpoint, AxisServoOutput& out) {
  // Compensation (notes §4.1): the LEC table holds the error it corrects (a positive value
  // moves the axis negative); the backlash step acts on the position loop only, as Siemens
  // corrects the actual value, so it is not differentiated into the feed-forward.
  const double backlash = backlash_comp_.update(setpoint - setpoint_);
  setpoint_ = setpoint;
  const double command = setpoint - pitchValue(pitch_compensation_, setpoint);

  // The setpoint is where the axis should be at the end of this cycle. The position loop acts
  // on the error at the cycle's start (against the previous setpoint); the feed-forward is the
  // speed (and the speed change) this cycle's move needs.
  const double ffw_velocity = (command - command_) / cycle_;
  const double ffw_acceleration = (ffw_velocity - ffw_velocity_) / cycle_;
  const double speed_setpoint = kv_ * (target_ - motor_) + velocity_ffw_ * ffw_velocity +
                                torque_ffw_ * t_eq_ * ffw_acceleration;
  command_ = command;
  ffw_velocity_ = ffw_velocity;
  target_ = command + backlash;

  // Speed loop as a first-order lag, its setpoint held over the cycle (integrated exactly).
  const double transient = speed_ - speed_setpoint;
  const double last_speed = speed_;
  motor_ = motor_ + speed_setpoint * cycle_ + transient * lag_distance_;
  speed_ = speed_setpoint + transient * decay_;

  // The sample at the cycle's end; the mechanics sit between the motor and the table.
  out.actual = play_.load(motor_ + pitchValue(pitch_error_, motor_));
  out.following_error = target_ - motor_;
  out.velocity = speed_;
  out.acceleration = (speed_ - last_speed) / cycle_;
}

}  // namespace ncc::vm
