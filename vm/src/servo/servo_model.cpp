#include "ncc/vm/servo/servo_model.h"

namespace ncc::vm {

ServoModel::ServoModel(const MachineConfig& machine)
    : axis_count_(machine.axisCount() < kMaxAxes ? machine.axisCount() : kMaxAxes) {
  for (int i = 0; i < axis_count_; ++i) {
    axes_[i] = AxisServo(machine.axes[i], machine.ipo_cycle_seconds);
    monitors_[i] = AxisMonitor(machine.axes[i], machine.ipo_cycle_seconds);
  }
  reset(machine.start_position);
}

void ServoModel::reset(const AxisValues& position) {
  sample_ = ServoSample{};
  alarm_ = ServoAlarm{};
  next_tick_ = 0;
  for (int i = 0; i < axis_count_; ++i) {
    axes_[i].reset(position[i]);
    monitors_[i].reset();
    violations_[i] = LimitViolations{};
    sample_.setpoint[i] = position[i];
    sample_.actual[i] = position[i];
  }
}

const ServoSample& ServoModel::step(const AxisValues& setpoint) {
  sample_.tick = next_tick_++;
  for (int i = 0; i < axis_count_; ++i) {
    const double delta = setpoint[i] - sample_.setpoint[i];
    sample_.setpoint[i] = setpoint[i];
    AxisServoOutput out;
    axes_[i].step(setpoint[i], out);
    sample_.actual[i] = out.actual;
    sample_.following_error[i] = out.following_error;
    sample_.velocity[i] = out.velocity;
    sample_.acceleration[i] = out.acceleration;
    const int code = monitors_[i].check(delta, out.actual, out.following_error, out.velocity,
                                        out.acceleration, violations_[i]);
    if (code != 0 && alarm_.code == 0)
      alarm_ = ServoAlarm{code, i, sample_.tick, out.following_error};
  }
  return sample_;
}

}  // namespace ncc::vm
