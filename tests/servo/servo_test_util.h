#pragma once
// Machines and setpoint generators shared by the servo tests.
#include <cmath>
#include <numbers>

#include "ncc/machine/machine_config.h"
#include "ncc/vm/servo/servo_model.h"

namespace ncc::test {

// X and Y (and Z) with the given servo parameters, wide limits and monitoring that never trips
// unless a test asks for it.
inline MachineConfig servoMachine(const ServoConfig& servo, int axes = 2) {
  MachineConfig m = defaultMachine();
  m.axes.resize(axes);
  for (AxisConfig& a : m.axes) {
    a.servo = servo;
    a.servo.contour_tol = 1e6;
    a.servo.standstill_pos_tol = 1e6;
  }
  return m;
}

inline ServoConfig servoParams(double kv, FeedForwardMode mode, double t_eq) {
  ServoConfig s;
  s.kv = kv;
  s.ffw_mode = mode;
  s.equiv_speedctrl_time = t_eq;
  return s;
}

inline double kvPerSecond(double kv) { return kv * 1000.0 / 60.0; }

// A counter-clockwise circle of radius r around the origin at angular speed omega (rad/s),
// starting at (r, 0): the setpoint of tick k.
inline AxisValues circleSetpoint(double r, double omega, double cycle, long k) {
  AxisValues p{};
  const double phi = omega * cycle * static_cast<double>(k);
  p[0] = r * std::cos(phi);
  p[1] = r * std::sin(phi);
  return p;
}

}  // namespace ncc::test
