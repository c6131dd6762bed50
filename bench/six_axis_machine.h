#pragma once
// The machine the VM benchmarks measure: the default mill plus rotary A, B and C, every axis
// with torque feed-forward, backlash and a pitch-error table (its compensation on), so a tick
// does the servo model's full work on six axes.
#include <vector>

#include "ncc/machine/machine_config.h"

namespace ncc::bench {

inline MachineConfig sixAxes() {
  MachineConfig m = defaultMachine();
  for (const char* name : {"A", "B", "C"}) {
    AxisConfig a;
    a.name = name;
    a.kind = AxisKind::Rotary;
    m.axes.push_back(a);
  }
  for (AxisConfig& a : m.axes) {
    a.servo.ffw_mode = FeedForwardMode::Torque;
    a.servo.backlash = 0.01;
    a.servo.backlash_compensation = 0.01;
    a.servo.pitch_error = PitchTable{-500.0, 10.0, std::vector<double>(101, 0.001)};
    a.servo.pitch_compensation = a.servo.pitch_error;
  }
  return m;
}

}  // namespace ncc::bench
