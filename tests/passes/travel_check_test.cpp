// TravelCheckPass: machine-space targets against the axes' travel limits, with the dialect's
// alarm numbers (`ncc check`).
#include "ncc/passes/travel_check.h"

#include "gtest/gtest.h"

namespace ncc::passes {
namespace {

struct Count : ir::BlockSink {
  void accept(ir::Block&&) override { ++blocks; }
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
  pass.accept(blockTo(ir::Rapid{inside, ir::Space::Machine}, 3));
  ir::Arc arc;  // a helix around (50, 0) from X100 down to Z-300.5
  arc.to = below;
  arc.center = AxisValues{50.0, 0.0, 0.0};
  arc.space = ir::Space::Machine;
  pass.accept(blockTo(arc, 4));
  pass.finish();
  EXPECT_EQ(out.blocks, 4);  // the pass reports, it does not drop blocks
  ASSERT_EQ(diags.diagnostics().size(), 2u);
  EXPECT_EQ(diags.diagnostics()[0].code, "OT0500");
  EXPECT_EQ(diags.diagnostics()[0].location.line, 2u);
  EXPECT_EQ(diags.diagnostics()[0].message,
            "+ overtravel (stored stroke limit): axis X would reach 500.5, beyond max_travel 500");
  EXPECT_EQ(diags.diagnostics()[1].code, "OT0501");
  EXPECT_EQ(diags.diagnostics()[1].location.line, 4u);
  EXPECT_EQ(diags.diagnostics()[1].message,
            "- overtravel (stored stroke limit): axis Z would reach -300.5, beyond min_travel -300");
}

TEST(TravelCheck, AnArcThatBulgesPastALimitIsReportedLikeTheRunDoes) {
  // Clockwise around (0, 0) from (-5, 0) to (5, 0) passes (0, 5): with Y's travel ending at
  // 4 the arc leaves it while its end points do not.
  MachineConfig machine = defaultMachine();
  machine.axes[1].max_travel = 4.0;
  DiagnosticEngine diags;
  Count out;
  TravelCheckPass pass(out, machine, Dialect::SiemensIsoM, diags);
  pass.accept(blockTo(ir::Rapid{AxisValues{-5.0, 0.0, 0.0}, ir::Space::Machine}, 1));
  ir::Arc arc;
  arc.to = AxisValues{5.0, 0.0, 0.0};
  arc.space = ir::Space::Machine;
  arc.clockwise = true;
  pass.accept(blockTo(arc, 2));
  pass.finish();
  ASSERT_EQ(diags.diagnostics().size(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].code, "10720");
  EXPECT_EQ(diags.diagnostics()[0].location.line, 2u);
  EXPECT_EQ(diags.diagnostics()[0].message,
            "+ overtravel (stored stroke limit): axis Y would reach 5, beyond max_travel 4");
}

TEST(TravelCheck, AlarmNumbersAreTheVmsPerDialect) {
  // One table for compile time and run time (ncc/machine/travel.h).
  EXPECT_EQ(travelAlarmCodes(Dialect::FanucM).plus, "OT0500");
  EXPECT_EQ(travelAlarmCodes(Dialect::FanucM).minus, "OT0501");
  EXPECT_EQ(travelAlarmCodes(Dialect::SiemensIsoM).plus, "10720");
  EXPECT_EQ(travelAlarmCodes(Dialect::MazakM).plus, "NCC7210");
}

}  // namespace
}  // namespace ncc::passes
