// Machine-file reader: values read back exactly, and every kind of bad input gives its
// code, line, column and message (docs/machine-file.md, "Diagnostics").
#include "ncc/machine/machine_file.h"

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "gtest/gtest.h"

namespace ncc {
namespace {

struct Result {
  std::optional<MachineConfig> machine;
  std::vector<std::string> errors;  // formatted: "machine.toml:4:1: error[NCC0302]: ..."
};

Result parse(std::string_view text, MachineFileOptions options = {}) {
  SourceManager sources;
  DiagnosticEngine diags(&sources);
  Result r;
  r.machine = parseMachineFile(text, "machine.toml", sources, diags, options);
  for (const Diagnostic& d : diags.diagnostics()) r.errors.push_back(diags.format(d));
  // The reader's contract: a machine exactly when there was no error.
  EXPECT_EQ(r.machine.has_value(), !diags.hasErrors());
  return r;
}

// The single error of a file that must be rejected.
std::string onlyError(std::string_view text) {
  Result r = parse(text);
  EXPECT_FALSE(r.machine.has_value());
  EXPECT_EQ(r.errors.size(), 1u) << (r.errors.empty() ? "" : r.errors.front());
  return r.errors.empty() ? "" : r.errors.front();
}

TEST(MachineFile, ReadsEveryTableBack) {
  Result r = parse(R"(
[machine]
axes = ["X", "Y", "Z", "B"]
ipo_cycle = 0.002
chord_tolerance = 0.0005
corner_tolerance = 0.05
lookahead_segments = 4096
[machine.offsets]
H1 = 100.5
D1 = 5.0
H12 = -3.25
T1 = { x = 1.0, z = 2.0, radius = 0.4, tip = 3 }
geometry2 = { x = 4.0, z = 2.0 }
wear2 = { x = 0.4, z = -0.2 }
second_geometry3 = { x = 10.0 }
[machine.work]
G54 = [-100.0, -50.0, -200.0, 0.0]
G59 = { Y = 7.0 }
"G54.1P1" = [1.0, 2.0, 3.0, 4.0]
"G54.1 P2" = [5.0, 6.0, 7.0, 8.0]
G54_1P3 = [9.0, 10.0, 11.0, 12.0]
G54P93 = [0.5, 0.0, 0.0, 0.0]
[machine.params]
decimal_point = "calculator"
peck_return = 2
offset_count = 128
block_skip = true
reference_point_2 = { X = -100.0, Y = -50.0 }
f1_f9_feedrates = [1500.0, 550.0]
modulo_axes = ["B"]
m_code_macros = { M6 = "M6_MAKRO" }
software_limits = { B = [-10000.0, 10000.0] }
block_skip_levels = [1, 3]
[machine.axis.X]
min_travel = -500.0
max_travel = 10.0
rapid_velocity = 24000.0
max_velocity = 10000.0
max_acceleration = 1500.0
max_jerk = 30000.0
[start]
position = { X = 1.0, Z = 200.0 }
)");
  ASSERT_TRUE(r.machine) << (r.errors.empty() ? "" : r.errors.front());
  const MachineConfig& m = *r.machine;
  ASSERT_EQ(m.axisCount(), 4);
  EXPECT_EQ(m.axes[3].name, "B");
  EXPECT_EQ(m.axes[3].kind, AxisKind::Rotary);  // A/B/C are rotary by default
  EXPECT_EQ(m.axes[0].kind, AxisKind::Linear);
  EXPECT_EQ(m.axisIndex("Z"), 2);
  EXPECT_EQ(m.axisIndex("Q"), -1);
  EXPECT_DOUBLE_EQ(m.ipo_cycle_seconds, 0.002);
  EXPECT_DOUBLE_EQ(m.chord_tolerance, 0.0005);
  EXPECT_DOUBLE_EQ(m.corner_tolerance, 0.05);
  EXPECT_EQ(m.lookahead_segments, 4096);

  EXPECT_EQ(m.tool_offsets.length, (std::map<int, double>{{1, 100.5}, {12, -3.25}}));
  EXPECT_EQ(m.tool_offsets.radius, (std::map<int, double>{{1, 5.0}}));
  EXPECT_EQ(m.lathe_offsets.combined.at(1), (LatheOffset{1.0, 2.0, 0.4, 3}));
  EXPECT_EQ(m.lathe_offsets.geometry.at(2), (LatheOffset{4.0, 2.0, 0.0, 0}));
  EXPECT_EQ(m.lathe_offsets.wear.at(2), (LatheOffset{0.4, -0.2, 0.0, 0}));
  EXPECT_EQ(m.lathe_offsets.second_geometry.at(3), (LatheOffset{10.0, 0.0, 0.0, 0}));

  EXPECT_EQ(m.work_offsets.at("G54")[0], -100.0);
  EXPECT_EQ(m.work_offsets.at("G54")[2], -200.0);
  EXPECT_EQ(m.work_offsets.at("G59")[1], 7.0);
  EXPECT_EQ(m.work_offsets.at("G59")[0], 0.0);
  EXPECT_EQ(m.work_offsets.at("G55"), zeroAxes());  // G54-G59 always exist
  EXPECT_EQ(m.work_offsets.at("G54.1P1")[3], 4.0);
  EXPECT_EQ(m.work_offsets.at("G54.1P2")[0], 5.0);
  EXPECT_EQ(m.work_offsets.at("G54.1P3")[1], 10.0);
  EXPECT_EQ(m.work_offsets.at("G54P93")[0], 0.5);

  EXPECT_EQ(m.params.getString("decimal_point", ""), "calculator");
  EXPECT_EQ(m.params.getNumber("peck_return", 0.0), 2.0);  // an integer is a number
  EXPECT_EQ(m.params.getNumber("offset_count", 0.0), 128.0);
  EXPECT_TRUE(m.params.getBool("block_skip", false));
  ASSERT_NE(m.params.getAxisTable("reference_point_2"), nullptr);
  EXPECT_EQ(m.params.getAxisTable("reference_point_2")->by_axis.at("Y"), -50.0);
  EXPECT_EQ(*m.params.getNumberList("f1_f9_feedrates"), (std::vector<double>{1500.0, 550.0}));
  EXPECT_EQ(*m.params.getStringList("modulo_axes"), (std::vector<std::string>{"B"}));
  EXPECT_EQ(m.params.getStringTable("m_code_macros")->by_key.at("M6"), "M6_MAKRO");
  EXPECT_EQ(*m.params.getNumberList("block_skip_levels"), (std::vector<double>{1, 3}));
  EXPECT_EQ(m.axes[3].min_travel, -10000.0);  // software_limits sets travel
  EXPECT_EQ(m.axes[3].max_travel, 10000.0);

  EXPECT_EQ(m.axes[0].min_travel, -500.0);
  EXPECT_EQ(m.axes[0].max_travel, 10.0);
  EXPECT_EQ(m.axes[0].rapid_velocity, 24000.0);
  EXPECT_EQ(m.axes[0].max_velocity, 10000.0);
  EXPECT_EQ(m.axes[0].max_acceleration, 1500.0);
  EXPECT_EQ(m.axes[0].max_jerk, 30000.0);

  EXPECT_EQ(m.start_position[0], 1.0);
  EXPECT_EQ(m.start_position[1], 0.0);
  EXPECT_EQ(m.start_position[2], 200.0);
}

TEST(MachineFile, EmptyFileIsTheDefaultMachine) {
  Result r = parse("");
  ASSERT_TRUE(r.machine);
  EXPECT_EQ(*r.machine, defaultMachine());
  EXPECT_EQ(r.machine->configHash(), defaultMachine().configHash());
}

TEST(MachineFile, LatheFileWithDiameterAxisAndSiemensEdge) {
  Result r = parse(R"(
[machine]
axes = ["X", "Z", "C"]
diameter_axes = ["X"]
[machine.offsets]
D1 = { x = 0.0, z = 0.0, radius = 0.4, tip = 3 }
[machine.params]
rotary_axes = ["C"]
reset_plane = "G18"
)");
  ASSERT_TRUE(r.machine);
  EXPECT_TRUE(r.machine->axes[0].diameter);
  EXPECT_FALSE(r.machine->axes[1].diameter);
  EXPECT_EQ(r.machine->axes[2].kind, AxisKind::Rotary);
  EXPECT_EQ(r.machine->lathe_offsets.edge.at(1), (LatheOffset{0.0, 0.0, 0.4, 3}));
  EXPECT_TRUE(r.machine->tool_offsets.radius.empty());
}

TEST(MachineFile, RotaryAxesParamOverridesTheNameRule) {
  Result r =
      parse("[machine]\naxes = [\"X\", \"A\", \"U\"]\n[machine.params]\nrotary_axes = [\"U\"]\n");
  ASSERT_TRUE(r.machine);
  EXPECT_EQ(r.machine->axes[1].kind, AxisKind::Linear);
  EXPECT_EQ(r.machine->axes[2].kind, AxisKind::Rotary);
}

TEST(MachineFile, ProbeTriggersAreReadAndNotHashed) {
  Result r = parse("[machine]\naxes = [\"X\", \"Y\", \"Z\"]\n[machine.probe]\nZ = -42.5\nX = 120\n");
  ASSERT_TRUE(r.machine);
  EXPECT_EQ(r.machine->probe.axes, 0b101);
  EXPECT_EQ(r.machine->probe.trigger[0], 120.0);
  EXPECT_EQ(r.machine->probe.trigger[2], -42.5);
  // A run-time property: a program compiled without the probe runs with it.
  EXPECT_EQ(r.machine->configHash(), defaultMachine().configHash());
  EXPECT_EQ(defaultMachine().probe.axes, 0);
}

TEST(MachineFile, BadProbeTriggers) {
  Result r = parse("[machine.probe]\nW = 1\nZ = \"a\"\nX = 2e7\n");
  ASSERT_EQ(r.errors.size(), 3u);
  EXPECT_EQ(r.errors[0], "machine.toml:2:1: error[NCC0304]: unknown axis 'W' in 'machine.probe' "
                         "(the machine's axes are X, Y, Z)");
  EXPECT_EQ(r.errors[1],
            "machine.toml:3:5: error[NCC0303]: wrong type for 'Z': expected a number, found a string");
  EXPECT_EQ(r.errors[2], "machine.toml:4:5: error[NCC0306]: the probe trigger of X is 2e+07: "
                         "positions must be within +-1e+06");
}

TEST(MachineFile, UnknownKeyInMachine) {
  EXPECT_EQ(onlyError("[machine]\naxes = [\"X\", \"Y\", \"Z\"]\n\nfoo = 1\n"),
            "machine.toml:4:1: error[NCC0302]: unknown key 'foo' in [machine]");
}

TEST(MachineFile, UnknownTopLevelKeyUnlessIgnored) {
  const char* text = "title = \"a case\"\n[machine]\naxes = [\"X\"]\n[expect]\nfinal = {}\n";
  Result strict = parse(text);
  ASSERT_EQ(strict.errors.size(), 2u);
  EXPECT_EQ(strict.errors[0],
            "machine.toml:1:1: error[NCC0302]: unknown key 'title' in the machine file");
  EXPECT_EQ(strict.errors[1],
            "machine.toml:4:2: error[NCC0302]: unknown key 'expect' in the machine file");
  Result lenient = parse(text, MachineFileOptions{.ignore_other_top_level_keys = true, .dialect = {}, .default_dialect = {}});
  ASSERT_TRUE(lenient.machine);
  EXPECT_EQ(lenient.machine->axisCount(), 1);
}

TEST(MachineFile, UnknownParameter) {
  EXPECT_EQ(onlyError("[machine.params]\ndecimal_pont = \"standard\"\n"),
            "machine.toml:2:1: error[NCC0302]: unknown key 'decimal_pont' in [machine.params]");
}

TEST(MachineFile, ParameterOfWrongTypeNamesKeyAndExpectedType) {
  EXPECT_EQ(onlyError("[machine.params]\ndecimal_point = 1\n"),
            "machine.toml:2:17: error[NCC0303]: wrong type for 'decimal_point': expected a "
            "string, found an integer");
  EXPECT_EQ(onlyError("[machine.params]\nblock_skip = \"yes\"\n"),
            "machine.toml:2:14: error[NCC0303]: wrong type for 'block_skip': expected a boolean "
            "(true or false), found a string");
  EXPECT_EQ(onlyError("[machine.params]\noffset_count = 12.5\n"),
            "machine.toml:2:16: error[NCC0303]: wrong type for 'offset_count': expected an "
            "integer, found a float");
  EXPECT_EQ(onlyError("[machine.params]\nreference_point_1 = [0.0, 0.0]\n"),
            "machine.toml:2:21: error[NCC0303]: wrong type for 'reference_point_1': expected a "
            "table of numbers by axis name, found a list");
  EXPECT_EQ(onlyError("[machine.params]\nsoftware_limits = { X = 5.0 }\n"),
            "machine.toml:2:25: error[NCC0303]: wrong type for 'software_limits': expected a "
            "[min, max] pair of numbers, found a float");
}

TEST(MachineFile, ParameterChoicesAndRanges) {
  EXPECT_EQ(onlyError("[machine.params]\ndecimal_point = \"pocket\"\n"),
            "machine.toml:2:17: error[NCC0306]: invalid value \"pocket\" for 'decimal_point': "
            "expected \"calculator\", \"standard\"");
  EXPECT_EQ(onlyError("[machine.params]\ntnrc_lookahead_blocks = 9\n"),
            "machine.toml:2:25: error[NCC0306]: value 9 of 'tnrc_lookahead_blocks' is out of "
            "range (3 to 8)");
  EXPECT_EQ(onlyError("[machine.params]\nblock_skip_levels = [1, 10]\n"),
            "machine.toml:2:25: error[NCC0306]: value 10 of 'block_skip_levels' is out of range "
            "(1 to 9)");
  EXPECT_EQ(onlyError("[machine.params]\nf1_f9_feedrates = [1,2,3,4,5,6,7,8,9,10]\n"),
            "machine.toml:2:19: error[NCC0306]: 'f1_f9_feedrates' has 10 entries; at most 9 are "
            "allowed");
  EXPECT_EQ(onlyError("[machine.params]\nsoftware_limits = { X = [5.0, -5.0] }\n"),
            "machine.toml:2:25: error[NCC0306]: 'software_limits' of X: min 5 must be below max "
            "-5");
}

TEST(MachineFile, AxisNamesMustBeConfigured) {
  EXPECT_EQ(onlyError("[machine.params]\nreference_point_1 = { X = 0.0, W = 1.0 }\n"),
            "machine.toml:2:32: error[NCC0304]: unknown axis 'W' in 'reference_point_1' (the "
            "machine's axes are X, Y, Z)");
  EXPECT_EQ(onlyError("[machine]\naxes = [\"X\", \"Z\"]\ndiameter_axes = [\"Y\"]\n"),
            "machine.toml:3:18: error[NCC0304]: unknown axis 'Y' in 'diameter_axes' (the "
            "machine's axes are X, Z)");
  EXPECT_EQ(onlyError("[start]\nposition = { X = 0.0, A = 1.0 }\n"),
            "machine.toml:2:23: error[NCC0304]: unknown axis 'A' in 'position' (the machine's "
            "axes are X, Y, Z)");
  EXPECT_EQ(onlyError("[machine.axis.B]\nmax_travel = 1.0\n"),
            "machine.toml:1:15: error[NCC0304]: unknown axis 'B' in 'machine.axis' (the "
            "machine's axes are X, Y, Z)");
  EXPECT_EQ(onlyError("[machine.params]\nparallel_axes = { X = \"U\" }\n"),
            "machine.toml:2:23: error[NCC0304]: unknown axis 'U' in 'parallel_axes' (the "
            "machine's axes are X, Y, Z)");
}

TEST(MachineFile, AxisListErrors) {
  EXPECT_EQ(
      onlyError(
          "[machine]\naxes = [\"X\",\"Y\",\"Z\",\"A\",\"B\",\"C\",\"U\",\"V\",\"W\",\"Q\"]\n"),
      "machine.toml:2:8: error[NCC0305]: 'axes' lists 10 axes; at most 9 are supported");
  EXPECT_EQ(onlyError("[machine]\naxes = [\"X\", \"Y\", \"X\"]\n"),
            "machine.toml:2:19: error[NCC0305]: axis 'X' is listed twice");
  EXPECT_EQ(onlyError("[machine]\naxes = [\"x\"]\n"),
            "machine.toml:2:9: error[NCC0305]: invalid axis name 'x': an upper-case letter, then "
            "upper-case letters or digits (at most 8 characters)");
  EXPECT_EQ(onlyError("[machine]\naxes = []\n"),
            "machine.toml:2:8: error[NCC0305]: 'axes' is empty: a machine has at least one axis");
  EXPECT_EQ(onlyError("[machine]\naxes = \"XYZ\"\n"),
            "machine.toml:2:8: error[NCC0303]: wrong type for 'axes': expected a list, found a "
            "string");
  // Siemens names such as Q1 are axes too.
  Result r = parse("[machine]\naxes = [\"X\", \"Q1\"]\n[start]\nposition = { Q1 = 5.0 }\n");
  ASSERT_TRUE(r.machine);
  EXPECT_EQ(r.machine->start_position[1], 5.0);
}

TEST(MachineFile, TomlSyntaxErrorHasPosition) {
  std::string e = onlyError("[machine]\naxes = [\"X\", \"Y\"\n");
  EXPECT_TRUE(e.rfind("machine.toml:3:", 0) == 0 || e.rfind("machine.toml:2:", 0) == 0) << e;
  EXPECT_NE(e.find("error[NCC0301]"), std::string::npos) << e;
  std::string dup = onlyError("[machine]\naxes = [\"X\"]\naxes = [\"Y\"]\n");
  EXPECT_EQ(dup.rfind("machine.toml:3:", 0), 0u) << dup;
  EXPECT_NE(dup.find("error[NCC0301]: "), std::string::npos) << dup;
  EXPECT_NE(dup.find("axes"), std::string::npos) << dup;
}

TEST(MachineFile, MissingFile) {
  SourceManager sources;
  DiagnosticEngine diags(&sources);
  auto m = loadMachineFile("/nonexistent/dir/machine.toml", sources, diags);
  EXPECT_FALSE(m);
  ASSERT_EQ(diags.diagnostics().size(), 1u);
  EXPECT_EQ(diags.format(diags.diagnostics()[0]),
            "/nonexistent/dir/machine.toml: error[NCC0300]: cannot read the machine file: no such "
            "file or not readable");
}

TEST(MachineFile, LoadsFromDiskAndQuotesTheLine) {
  auto path = std::filesystem::temp_directory_path() /
              ("ncc_machine_file_test_" + std::to_string(::getpid()) + ".toml");
  {
    std::ofstream out(path);
    out << "[machine]\naxes = [\"X\", \"Z\"]\n[machine.work]\nG54 = [1.0, 2.0, 3.0]\n";
  }
  SourceManager sources;
  DiagnosticEngine diags(&sources);
  auto m = loadMachineFile(path, sources, diags);
  EXPECT_FALSE(m);
  std::ostringstream printed;
  diags.print(printed);
  EXPECT_EQ(printed.str(), path.string() +
                               ":4:7: error[NCC0306]: 'G54' has 3 values but the machine has 2 "
                               "axes (X, Z)\n  G54 = [1.0, 2.0, 3.0]\n        ^\n");
  std::filesystem::remove(path);
}

TEST(MachineFile, OffsetRegisterErrors) {
  EXPECT_EQ(onlyError("[machine.offsets]\nX1 = 1.0\n"),
            "machine.toml:2:1: error[NCC0302]: unknown key 'X1' in [machine.offsets] (expected "
            "H<n>, D<n>, T<n>, geometry<n>, wear<n> or second_geometry<n>)");
  EXPECT_EQ(onlyError("[machine.offsets]\nH0 = 1.0\n"),
            "machine.toml:2:1: error[NCC0306]: offset register number in 'H0' must be 1 to 9999");
  EXPECT_EQ(onlyError("[machine.offsets]\nH1 = 1.0\nH01 = 2.0\n"),
            "machine.toml:3:1: error[NCC0306]: offset register H1 is given twice");
  EXPECT_EQ(onlyError("[machine.offsets]\nH1 = \"100\"\n"),
            "machine.toml:2:6: error[NCC0303]: wrong type for 'H1': expected a number, found a "
            "string");
  EXPECT_EQ(onlyError("[machine.offsets]\nT1 = { x = 0.0, tip = 10 }\n"),
            "machine.toml:2:23: error[NCC0306]: 'T1.tip' (tool tip direction) must be 0 to 9");
  EXPECT_EQ(onlyError("[machine.offsets]\nT1 = { y = 0.0 }\n"),
            "machine.toml:2:8: error[NCC0302]: unknown key 'y' in offset register 'T1' "
            "(expected x, z, radius, tip)");
  EXPECT_EQ(onlyError("[machine.offsets]\nT1 = 0.4\n"),
            "machine.toml:2:6: error[NCC0303]: wrong type for 'T1': expected a table { x, z, "
            "radius, tip }, found a float");
  EXPECT_EQ(onlyError("[machine.offsets]\nH1 = inf\n"),
            "machine.toml:2:6: error[NCC0306]: 'H1' must be a finite number");
}

TEST(MachineFile, WorkOffsetErrors) {
  EXPECT_EQ(onlyError("[machine.work]\nG53 = [0.0, 0.0, 0.0]\n"),
            "machine.toml:2:1: error[NCC0302]: unknown key 'G53' in [machine.work] (expected "
            "G54..G59, \"G54.1P<n>\" or G54P<n>)");
  EXPECT_EQ(onlyError("[machine.work]\nG54.1P1 = [0.0, 0.0, 0.0]\n"),
            "machine.toml:2:1: error[NCC0303]: 'G54' is a table: write additional work offsets "
            "in quotes, \"G54.1P1\" = [...] (an unquoted dot makes a TOML sub-table)");
  EXPECT_EQ(onlyError("[machine.work]\n\"G54.1P301\" = [0.0, 0.0, 0.0]\n"),
            "machine.toml:2:1: error[NCC0306]: work offset number in 'G54.1P301' must be 1 to "
            "300");
  EXPECT_EQ(onlyError("[machine.work]\n\"G54.1P1\" = [0.0, 0.0, 0.0]\nG54_1P1 = [1.0, 0.0, 0.0]\n"),
            "machine.toml:3:1: error[NCC0306]: work offset G54.1P1 is given twice");
  EXPECT_EQ(onlyError("[machine.work]\nG55 = [0.0, \"a\", 0.0]\n"),
            "machine.toml:2:13: error[NCC0303]: wrong type for 'G55': expected a number, found a "
            "string");
}

TEST(MachineFile, AxisLimitErrors) {
  EXPECT_EQ(onlyError("[machine.axis.X]\nmax_speed = 1.0\n"),
            "machine.toml:2:1: error[NCC0302]: unknown key 'max_speed' in [machine.axis.X]");
  EXPECT_EQ(onlyError("[machine.axis.X]\nmin_travel = 10.0\nmax_travel = -10.0\n"),
            "machine.toml:1:1: error[NCC0306]: min_travel 10 of X must be below max_travel -10");
  EXPECT_EQ(onlyError("[machine.axis.Y]\nmax_jerk = 0.0\n"),
            "machine.toml:2:12: error[NCC0306]: 'max_jerk' of Y must be at least 1 and at most "
            "1e+09, not 0");
  EXPECT_EQ(onlyError("[machine.params]\nsoftware_limits = { X = [-1.0, 1.0] }\n"
                      "[machine.axis.X]\nmax_travel = 5.0\n"),
            "machine.toml:4:1: error[NCC0306]: travel limits of X are given twice: in "
            "'software_limits' and in [machine.axis.X]");
  EXPECT_EQ(onlyError("[machine]\nipo_cycle = 0.0\n"),
            "machine.toml:2:13: error[NCC0306]: 'ipo_cycle' must be at least 0.0001 and at most "
            "0.1 s, not 0");
  EXPECT_EQ(onlyError("[machine]\ncorner_tolerance = -0.1\n"),
            "machine.toml:2:20: error[NCC0306]: 'corner_tolerance' must be 0 or at least 1e-06 and "
            "at most 10 mm, not -0.1");
  EXPECT_EQ(onlyError("[machine]\nchord_tolerance = -0.001\n"),
            "machine.toml:2:19: error[NCC0306]: 'chord_tolerance' must be at least 1e-06 and at "
            "most 1 mm, not -0.001");
  EXPECT_EQ(onlyError("[machine]\nlookahead_segments = 8\n"),
            "machine.toml:2:22: error[NCC0306]: 'lookahead_segments' must be at least 16 and at "
            "most 16384, not 8");
  EXPECT_EQ(onlyError("[machine]\nlookahead_segments = 16385\n"),
            "machine.toml:2:22: error[NCC0306]: 'lookahead_segments' must be at least 16 and at "
            "most 16384, not 16385");
  EXPECT_EQ(onlyError("[machine]\nlookahead_segments = 100.5\n"),
            "machine.toml:2:22: error[NCC0303]: wrong type for 'lookahead_segments': expected an "
            "integer, found a float");
}

TEST(MachineFile, ModuloAxisMustBeRotary) {
  EXPECT_EQ(onlyError("[machine.params]\nmodulo_axes = [\"X\"]\n"),
            "machine.toml:2:15: error[NCC0306]: modulo axis 'X' is not a rotary axis (see "
            "'rotary_axes')");
}

TEST(MachineFile, ReportsEveryErrorOfAFile) {
  Result r = parse(R"([machine]
axes = ["X", "Y", "Z"]
bogus = 1
[machine.params]
peck_return = "far"
nope = 1
[start]
position = { W = 1.0 }
)");
  EXPECT_FALSE(r.machine);
  ASSERT_EQ(r.errors.size(), 4u);
  EXPECT_NE(r.errors[0].find("machine.toml:3:1: error[NCC0302]"), std::string::npos);
  EXPECT_NE(r.errors[1].find("machine.toml:5:15: error[NCC0303]"), std::string::npos);
  EXPECT_NE(r.errors[2].find("machine.toml:6:1: error[NCC0302]"), std::string::npos);
  EXPECT_NE(r.errors[3].find("machine.toml:8:14: error[NCC0304]"), std::string::npos);
}

// Bad input never crashes: every prefix and many byte mutations of a valid file either load
// or are rejected with at least one located diagnostic.
TEST(MachineFile, MutatedInputNeverCrashes) {
  const std::string valid = R"([machine]
axes = ["X", "Y", "Z", "C"]
diameter_axes = ["X"]
[machine.offsets]
H1 = 100.0
T1 = { x = 0.0, z = 0.0, radius = 0.4, tip = 3 }
[machine.work]
G54 = [0.0, 0.0, 0.0, 0.0]
[machine.params]
software_limits = { C = [-10.0, 10.0] }
reference_point_1 = { X = 0.0 }
[start]
position = { X = 0.0, Y = 0.0, Z = 0.0, C = 0.0 }
)";
  const char replacements[] = {'[',  ']',  '{', '}', '"', '=',   ',',
                               '\n', '\0', 'x', '9', '.', '\xff'};
  size_t loaded = 0, rejected = 0;
  for (size_t i = 0; i <= valid.size(); ++i) {
    for (int variant = 0; variant < 14; ++variant) {
      std::string text = valid;
      if (variant == 13)
        text = valid.substr(0, i);
      else if (i < text.size())
        text[i] = replacements[variant];
      SourceManager sources;
      DiagnosticEngine diags(&sources);
      auto m = parseMachineFile(text, "fuzz.toml", sources, diags);
      if (m) {
        ++loaded;
        EXPECT_FALSE(diags.hasErrors());
      } else {
        ++rejected;
        ASSERT_TRUE(diags.hasErrors()) << text;
      }
    }
  }
  EXPECT_GT(loaded, 0u);
  EXPECT_GT(rejected, 0u);
}

}  // namespace
}  // namespace ncc
