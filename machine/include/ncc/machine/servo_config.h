#pragma once
// Per-axis servo parameters read by the VM's servo model (docs/servo.md). They change how the
// simulated axis follows its setpoints, never the compiled code, so they are not in
// MachineConfig::configHash(). Names follow the Sinumerik machine data they come from
// (840Di extended functions, K3 / notes §4.1).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace ncc {

// MD 32620 FFW_MODE.
enum class FeedForwardMode : uint8_t { None, Velocity, Torque };

// Values at equidistant support points start, start + step, ...; linear interpolation
// between them, the end values held outside (as $AA_ENC_COMP / LEC tables). Empty: no table.
struct PitchTable {
  double start = 0.0;           // machine position of values[0], mm or deg
  double step = 1.0;            // distance of the support points, > 0
  std::vector<double> values;   // mm or deg
  friend bool operator==(const PitchTable&, const PitchTable&) = default;
};

// Support point k of a table, start + k step, as every lookup computes it.
inline double pitchSupport(double start, double step, std::size_t k) {
  return start + static_cast<double>(k) * step;
}

// The slope after support point k of values[0..last_index], as every lookup computes it
// (0 after the last).
inline double pitchSlope(const double* values, std::size_t k, std::size_t last_index,
                         double step) {
  return k < last_index ? (values[k + 1] - values[k]) / step : 0.0;
}

// Where a table with a finite start, a step above 0 and finite values cannot be used: its
// support points must be distinct finite doubles (a step below the positions' last digit
// made several of them one), and the slope between neighbours, (v_k - v_k-1) / step, finite
// (a change over a subnormal step, or values near +-1e308, overflowed it).
struct PitchTableFault {
  enum class Kind : uint8_t { Grid, Slope };
  Kind kind;
  std::size_t index;  // the support point (Grid) or value (Slope) k >= 1 where it breaks
};
std::optional<PitchTableFault> pitchTableFault(const PitchTable& table);

struct ServoConfig {
  double kv = 1.0;                       // MD 32200 POSCTRL_GAIN, (m/min)/mm = 16.67/s
  FeedForwardMode ffw_mode = FeedForwardMode::Velocity;  // MD 32620
  double velo_ffw_weight = 1.0;          // MD 32610 VELO_FFW_WEIGHT, 0..1 nominal
  double equiv_speedctrl_time = 0.004;   // MD 32810 EQUIV_SPEEDCTRL_TIME, s
  double contour_tol = 1.0;              // MD 36400 CONTOUR_TOL, mm: following-error limit
  double standstill_pos_tol = 0.2;       // MD 36030 STANDSTILL_POS_TOL, mm
  double standstill_delay_time = 0.4;    // MD 36040 STANDSTILL_DELAY_TIME, s
  double stop_limit_fine = 0.01;         // MD 36010 STOP_LIMIT_FINE, mm: in-position window
  double positioning_time = 1.0;         // MD 36020 POSITIONING_TIME, s: alarm 25080 after
  double backlash = 0.0;                 // mechanical play of the simulated axis, mm
  double backlash_compensation = 0.0;    // MD 32450 BACKLASH, mm
  PitchTable pitch_error;                // leadscrew error of the simulated axis
  PitchTable pitch_compensation;         // LEC table the control corrects with
  friend bool operator==(const ServoConfig&, const ServoConfig&) = default;
};

// The range a servo number must be in: what the machine file accepts, and what
// vm::checkMachine requires of a configuration built in code (Any: finite).
enum class NumberRange : uint8_t { Positive, NonNegative, Any };

struct ServoNumberKey {
  std::string_view name;  // its key in [machine.axis.<NAME>]
  double ServoConfig::*field;
  NumberRange range;
};

// Every number of ServoConfig with its key and range (the pitch tables apart).
std::span<const ServoNumberKey> servoNumberKeys();

}  // namespace ncc
