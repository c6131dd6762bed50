// G31 skip (lowering_skip.cpp): the IR Skip it becomes, the feed rules of each dialect, and
// the blocks after it that need where it stopped (the compiler stops there: LowerResult::
// needs_run_time; the VM knows the position) or do not (absolute words).
#include <string>

#include "gtest/gtest.h"
#include "lowering_harness.h"
#include "ncc/ir/ir.h"

namespace ncc::passes::test {
namespace {

const ir::Skip* skipOf(const Lowered& r, size_t block) {
  if (block >= r.blocks.size() || r.blocks[block].ops.empty()) return nullptr;
  return std::get_if<ir::Skip>(&r.blocks[block].ops[0]);
}

TEST(Skip, G31BecomesASkipMoveWithTheFeedAndTheSkipVariables) {
  Lowered r = lower(Dialect::FanucM, "G90 G00 X10. Y10. Z10.\nG31 Z-50. F100.\nG00 Z20.\nM30\n");
  EXPECT_EQ(r.diagText(), "");
  ASSERT_EQ(r.blocks.size(), 4u);
  const ir::Skip* s = skipOf(r, 1);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->space, ir::Space::Machine);
  EXPECT_EQ(s->to[0], 10.0);
  EXPECT_EQ(s->to[1], 10.0);
  EXPECT_EQ(s->to[2], -50.0);
  EXPECT_EQ(s->feed, 100.0);
  EXPECT_FALSE(s->feed_per_rev);
  EXPECT_EQ(s->first_variable, 5061u);  // the dialect's SkipPosition range
  EXPECT_FALSE(s->inch_variables);
  // G31 is one-shot: the block after it is a rapid again, and FANUC keeps F modal.
  EXPECT_NE(std::get_if<ir::Rapid>(&r.blocks[2].ops[0]), nullptr);
  EXPECT_EQ(r.blocks[2].modal.feed, 100.0);
}

TEST(Skip, TheSkipMoveUsesTheFrameOfItsBlock) {
  Lowered r = lower(Dialect::FanucM, "G52 X100.\nG90 G00 X0 Y0 Z0\nG31 G91 X5. F60.\nG90 G00 X0\n");
  EXPECT_EQ(r.diagText(), "");
  const ir::Skip* s = skipOf(r, 2);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->to[0], 105.0);  // machine coordinates after the work-to-machine pass
  EXPECT_EQ(r.blocks[2].frame.total()[0], 100.0);  // the VM stores stop - frame in #5061
}

TEST(Skip, FanucTakesTheModalFeedAndNeedsOne) {
  Lowered r = lower(Dialect::FanucM, "G01 X1. F250.\nG31 X20.\n");
  const ir::Skip* s = skipOf(r, 1);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->feed, 250.0);
  Lowered none = lower(Dialect::FanucM, "G31 X20.\n");
  EXPECT_NE(none.diagText().find("error[PS0011]"), std::string::npos) << none.diagText();
}

TEST(Skip, MazakNeedsItsOwnFAndKeepsTheModalF) {
  // §4.10: F missing -> K41 (0: error); the modal F is not changed.
  Lowered r = lower(Dialect::MazakM, "G01 X1. F250.\nG31 X20. F40.\nG01 X30.\n");
  EXPECT_EQ(r.diagText(), "");
  const ir::Skip* s = skipOf(r, 1);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->feed, 40.0);
  ASSERT_EQ(r.blocks.size(), 3u);
  EXPECT_EQ(std::get<ir::Linear>(r.blocks[2].ops[0]).feed, 250.0);
  Lowered none = lower(Dialect::MazakM, "G01 X1. F250.\nG31 X20.\n");
  EXPECT_NE(none.diagText().find("G31 needs its own F"), std::string::npos) << none.diagText();
}

TEST(Skip, MazakMultiStepSkipCodesAreSkipMoves) {
  for (const char* code : {"G31.1", "G31.2", "G31.3"}) {
    Lowered r = lower(Dialect::MazakM, std::string(code) + " Z-10. F50.\n");
    EXPECT_EQ(r.diagText(), "") << code;
    EXPECT_NE(skipOf(r, 0), nullptr) << code;
  }
}

TEST(Skip, SiemensIsoHasNoSkipVariable) {
  Lowered r = lower(Dialect::SiemensIsoM, "G31 Z-10. F50.\n");
  EXPECT_EQ(r.diagText(), "");
  const ir::Skip* s = skipOf(r, 0);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->first_variable, 0u);  // $AA_MW is latched, not a numbered variable
}

TEST(Skip, InchProgramsGetTheSkipPositionInInches) {
  Lowered r = lower(Dialect::FanucM, "G20 G31 Z-1. F10.\n");
  const ir::Skip* s = skipOf(r, 0);
  ASSERT_NE(s, nullptr);
  EXPECT_TRUE(s->inch_variables);
  EXPECT_NEAR(s->to[2], -25.4, 1e-9);
}

