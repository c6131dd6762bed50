#include "ncc/vm/servo/servo_model.h"

namespace ncc::vm {

ServoModel::ServoModel(const MachineConfig& machine)
    : axis_count_(machine.axisCount() < kMaxAxes ? machine.axisCount() : kMaxAxes),
      axes_(machine, axis_count_),
      monitors_(machine, axis_count_) {
  reset(machine.start_position);
}

void ServoModel::reset(const AxisValues& position) {
  sample_ = ServoSample{};
  alarm_ = ServoAlarm{};
  next_tick_ = 0;
  axes_.reset(position);
  monitors_.reset();
  for (int i = 0; i < axis_count_; ++i) {
    sample_.setpoint[i] = position[i];
    sample_.actual[i] = position[i];
  }
}

const ServoSample& ServoModel::step(const AxisValues& setpoint) {
  sample_.tick = next_tick_++;
  axes_.step(setpoint, sample_);
  monitors_.check(axes_);
  // The first alarm since reset is kept; later ones (and later axes') are not.
  if (alarm_.code == 0 && monitors_.anyAlarm()) {
    for (int i = 0; i < axis_count_; ++i) {
      if (monitors_.alarmCode(i) == 0) continue;
      alarm_ = ServoAlarm{monitors_.alarmCode(i), i, sample_.tick, sample_.following_error[i]};
      break;
    }
  }
  return sample_;
}

}  // namespace ncc::vm
