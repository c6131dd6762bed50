// The default machine and the configuration hash.
#include "ncc/machine/machine_config.h"

#include "gtest/gtest.h"
#include "ncc/machine/machine_file.h"

namespace ncc {
namespace {

TEST(DefaultMachine, IsAThreeAxisMetricMill) {
  MachineConfig m = defaultMachine();
  ASSERT_EQ(m.axisCount(), 3);
  EXPECT_EQ(m.axes[0].name, "X");
  EXPECT_EQ(m.axes[1].name, "Y");
  EXPECT_EQ(m.axes[2].name, "Z");
  for (const AxisConfig& a : m.axes) {
    EXPECT_EQ(a.kind, AxisKind::Linear);
    EXPECT_FALSE(a.diameter);
  }
  EXPECT_EQ(m.axisIndex("Y"), 1);
  EXPECT_EQ(m.axisIndex("A"), -1);
  ASSERT_EQ(m.work_offsets.size(), 6u);
  for (const char* g : {"G54", "G55", "G56", "G57", "G58", "G59"})
    EXPECT_EQ(m.work_offsets.at(g), zeroAxes()) << g;
  EXPECT_EQ(m.start_position, zeroAxes());
  EXPECT_TRUE(m.tool_offsets.length.empty());
  EXPECT_TRUE(m.params.all().empty());
  EXPECT_EQ(m.params.getString("reset_unit"), "G21");  // metric: the registry default
}

// The hash is written into bytecode files: it must not change between runs, builds or
// platforms. If this literal changes, the canonical serialisation changed (bump its version
// string "ncc-machine-1" and say so in docs/machine-file.md).
TEST(ConfigHash, DefaultMachineHasAFixedValue) {
  EXPECT_EQ(defaultMachine().configHash(), 0x9711b811c2d3544fULL);
}

TEST(ConfigHash, ChangesWithEveryCompileRelevantSetting) {
  const MachineConfig base = defaultMachine();
  const uint64_t h = base.configHash();
  auto differs = [&](auto&& change) {
    MachineConfig m = defaultMachine();
    change(m);
    return m.configHash() != h;
  };
  EXPECT_TRUE(differs([](MachineConfig& m) { m.tool_offsets.length[1] = 100.0; }));
  EXPECT_TRUE(differs([](MachineConfig& m) { m.tool_offsets.radius[1] = 5.0; }));
  EXPECT_TRUE(differs([](MachineConfig& m) { m.lathe_offsets.combined[1].tip = 3; }));
  EXPECT_TRUE(differs([](MachineConfig& m) { m.lathe_offsets.wear[2].x = 0.4; }));
  EXPECT_TRUE(differs([](MachineConfig& m) { m.lathe_offsets.edge[1].radius = 0.4; }));
  EXPECT_TRUE(differs([](MachineConfig& m) { m.work_offsets["G55"][0] = 1e-9; }));
  EXPECT_TRUE(differs([](MachineConfig& m) { m.work_offsets["G54.1P1"] = zeroAxes(); }));
  EXPECT_TRUE(differs([](MachineConfig& m) { m.start_position[2] = 100.0; }));
  EXPECT_TRUE(differs([](MachineConfig& m) { m.params.set("peck_return", 1.0); }));
  EXPECT_TRUE(
      differs([](MachineConfig& m) { m.params.set("decimal_point", std::string("standard")); }));
  EXPECT_TRUE(differs([](MachineConfig& m) { m.axes[0].diameter = true; }));
  EXPECT_TRUE(differs([](MachineConfig& m) { m.axes[2].kind = AxisKind::Rotary; }));
  EXPECT_TRUE(differs([](MachineConfig& m) { m.axes[0].max_travel = 500.0; }));
  EXPECT_TRUE(differs([](MachineConfig& m) { m.axes.pop_back(); }));
  // Run-time dynamics are read by the VM, not compiled in.
  EXPECT_FALSE(differs([](MachineConfig& m) { m.axes[0].max_jerk = 1.0; }));
  EXPECT_FALSE(differs([](MachineConfig& m) { m.ipo_cycle_seconds = 0.004; }));
  // -0.0 is the same setting as 0.0.
  EXPECT_FALSE(differs([](MachineConfig& m) { m.work_offsets["G54"][0] = -0.0; }));
}

TEST(ConfigHash, SameFileSameHash) {
  const char* text =
      "[machine]\naxes = [\"X\", \"Z\"]\n[machine.offsets]\nT1 = { x = 1.0 }\n"
      "[machine.params]\nreset_plane = \"G18\"\n";
  SourceManager sources;
  DiagnosticEngine diags(&sources);
  auto a = parseMachineFile(text, "a.toml", sources, diags);
  auto b = parseMachineFile(text, "b.toml", sources, diags);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->configHash(), b->configHash());
  EXPECT_NE(a->configHash(), defaultMachine().configHash());
}

}  // namespace
}  // namespace ncc
