#pragma once
// The closed speed loop as the position controller sees it (MD 32810 EQUIV_SPEEDCTRL_TIME):
// a first-order lag with the equivalent time constant T_eq from speed setpoint to speed, and
// the position that speed integrates to. Integrated exactly for a setpoint held over the IPO
// cycle T, so it is exact and stable for any T and T_eq (T_eq = 0: the speed follows at once).
//
// The servo model uses it twice with the same arithmetic: as the motor's speed loop, and as
// the symmetrisation of the position setpoint under velocity feed-forward (docs/servo.md), so
// that with ideal feed-forward the two stay bit-identical and the control deviation is 0.
#include <cmath>

namespace ncc::vm {

// The lag's constants for a cycle of T.
struct SpeedLoopLag {
  double decay = 0.0;         // b = exp(-T / T_eq): what is left of a speed transient
  double lag_distance = 0.0;  // L = T_eq (1 - b): position lost to the lag per unit speed step

  static SpeedLoopLag of(double t_eq, double cycle_seconds) {
    const double decay = t_eq > 0.0 ? std::exp(-cycle_seconds / t_eq) : 0.0;
    return {decay, t_eq * (1.0 - decay)};
  }
};

// One cycle with `speed_setpoint` u held:  x += u T + (v - u) L,  v = u + (v - u) b.
inline void advanceSpeedLoop(double& position, double& speed, double speed_setpoint,
                             double cycle_seconds, double decay, double lag_distance) {
  const double transient = speed - speed_setpoint;
  position = position + speed_setpoint * cycle_seconds + transient * lag_distance;
  speed = speed_setpoint + transient * decay;
}

}  // namespace ncc::vm
