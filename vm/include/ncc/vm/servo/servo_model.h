#pragma once
// The VM's servo model (DESIGN.md "Servo model", issue 3, docs/servo.md): per axis a position
// loop with gain Kv, velocity/torque feed-forward, a speed loop with its equivalent time
// constant, backlash and pitch-error compensation and mechanics, following-error monitoring
// and limit counts. Feed it one setpoint per IPO cycle (machine coordinates); it returns the
// simulated actual positions.
//
// Real-time: everything is sized in the constructor; reset() and step() allocate nothing,
// throw nothing and do a fixed amount of work per configured axis. Deterministic: the same
// setpoints give bit-identical samples.
#include <cstdint>

#include "ncc/machine/machine_config.h"
#include "ncc/vm/servo/servo_axes.h"
#include "ncc/vm/servo/servo_monitor.h"
#include "ncc/vm/servo/servo_sample.h"

namespace ncc::vm {

class ServoModel {
 public:
  explicit ServoModel(const MachineConfig& machine);

  // At rest at `position` (setpoint = actual, following error 0); clears alarm and counts.
  void reset(const AxisValues& position);
  // One IPO cycle. Axes beyond the machine's are ignored (their sample entries stay 0).
  const ServoSample& step(const AxisValues& setpoint);

  const ServoSample& sample() const { return sample_; }
  int axisCount() const { return axis_count_; }
  // The first alarm since reset (code 0: none). The model keeps running after it: stopping
  // is the VM's decision.
  const ServoAlarm& alarm() const { return alarm_; }
  LimitViolations violations(int axis) const { return monitors_.violations(axis); }

 private:
  int axis_count_ = 0;
  ServoAxes axes_;
  ServoMonitors monitors_;
  ServoSample sample_;
  ServoAlarm alarm_;
  int64_t next_tick_ = 0;
};

}  // namespace ncc::vm
