// Issue 21 in the machine file: sane bounds on every number (ncc/machine/bounds.h), a start
// position within the travel, the machine's dialect, and warnings for parameters without
// effect in the selected dialect.
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "ncc/machine/bounds.h"
#include "ncc/machine/machine_file.h"
#include "ncc/machine/params.h"

namespace ncc {
namespace {

struct Result {
  std::optional<MachineConfig> machine;
  std::vector<std::string> messages;  // "machine.toml:4:1: error[NCC0306]: ..."
};

Result parse(std::string_view text, MachineFileOptions options = {}) {
  SourceManager sources;
  DiagnosticEngine diags(&sources);
  Result r;
  r.machine = parseMachineFile(text, "machine.toml", sources, diags, options);
  for (const Diagnostic& d : diags.diagnostics()) r.messages.push_back(diags.format(d));
  return r;
}

TEST(MachineBounds, AbsurdValuesAreRefusedAtTheirValue) {
  struct Case {
    const char* text;
    const char* where_and_key;
  };
  const Case cases[] = {
      {"[machine]\nipo_cycle = 1e-300\n", "machine.toml:2:13: error[NCC0306]: 'ipo_cycle'"},
      {"[machine]\nipo_cycle = 0.00005\n", "machine.toml:2:13: error[NCC0306]: 'ipo_cycle'"},
      {"[machine]\nchord_tolerance = 1e-300\n", "machine.toml:2:19: error[NCC0306]: 'chord_tolerance'"},
      {"[machine]\ncorner_tolerance = 1e-300\n", "machine.toml:2:20: error[NCC0306]: 'corner_tolerance'"},
      {"[machine.axis.X]\nmax_jerk = 1e-300\n", "machine.toml:2:12: error[NCC0306]: 'max_jerk' of X"},
      {"[machine.axis.X]\nmax_jerk = 1e10\n", "machine.toml:2:12: error[NCC0306]: 'max_jerk' of X"},
      {"[machine.axis.Y]\nmax_acceleration = 1e-300\n", "error[NCC0306]: 'max_acceleration' of Y"},
      {"[machine.axis.Z]\nmax_velocity = 0.5\n", "error[NCC0306]: 'max_velocity' of Z"},
      {"[machine.axis.Z]\nrapid_velocity = 2e6\n", "error[NCC0306]: 'rapid_velocity' of Z"},
      {"[machine.axis.X]\nmin_travel = -1e300\n", "error[NCC0306]: 'min_travel' of X"},
      {"[start]\nposition = { X = 1e300 }\n", "error[NCC0306]: 'position' of X is 1e+300"},
      {"[machine.work]\nG55 = [0.0, 2e9, 0.0]\n", "error[NCC0306]: 'G55' of Y"},
  };
  for (const Case& c : cases) {
    const Result r = parse(c.text);
    EXPECT_FALSE(r.machine) << c.text;
    ASSERT_FALSE(r.messages.empty()) << c.text;
    EXPECT_NE(r.messages.front().find(c.where_and_key), std::string::npos)
        << c.text << "\n" << r.messages.front();
  }
}

TEST(MachineBounds, RealMachinesStayWithinTheBounds) {
  const Result r = parse(
      "[machine]\nipo_cycle = 0.000125\nchord_tolerance = 0.0001\ncorner_tolerance = 0\n"
      "[machine.axis.X]\nrapid_velocity = 120000.0\nmax_jerk = 1.0\nmax_acceleration = 30000.0\n"
      "min_travel = -1500.0\nmax_travel = 1500.0\n");
  ASSERT_TRUE(r.machine) << (r.messages.empty() ? "" : r.messages.front());
  EXPECT_EQ(r.machine->corner_tolerance, 0.0);
  EXPECT_EQ(r.machine->ipo_cycle_seconds, 0.000125);
}

TEST(MachineBounds, StartPositionOutsideTheTravelIsAnError) {
  const Result r = parse(
      "[machine.axis.X]\nmax_travel = 10.0\n\n[start]\nposition = { Y = 1.0, X = 11.0 }\n");
  EXPECT_FALSE(r.machine);
  ASSERT_EQ(r.messages.size(), 1u);
  EXPECT_EQ(r.messages.front(),
            "machine.toml:5:27: error[NCC0306]: start position 11 of X is outside its travel "
            "[-1e+09, 10]");
  // On the limit is inside.
  EXPECT_TRUE(parse("[machine.axis.X]\nmax_travel = 10.0\n\n[start]\nposition = { X = 10.0 }\n")
                  .machine);
  // The software_limits parameter sets the travel too.
  EXPECT_FALSE(parse("[machine.params]\nsoftware_limits = { Z = [-100.0, 0.0] }\n\n[start]\n"
                     "position = { Z = 5.0 }\n")
                   .machine);
}

TEST(MachineBounds, DialectKey) {
  const Result r = parse("[machine]\ndialect = \"mazak-m\"\n");
  ASSERT_TRUE(r.machine);
  EXPECT_EQ(r.machine->dialect, Dialect::MazakM);
  EXPECT_FALSE(parse("").machine->dialect);
  const Result bad = parse("[machine]\ndialect = \"heidenhain\"\n");
  EXPECT_FALSE(bad.machine);
  ASSERT_EQ(bad.messages.size(), 1u);
  EXPECT_NE(bad.messages.front().find("machine.toml:2:11: error[NCC0306]: unknown dialect "
                                      "'heidenhain'"),
            std::string::npos);
  // Not hashed: the bytecode header carries the dialect.
  EXPECT_EQ(r.machine->configHash(), defaultMachine().configHash());
}

TEST(MachineBounds, ParameterWithoutEffectInTheDialectIsAWarning) {
  const std::string text =
      "[machine]\ndialect = \"fanuc-m\"\n\n[machine.params]\ngcode_system = \"B\"\n"
      "decimal_point = \"calculator\"\n";
  // Without a known dialect (a conformance case read alone): no warning.
  MachineFileOptions none;
  const Result quiet = parse("[machine.params]\ngcode_system = \"B\"\n", none);
  EXPECT_TRUE(quiet.machine);
  EXPECT_TRUE(quiet.messages.empty());
  // The file's dialect.
  const Result r = parse(text);
  ASSERT_TRUE(r.machine);
  ASSERT_EQ(r.messages.size(), 1u);
  EXPECT_EQ(r.messages.front(),
            "machine.toml:5:16: warning[NCC0307]: parameter 'gcode_system' has no effect in "
            "fanuc-m (ncc does not apply it in any dialect yet)");
  // --dialect overrides the file's; the default only applies when neither names one.
  MachineFileOptions siemens;
  siemens.dialect = Dialect::SiemensIsoM;
  EXPECT_NE(parse(text, siemens).messages.front().find("no effect in siemens-iso-m"),
            std::string::npos);
  MachineFileOptions fallback;
  fallback.default_dialect = Dialect::MazakM;
  EXPECT_NE(parse("[machine.params]\ngcode_system = \"B\"\n", fallback).messages.front().find(
                "no effect in mazak-m"),
            std::string::npos);
}

TEST(MachineBounds, AppliedParametersApplyInEveryDialect) {
  const ParamSpec* decimal = findParameter("decimal_point");
  ASSERT_NE(decimal, nullptr);
  for (Dialect d : {Dialect::FanucM, Dialect::MazakM, Dialect::SiemensIsoM})
    EXPECT_TRUE(paramApplies(*decimal, d));
  const ParamSpec* gcode = findParameter("gcode_system");
  ASSERT_NE(gcode, nullptr);
  EXPECT_FALSE(paramApplies(*gcode, Dialect::FanucT));
}

}  // namespace
}  // namespace ncc
