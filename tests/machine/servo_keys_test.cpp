// The servo keys of [machine.axis.<NAME>] (docs/machine-file.md, docs/servo.md): read back,
// rejected with their code and position, and left out of the configuration hash.
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "ncc/machine/machine_file.h"

namespace ncc {
namespace {

struct Result {
  std::optional<MachineConfig> machine;
  std::vector<std::string> errors;
};

Result parse(std::string_view text) {
  SourceManager sources;
  DiagnosticEngine diags(&sources);
  Result r;
  r.machine = parseMachineFile(text, "machine.toml", sources, diags);
  for (const Diagnostic& d : diags.diagnostics()) r.errors.push_back(diags.format(d));
  EXPECT_EQ(r.machine.has_value(), !diags.hasErrors());
  return r;
}

std::string onlyError(std::string_view text) {
  Result r = parse(text);
  EXPECT_FALSE(r.machine.has_value());
  EXPECT_EQ(r.errors.size(), 1u) << (r.errors.empty() ? "" : r.errors.front());
  return r.errors.empty() ? "" : r.errors.front();
}

TEST(ServoKeys, DefaultsAreSiemensDefaults) {
  const ServoConfig s = defaultMachine().axes[0].servo;
  EXPECT_EQ(s.kv, 1.0);
  EXPECT_EQ(s.ffw_mode, FeedForwardMode::Velocity);
  EXPECT_EQ(s.velo_ffw_weight, 1.0);
  EXPECT_EQ(s.equiv_speedctrl_time, 0.004);
  EXPECT_EQ(s.contour_tol, 1.0);
  EXPECT_EQ(s.standstill_pos_tol, 0.2);
  EXPECT_EQ(s.standstill_delay_time, 0.4);
  EXPECT_EQ(s.stop_limit_fine, 0.01);
  EXPECT_EQ(s.positioning_time, 1.0);
  EXPECT_EQ(s.backlash, 0.0);
  EXPECT_EQ(s.backlash_compensation, 0.0);
  EXPECT_TRUE(s.pitch_error.values.empty());
  EXPECT_TRUE(s.pitch_compensation.values.empty());
}

TEST(ServoKeys, ReadsEveryKeyBack) {
  Result r = parse(R"(
[machine.axis.Y]
max_velocity = 20000.0
kv = 2.5
ffw_mode = "torque"
velo_ffw_weight = 0.9
equiv_speedctrl_time = 0.003
contour_tol = 0.5
standstill_pos_tol = 0.05
standstill_delay_time = 0.2
stop_limit_fine = 0.005
positioning_time = 2.5
backlash = 0.012
backlash_compensation = 0.01
pitch_error = { start = -100.0, step = 50.0, values = [0.0, 0.002, -0.001] }
pitch_compensation = { start = -100, step = 50, values = [0.0, 0.002, -0.001] }
)");
  ASSERT_TRUE(r.machine) << (r.errors.empty() ? "" : r.errors.front());
  const AxisConfig& y = r.machine->axes[1];
  EXPECT_EQ(y.max_velocity, 20000.0);
  EXPECT_EQ(y.servo.kv, 2.5);
  EXPECT_EQ(y.servo.ffw_mode, FeedForwardMode::Torque);
  EXPECT_EQ(y.servo.velo_ffw_weight, 0.9);
  EXPECT_EQ(y.servo.equiv_speedctrl_time, 0.003);
  EXPECT_EQ(y.servo.contour_tol, 0.5);
  EXPECT_EQ(y.servo.standstill_pos_tol, 0.05);
  EXPECT_EQ(y.servo.standstill_delay_time, 0.2);
  EXPECT_EQ(y.servo.stop_limit_fine, 0.005);
  EXPECT_EQ(y.servo.positioning_time, 2.5);
  EXPECT_EQ(y.servo.backlash, 0.012);
  EXPECT_EQ(y.servo.backlash_compensation, 0.01);
  const PitchTable expected{-100.0, 50.0, {0.0, 0.002, -0.001}};
  EXPECT_EQ(y.servo.pitch_error, expected);
  EXPECT_EQ(y.servo.pitch_compensation, expected);
  EXPECT_EQ(r.machine->axes[0].servo, ServoConfig{});  // other axes keep the defaults
}

TEST(ServoKeys, ServoParametersDoNotChangeTheHash) {
  Result r = parse(R"(
[machine.axis.X]
kv = 3.0
ffw_mode = "none"
backlash = 0.01
pitch_error = { start = 0.0, step = 10.0, values = [0.0, 0.001] }
)");
  ASSERT_TRUE(r.machine);
  EXPECT_EQ(r.machine->configHash(), defaultMachine().configHash());
  EXPECT_EQ(r.machine->configHash(), 0x9711b811c2d3544fULL);
}

TEST(ServoKeys, BadValuesAreReported) {
  EXPECT_EQ(onlyError("[machine.axis.X]\nkv = 0.0\n"),
            "machine.toml:2:6: error[NCC0306]: 'kv' of X must be above 0");
  EXPECT_EQ(onlyError("[machine.axis.X]\nstop_limit_fine = 0.0\n"),
            "machine.toml:2:19: error[NCC0306]: 'stop_limit_fine' of X must be above 0");
  EXPECT_EQ(onlyError("[machine.axis.Y]\npositioning_time = -1.0\n"),
            "machine.toml:2:20: error[NCC0306]: 'positioning_time' of Y must be above 0");
  EXPECT_EQ(onlyError("[machine.axis.X]\nequiv_speedctrl_time = -0.001\n"),
            "machine.toml:2:24: error[NCC0306]: 'equiv_speedctrl_time' of X must be at least 0");
  EXPECT_EQ(onlyError("[machine.axis.X]\nkv = \"fast\"\n"),
            "machine.toml:2:6: error[NCC0303]: wrong type for 'kv': expected a number, found a "
            "string");
  EXPECT_EQ(onlyError("[machine.axis.X]\nffw_mode = \"both\"\n"),
            "machine.toml:2:12: error[NCC0306]: invalid value \"both\" for 'ffw_mode': expected "
            "\"none\", \"velocity\", \"torque\"");
  EXPECT_EQ(onlyError("[machine.axis.X]\npitch_error = { start = 0.0, step = 0.0, values = [0.0] }\n"),
            "machine.toml:2:37: error[NCC0306]: 'pitch_error.step' of X must be above 0");
  EXPECT_EQ(onlyError("[machine.axis.X]\npitch_error = { start = 0.0, step = 1.0 }\n"),
            "machine.toml:2:15: error[NCC0306]: 'pitch_error' of X has no 'values'");
  EXPECT_EQ(onlyError("[machine.axis.X]\npitch_error = { values = [], step = 1.0 }\n"),
            "machine.toml:2:26: error[NCC0306]: 'pitch_error.values' of X must have 1 to 5000 "
            "values, not 0");
  EXPECT_EQ(onlyError("[machine.axis.X]\npitch_compensation = { values = [0.0], slope = 1.0 }\n"),
            "machine.toml:2:40: error[NCC0302]: unknown key 'slope' in 'pitch_compensation' "
            "(expected start, step, values)");
  EXPECT_EQ(onlyError("[machine.axis.X]\npitch_error = [0.0, 1.0]\n"),
            "machine.toml:2:15: error[NCC0303]: wrong type for 'pitch_error': expected a table "
            "{ start, step, values }, found a list");
  // Support points that coincide (a step below the positions' last digit), and a slope that
  // overflows (review 12: a lookup walked the grid, or gave inf).
  EXPECT_EQ(onlyError("[machine.axis.X]\n"
                      "pitch_error = { start = 1e16, step = 0.5, values = [0.0, 0.001] }\n"),
            "machine.toml:2:38: error[NCC0306]: 'pitch_error.step' of X is too small for its 2 "
            "support points: start + 1 step is not a finite number above start + 0 step");
  EXPECT_EQ(onlyError("[machine.axis.Y]\n"
                      "pitch_compensation = { step = 0.5, values = [-1e308, 1e308] }\n"),
            "machine.toml:2:54: error[NCC0306]: 'pitch_compensation.values' of Y: values[1] - "
            "values[0] over the step is not a finite slope");
}

}  // namespace
}  // namespace ncc
