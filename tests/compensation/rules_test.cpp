// The compensation pass's parameters and special cases beyond the corner rules (see
// corners_test.cpp): FANUC's corner move limit, G93 feeds, machine-space moves.
#include <algorithm>
#include <variant>

#include "compensation/compensation_pass.h"
#include "compensation_harness.h"
#include "gtest/gtest.h"

namespace ncc::passes::testing {
namespace {

using Side = ir::CutterComp::Side;

int movesOfLine(const std::string& moves, int line) {
  const std::string prefix = std::to_string(line) + ": ";
  int n = 0;
  for (size_t at = 0; (at = moves.find(prefix, at)) != std::string::npos; at += prefix.size())
    if (at == 0 || moves[at - 1] == '\n') ++n;
  return n;
}

CompProgram sharpTurn(double radius, double limit) {
  // Right of +X, then back up-left: an acute outer corner, turned by two extended vectors.
  CompProgram p;
  p.settings().corner_move_limit = limit;
  p.rapid(-10, 0).side(Side::Right, radius).line(0, 0).line(40, 0).line(0, 10).cancel()
      .line(-10, 10);
  return p;
}

TEST(CompensationRules, CornerMovesWithinTheLimitAreLeftOut) {
  // r = 0.004: the corner move between the two extended vectors changes X and Y by less than
  // 0.01 mm (FANUC No.5010 = 0.01): left out, the next move starts where the last one ended.
  const std::string kept = sharpTurn(0.004, 0.0).run(), dropped = sharpTurn(0.004, 0.01).run();
  EXPECT_EQ(movesOfLine(kept, 3), 2) << kept;
  EXPECT_EQ(movesOfLine(dropped, 3), 1) << dropped;
  // A larger tool's corner move stays.
  EXPECT_EQ(movesOfLine(sharpTurn(5, 0.01).run(), 3), 2);
}

TEST(CompensationRules, AMachineSpaceMoveRunsOnItsPointAndTheNextMoveTakesTheVectorUp) {
  // G28's last leg (machine space) while compensating: the move before ends perpendicular to
  // itself, the reference move runs as programmed, the next move starts from it.
  CompProgram p;
  p.rapid(0, -10).side(Side::Left, 2).line(0, 0).line(20, 0).machineRapid(50, 50).line(60, 50)
      .line(60, 70).cancel().line(70, 80);
  EXPECT_EQ(p.run(),
            "1: R 0.000 -10.000\n"
            "2: L 0.000 2.000\n"      // type A start-up: perpendicular to the next move
            "3: L 20.000 2.000\n"     // perpendicular to itself before the temporary cancel
            "4: R 50.000 50.000\n"    // on the programmed (machine) point
            "5: L 58.000 52.000\n"    // from there to the corner with the next move (inner)
            "6: L 58.000 70.000\n"    // cancel corner, outer, type A: perpendicular to Y70
            "7: L 70.000 80.000\n");
}

TEST(CompensationRules, TheWindowNeverHoldsMoreThanTheBlocksWithoutMotionThatKeepACorner) {
  // 10000 blocks without motion (M08) after a compensated move: past the limit (1) the tool
  // stops perpendicular and every block goes on at once, so the pass holds at most the move and
  // the limit's blocks, whatever follows.
  CompProgram p;
  p.rapid(0, -10).side(Side::Left, 5).line(0, 0).line(20, 0);
  for (int k = 0; k < 10000; ++k) p.still();
  p.line(20, 20).cancel().line(30, 30);
  struct Count : ir::BlockSink {
    void accept(ir::Block&&) override { ++n; }
    void finish() override {}
    size_t n = 0;
  } out;
  DiagnosticEngine diags;
  CompensationPass pass(out, Dialect::FanucM, diags);
  size_t in = 0, most_held = 0;
  for (const ir::Block& b : p.built()) {
    pass.accept(ir::Block(b));
    ++in;
    most_held = std::max(most_held, in - out.n);
  }
  pass.finish();
  EXPECT_EQ(out.n, in);
  EXPECT_LE(most_held, 3u);  // the held move's block, one block without motion, the one past it
}

TEST(CompensationRules, AStopPastTheLookAheadEndsWithACancelAndIsNotTakenIntoTheNextStart) {
  // G41 r = 2, two blocks without motion (past the limit: the tool stops at (20,2)), G40 alone,
  // a move off the plane, then a new start-up: nothing of the old stop point reaches it.
  CompProgram p;
  p.rapid(0, -10).side(Side::Left, 2).line(0, 0).line(20, 0).still().still().cancel().still()
      .side(Side::Left, 2).rapid(20, 0, 5).line(40, 0).line(40, 20).cancel().line(50, 30);
  EXPECT_EQ(p.run(),
            "1: R 0.000 -10.000\n"
            "2: L 0.000 2.000\n"
            "3: L 20.000 2.000\n"    // stopped perpendicular past the look-ahead
            "7: R 20.000 0.000\n"    // G41 with Z alone: no vector yet (type A), Z at the point
            "8: L 38.000 2.000\n"    // a fresh start-up (inner corner with Y20.)
            "9: L 38.000 20.000\n"
            "10: L 50.000 30.000\n");
}

TEST(CompensationRules, G39AfterG00WithoutAFeedIsPs0011AtTheG39Block) {
  // G39's arc runs at the modal F even after G00 (FANUC §5.6); none was programmed.
  CompProgram p;
  p.rapid(0, -10).side(Side::Left, 5).rapid(0, 0).rapid(40, 0)
      .special(ir::CutterComp::Special::CornerArc).still().rapid(40, -30).cancel().rapid(50, -40);
  p.run();
  ASSERT_EQ(p.diagnostics().diagnostics().size(), 1u);
  const Diagnostic& d = p.diagnostics().diagnostics()[0];
  EXPECT_EQ(d.code, "PS0011");
  EXPECT_EQ(d.location.line, 4u);
  EXPECT_NE(d.message.find("G39's corner arc after G00 runs at the modal F"), std::string::npos)
      << d.message;
}

TEST(CompensationRules, TooManyBlocksWithoutMotionBeforeAnInnerCornerIsNcc2128AtTheMove) {
  CompProgram p;
  p.rapid(-20, 0).side(Side::Left, 5).line(0, 0).line(40, 0).still().still().line(40, 30)
      .cancel().line(40, 40);
  p.run();
  ASSERT_EQ(p.diagnostics().diagnostics().size(), 1u);
  const Diagnostic& d = p.diagnostics().diagnostics()[0];
  EXPECT_EQ(d.code, "NCC2128");
  EXPECT_EQ(d.location.line, 6u);
  EXPECT_NE(d.message.find("2 blocks without motion in the XY plane before this move (at most 1 "
                           "keep the corner)"),
            std::string::npos) << d.message;
  EXPECT_NE(d.message.find("this inner corner would be cut into"), std::string::npos);
}

CompProgram shortChamfer(bool avoidance) {
  // G41 r = 5: along +X, a 1 mm 45-degree chamfer, then up. The chamfer's offset runs backwards
  // from (17.929,5) to (16,3.071): an interference.
  CompProgram p;
  p.settings().interference_avoidance = avoidance;
  p.rapid(0, -10).side(Side::Left, 5).line(0, 0).line(20, 0).line(21, 1).line(21, 20).cancel()
      .line(30, 30);
  return p;
}

TEST(CompensationRules, AnInterferenceIsAnAlarmUnlessAvoidanceIsOn) {
  CompProgram alarm = shortChamfer(false);
  alarm.run();
  ASSERT_TRUE(alarm.diagnostics().hasErrors());
  EXPECT_EQ(alarm.diagnostics().diagnostics()[0].code, "PS0041");
  EXPECT_EQ(alarm.diagnostics().diagnostics()[0].location.line, 4u);

  // Avoidance (FANUC CAV = 1): the moves before and after the chamfer are joined where their
  // offsets y = 5 and x = 16 meet; the chamfer runs no way in the plane; a warning says so.
  CompProgram avoided = shortChamfer(true);
  EXPECT_EQ(avoided.run(),
            "1: R 0.000 -10.000\n"
            "2: L 0.000 5.000\n"
            "3: L 16.000 5.000\n"
            "4: L 16.000 5.000\n"
            "5: L 16.000 20.000\n"   // cancel corner, outer, type A: perpendicular
            "6: L 30.000 30.000\n");
  ASSERT_EQ(avoided.diagnostics().diagnostics().size(), 1u);
  const Diagnostic& d = avoided.diagnostics().diagnostics()[0];
  EXPECT_EQ(d.severity, Severity::Warning);
  EXPECT_EQ(d.code, "PS0041");
  EXPECT_EQ(d.location.line, 4u);
  EXPECT_NE(d.message.find("interference avoided"), std::string::npos) << d.message;
}

TEST(CompensationRules, AvoidanceCannotJoinParallelWallsSoAGrooveStaysAnAlarm) {
  CompProgram p;
  p.settings().interference_avoidance = true;
  p.rapid(-10, 10).side(Side::Left, 5).line(0, 0).line(20, 0).line(20, -10).line(23, -10)
      .line(23, 0).line(40, 0).cancel().line(50, 10);
  p.run();
  ASSERT_TRUE(p.diagnostics().hasErrors());
  EXPECT_EQ(p.diagnostics().diagnostics()[0].code, "PS0041");
}

}  // namespace
}  // namespace ncc::passes::testing
