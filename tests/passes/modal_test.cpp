// Modal groups, the same-group policies, decimal-point rules, M/S/T, dwell, path control.
#include "expect_moves.h"

namespace ncc::passes::test {
namespace {

const std::vector<std::string> kXYZ = {"X", "Y", "Z"};

TEST(Modal, SameGroupPolicyLastWinsByParameter) {
  Lowered r = lower(Dialect::FanucM, "G01 X10. F100.\nG90 G91 X5.\n",
                xyzMachine("same_group_in_block = \"last_wins\"\ndecimal_point = \"standard\""));
  expectMoves(r, kXYZ, {{"line", {{"X", 10}}}, {"line", {{"X", 15}}}});
  EXPECT_EQ(r.blocks[1].modal.distance, ir::DistanceMode::Incremental);
}

TEST(Modal, PerWordDistanceModeKeepsTheLastCode) {
  Lowered r = lower(Dialect::MazakM, "G91 X1. G90 Y2.\nX3.\n");
  expectMoves(r, kXYZ, {{"rapid", {{"X", 1}, {"Y", 2}}}, {"rapid", {{"X", 3}, {"Y", 2}}}});
  EXPECT_EQ(r.blocks[1].modal.distance, ir::DistanceMode::Absolute);
}

TEST(Modal, DecimalPointAndIntegerAddresses) {
  Lowered r = lower(Dialect::MazakM, "G01 X10 Y10. F100 S1200.5 T3\nM30\n");
  expectMoves(r, kXYZ, {{"line", {{"X", 0.01}, {"Y", 10}}, {}, false, 100}}, 0.001,
              "1:5: warning[NCC2034]: 1 coordinate word without a decimal point is read as least "
              "input increments (the first: X10 = 0.01 mm) in a program that also writes decimal "
              "points; write the point (`Z3.`) for whole units, or set decimal_point = "
              "\"calculator\"\n");
  EXPECT_EQ(r.blocks[0].modal.spindle_speed, 1200.0);  // Mazak drops the fraction of S
  EXPECT_EQ(r.blocks[0].modal.tool, 3);
}

TEST(Modal, MachineFunctionsInOrder) {
  Lowered r = lower(Dialect::FanucM, "G00 X10. S500 M03 M08 M05\nT2 M06\nM01\nM123\nM02\n");
  ASSERT_EQ(r.diagText(), "");
  using K = ir::MachineFunction::Kind;
  const auto& ops = r.blocks[0].ops;
  ASSERT_EQ(ops.size(), 5u);
  EXPECT_EQ(std::get<ir::MachineFunction>(ops[0]).kind, K::SpindleSpeed);
  EXPECT_EQ(std::get<ir::MachineFunction>(ops[0]).value, 500.0);
  EXPECT_EQ(std::get<ir::MachineFunction>(ops[1]).kind, K::SpindleCW);
  EXPECT_EQ(std::get<ir::MachineFunction>(ops[2]).kind, K::CoolantOn);
  EXPECT_TRUE(std::holds_alternative<ir::Rapid>(ops[3]));
  EXPECT_EQ(std::get<ir::MachineFunction>(ops[4]).kind, K::SpindleStop);
  EXPECT_EQ(std::get<ir::MachineFunction>(r.blocks[1].ops[0]).kind, K::ToolSelect);
  EXPECT_EQ(std::get<ir::MachineFunction>(r.blocks[1].ops[0]).code, 2);
  EXPECT_EQ(std::get<ir::MachineFunction>(r.blocks[1].ops[1]).kind, K::ToolChange);
  EXPECT_EQ(std::get<ir::MachineFunction>(r.blocks[2].ops[0]).kind, K::OptionalStop);
  EXPECT_EQ(std::get<ir::MachineFunction>(r.blocks[3].ops[0]).kind, K::OtherM);
  EXPECT_EQ(std::get<ir::MachineFunction>(r.blocks[3].ops[0]).code, 123);
  EXPECT_EQ(std::get<ir::MachineFunction>(r.blocks[4].ops[0]).kind, K::ProgramEnd);
  EXPECT_TRUE(r.program_end);
}

TEST(Modal, MazakKeepsTheLastFourMCodes) {
  Lowered r = lower(Dialect::MazakM, "M10 M11 M12 M13 M14\n");
  ASSERT_EQ(r.diags.size(), 1u);
  EXPECT_EQ(r.diags[0].severity, Severity::Warning);
  ASSERT_EQ(r.blocks[0].ops.size(), 4u);
  EXPECT_EQ(std::get<ir::MachineFunction>(r.blocks[0].ops[0]).code, 11);
}

TEST(Modal, ExactStopOneShotAndModes) {
  Lowered r = lower(Dialect::FanucM, "G01 X1. F100.\nG09 X2.\nX3.\nG61 X4.\nG64 X5.\nG63\nG62\n");
  ASSERT_EQ(r.diagText(), "");
  EXPECT_FALSE(r.blocks[0].exact_stop);
  EXPECT_TRUE(r.blocks[1].exact_stop);
  EXPECT_EQ(r.blocks[1].modal.path, ir::PathControl::Continuous);
  EXPECT_FALSE(r.blocks[2].exact_stop);
  EXPECT_TRUE(r.blocks[3].exact_stop);
  EXPECT_EQ(r.blocks[3].modal.path, ir::PathControl::ExactStop);
  EXPECT_FALSE(r.blocks[4].exact_stop);
  EXPECT_EQ(r.blocks[5].modal.path, ir::PathControl::Tapping);
  EXPECT_EQ(r.blocks[6].modal.path, ir::PathControl::CornerOverride);
}

TEST(Modal, DwellInRevolutionsUnderG95) {
  Lowered r = lower(Dialect::MazakM, "G95 G04 X2.\nG94 G04 X2.\n");
  ASSERT_EQ(r.diagText(), "");
  EXPECT_TRUE(std::get<ir::Dwell>(r.blocks[0].ops[0]).revolutions);
  EXPECT_FALSE(std::get<ir::Dwell>(r.blocks[1].ops[0]).revolutions);
  Lowered f = lower(Dialect::FanucM, "G95 G04 X2.\n");
  EXPECT_FALSE(std::get<ir::Dwell>(f.blocks[0].ops[0]).revolutions);
}

TEST(Modal, CancelCodesOfInactiveFunctionsAreAccepted) {
  Lowered r = lower(Dialect::FanucM, "G40 G80 G49 G50 G67 G69 G15 G50.1 G97 G98 G23\n");
  EXPECT_EQ(r.diagText(), "");
  EXPECT_EQ(r.blocks.size(), 1u);
}

}  // namespace
}  // namespace ncc::passes::test
