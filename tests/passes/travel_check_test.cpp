// TravelCheckPass: machine-space targets against the axes' travel limits, with the dialect's
// alarm numbers (`ncc check`).
#include "ncc/passes/travel_check.h"

#include "gtest/gtest.h"

namespace ncc::passes {
namespace {

struct Count : ir::BlockSink {
  void accept(ir::Block) override { ++blocks; }
  void finish() override {}
  int blocks = 0;
};

ir::Block blockTo(ir::Operation op, uint32_t line) {
  ir::Block b;
  b.loc = SourceLocation{1, line, 1};
  b.ops.push_back(std::move(op));
  return b;
}

MachineConfig limitedMachine() {
  MachineConfig m = defaultMachine();
  m.axes[0].min_travel = -10.0;  // X
  m.axes[0].max_travel = 500.0;
  m.axes[2].min_travel = -300.0;  // Z
  m.axes[2].max_travel = 0.0;
  return m;
}

TEST(TravelCheck, ReportsTheFirstAxisBeyondItsLimitsWithTheDialectsAlarm) {
  MachineConfig machine = limitedMachine();
  DiagnosticEngine diags;
  Count out;
  TravelCheckPass pass(out, machine, Dialect::FanucM, diags);
  AxisValues inside{100.0, 0.0, -10.0}, above{500.5, 0.0, -10.0}, below{0.0, 0.0, -300.5};
  pass.accept(blockTo(ir::Rapid{inside, ir::Space::Machine}, 1));
  pass.accept(blockTo(ir::Linear{above, ir::Space::Machine, 100.0}, 2));
  ir::Arc arc;
  arc.to = below;
  arc.space = ir::Space::Machine;
  pass.accept(blockTo(arc, 3));
  pass.finish();
  EXPECT_EQ(out.blocks, 3);  // the pass reports, it does not drop blocks
  ASSERT_EQ(diags.diagnostics().size(), 2u);
  EXPECT_EQ(diags.diagnostics()[0].code, "OT0500");
  EXPECT_EQ(diags.diagnostics()[0].location.line, 2u);
  EXPECT_EQ(diags.diagnostics()[0].message,
            "+ overtravel: the target X500.500 mm (machine coordinates) is beyond the travel "
            "limit 500.000 mm");
  EXPECT_EQ(diags.diagnostics()[1].code, "OT0501");
  EXPECT_EQ(diags.diagnostics()[1].location.line, 3u);
}

TEST(TravelCheck, AlarmNumbersAreDataPerDialect) {
  EXPECT_EQ(travelAlarms(Dialect::FanucM).positive, "OT0500");
  EXPECT_EQ(travelAlarms(Dialect::FanucM).negative, "OT0501");
  EXPECT_EQ(travelAlarms(Dialect::SiemensIsoM).positive, "10720");
  EXPECT_EQ(travelAlarms(Dialect::SiemensIsoM).negative, "10720");
  EXPECT_EQ(travelAlarms(Dialect::MazakM).positive, "NCC2090");
}

}  // namespace
}  // namespace ncc::passes