TEST(Skip, G31WithoutAnAxisWordIsAnError) {
  Lowered r = lower(Dialect::FanucM, "G31 F100.\n");
  EXPECT_NE(r.diagText().find("error[NCC2080]"), std::string::npos) << r.diagText();
}

TEST(Skip, AnIncrementalWordOnASkippedAxisNeedsTheRunTime) {
  Lowered r = lower(Dialect::FanucM, "G31 Z-50. F100.\nG91 G00 Z5.\n");
  EXPECT_EQ(r.diagText(), "");
  ASSERT_TRUE(r.run_time);
  EXPECT_EQ(r.run_time->error, eval::EvalError::RunTimeValue);
  EXPECT_EQ(r.run_time->message, "the incremental Z starts from the position where G31 stopped");
  EXPECT_EQ(r.run_time->loc.line, 2u);
  EXPECT_EQ(r.run_time->loc.column, 9u);
  EXPECT_EQ(r.blocks.size(), 1u);  // the skip; nothing of the block that needs the run time
}

TEST(Skip, AMoveThatKeepsASkippedAxisNeedsTheRunTime) {
  Lowered r = lower(Dialect::FanucM, "G31 Z-50. F100.\nG00 X20.\n");
  ASSERT_TRUE(r.run_time);
  EXPECT_EQ(r.run_time->message, "this move keeps Z where G31 stopped");
  EXPECT_EQ(r.run_time->loc.line, 2u);
  Lowered g92 = lower(Dialect::FanucM, "G31 Z-50. F100.\nG92 Z0\n");
  ASSERT_TRUE(g92.run_time);
  EXPECT_EQ(g92.run_time->message, "G92 Z sets the shift from the position where G31 stopped");
}

// The VM's block preparation: the running machine says where G31 stopped.
struct StoppedAt final : RunTimeState {
  AxisValues at{};
  bool running() const override { return true; }
  AxisValues machinePosition() const override { return at; }
  double seconds() const override { return 0.0; }
  eval::Value skipVariable(int64_t) const override { return eval::Value::none(); }
  std::optional<eval::Value> machineVariable(int64_t) const override { return std::nullopt; }
};

TEST(Skip, AtRunTimeTheSkippedAxesStartWhereG31Stopped) {
  StoppedAt machine;
  machine.at = {10.0, 10.0, -42.5};
  Lowered r = lower(Dialect::FanucM, "G90 G00 X10. Y10. Z10.\nG31 Z-50. F100.\nG91 G00 Z5.\nX1.\n",
                    "", &machine);
  EXPECT_EQ(r.diagText(), "");
  EXPECT_FALSE(r.run_time);
  ASSERT_EQ(r.blocks.size(), 4u);
  const auto* up = std::get_if<ir::Rapid>(&r.blocks[2].ops[0]);
  ASSERT_NE(up, nullptr);
  EXPECT_EQ(up->to[2], -37.5);
  const auto* side = std::get_if<ir::Rapid>(&r.blocks[3].ops[0]);
  ASSERT_NE(side, nullptr);
  EXPECT_EQ(side->to[0], 11.0);
  EXPECT_EQ(side->to[2], -37.5);
}

TEST(Skip, AbsoluteWordsMakeTheAxisKnownAgain) {
  // Retract absolutely, then anything: the skipped axis is known from the retract on.
  Lowered r = lower(Dialect::FanucM,
                    "G31 X30. Z-50. F100.\nG00 X0 Z20.\nG91 G00 Z5.\nG90 G28 Z0\nG04 X1.\n");
  EXPECT_EQ(r.diagText(), "");
  EXPECT_EQ(r.blocks.size(), 5u);
  // Words that are no positions (a dwell time, G10 values) do not depend on the skip.
  Lowered d = lower(Dialect::FanucM, "G31 X30. F100.\nG04 X1.\nG10 L2 P1 X5.\nM30\n");
  EXPECT_EQ(d.diagText(), "");
}

TEST(Skip, AnAxisTheSkipDoesNotMoveStaysKnown) {
  Lowered r = lower(Dialect::FanucM, "G00 Z5.\nG31 Z5. X10. F100.\nG91 G00 Z1.\n");
  // X moved (unknown), Z did not: an incremental Z is fine, but the move keeps X.
  ASSERT_TRUE(r.run_time);
  EXPECT_EQ(r.run_time->message, "this move keeps X where G31 stopped");
  Lowered fine = lower(Dialect::FanucM, "G00 Z5.\nG31 Z5. X10. F100.\nG90 G00 X0\nG91 Z1.\n");
  EXPECT_EQ(fine.diagText(), "");
}

}  // namespace
}  // namespace ncc::passes::test
