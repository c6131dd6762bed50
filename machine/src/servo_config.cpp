#include "ncc/machine/servo_config.h"

#include <cmath>

namespace ncc {
namespace {

constexpr ServoNumberKey kServoNumberKeys[] = {
    {"kv", &ServoConfig::kv, NumberRange::Positive},
    {"velo_ffw_weight", &ServoConfig::velo_ffw_weight, NumberRange::NonNegative},
    {"equiv_speedctrl_time", &ServoConfig::equiv_speedctrl_time, NumberRange::NonNegative},
    {"contour_tol", &ServoConfig::contour_tol, NumberRange::Positive},
    {"standstill_pos_tol", &ServoConfig::standstill_pos_tol, NumberRange::Positive},
    {"standstill_delay_time", &ServoConfig::standstill_delay_time, NumberRange::NonNegative},
    {"stop_limit_fine", &ServoConfig::stop_limit_fine, NumberRange::Positive},
    {"positioning_time", &ServoConfig::positioning_time, NumberRange::Positive},
    {"backlash", &ServoConfig::backlash, NumberRange::Any},
    {"backlash_compensation", &ServoConfig::backlash_compensation, NumberRange::Any},
};

}  // namespace

std::span<const ServoNumberKey> servoNumberKeys() { return kServoNumberKeys; }

std::optional<PitchTableFault> pitchTableFault(const PitchTable& table) {
  for (std::size_t k = 1; k < table.values.size(); ++k) {
    const double point = pitchSupport(table.start, table.step, k);
    if (!(std::isfinite(point) && point > pitchSupport(table.start, table.step, k - 1)))
      return PitchTableFault{PitchTableFault::Kind::Grid, k};
    if (!std::isfinite(pitchSlope(table.values.data(), k - 1, table.values.size() - 1, table.step)))
      return PitchTableFault{PitchTableFault::Kind::Slope, k};
  }
  return std::nullopt;
}

}  // namespace ncc
