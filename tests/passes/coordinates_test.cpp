// Work offsets, G92/G92.1, G52, G53, G10, tool length, reference returns (fanuc-m defaults
// unless a test says otherwise).
#include "expect_moves.h"

namespace ncc::passes::test {
namespace {

const std::vector<std::string> kXYZ = {"X", "Y", "Z"};

std::string machine(const std::string& params = "", const std::string& offsets = "") {
  return "[machine]\naxes = [\"X\", \"Y\", \"Z\"]\n[machine.offsets]\n" + offsets +
         "[machine.work]\nG54 = [10.0, 0.0, 0.0]\nG55 = [100.0, 0.0, 0.0]\n"
         "\"G54.1P2\" = [0.0, 50.0, 0.0]\n[machine.params]\n" + params +
         "\n[start]\nposition = { X = 0.0, Y = 0.0, Z = 0.0 }\n";
}

TEST(Coordinates, WorkOffsetsAndFrame) {
  Lowered r = lower(Dialect::FanucM, "G00 X1.\nG55 X1.\nG54.1 P2 X1.\n", machine());
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 11}, {"Y", 0}}}, {"rapid", {{"X", 101}}}, {"rapid", {{"X", 1}, {"Y", 0}}}});  // Y not programmed: it stays
  EXPECT_EQ(r.blocks[1].modal.work_offset, "G55");
  EXPECT_EQ(r.blocks[2].modal.work_offset, "G54.1P2");
  EXPECT_EQ(r.blocks[2].frame.work_offset[1], 50.0);
}

TEST(Coordinates, FanucLocalShiftAppliesInEveryWorkSystem) {
  Lowered r = lower(Dialect::FanucM, "G52 X5.\nG00 X0\nG55 X0\n", machine());
  expectMoves(r, kXYZ, {{"rapid", {{"X", 15}}}, {"rapid", {{"X", 105}}}});
}

TEST(Coordinates, G92AndIncrementalG92) {
  Lowered r = lower(Dialect::FanucM, "G00 X20.\nG92 X0\nX5.\nG91 G92 X-5.\nG90 X0\n", machine());
  // G54 X10: X20 is machine 30. G92 X0 there: shift 20, so X5 is machine 35. G91 G92 X-5
  // makes the current point 5 - 5 = 0, so the final G90 X0 does not move.
  expectMoves(r, kXYZ, {{"rapid", {{"X", 30}}}, {"rapid", {{"X", 35}}}});
  EXPECT_EQ(r.blocks.back().frame.shift[0], 25.0);
}

TEST(Coordinates, G10L2WritesTheActiveOffsetImmediatelyOnFanuc) {
  Lowered r = lower(Dialect::FanucM, "G10 L2 P1 X20.\nG00 X1.\nG10 L2 P0 Y3.\nY0\n", machine());
  expectMoves(r, kXYZ, {{"rapid", {{"X", 21}}}, {"rapid", {{"X", 21}, {"Y", 3}}}});
}

TEST(Coordinates, G10L11WearAddsToTheLength) {
  Lowered r = lower(Dialect::FanucM, "G10 L10 P1 R100.\nG10 L11 P1 R-0.5\nG43 Z0 H1\n", machine());
  expectMoves(r, kXYZ, {{"rapid", {{"Z", 99.5}}}});
  EXPECT_EQ(r.blocks.back().modal.length_offset_h, 1);
  EXPECT_EQ(r.blocks.back().frame.tool_length[2], 99.5);
}

TEST(Coordinates, G43HAloneMovesTheLengthAxis) {
  Lowered r = lower(Dialect::FanucM, "G43 H1\nG49\n", machine("", "H1 = 20.0\n"));
  expectMoves(r, kXYZ, {{"rapid", {{"Z", 20}}}, {"rapid", {{"Z", 0}}}});
}

TEST(Coordinates, SiemensLengthChangeWaitsForTheAxis) {
  Lowered r = lower(Dialect::SiemensIsoM, "G43 H1\nZ5.\n", machine("", "H1 = 20.0\n"));
  expectMoves(r, kXYZ, {{"rapid", {{"Z", 25}}}});
}

TEST(Coordinates, G53IsIgnoredInG91OnFanuc) {
  Lowered r = lower(Dialect::FanucM, "G91 G53 X10.\n", machine());
  ASSERT_EQ(r.diags.size(), 1u);
  EXPECT_EQ(r.diags[0].severity, Severity::Warning);
  EXPECT_EQ(r.diags[0].code, "NCC2081");
  EXPECT_TRUE(r.moves.empty());
}

TEST(Coordinates, G28ThroughIntermediatePointToReferencePoint) {
  Lowered r = lower(Dialect::FanucM, "G43 H1 Z0\nG28 Z10.\nZ0\n",
                machine("reference_point_1 = { X = 0.0, Y = 0.0, Z = 300.0 }", "H1 = 20.0\n"));
  expectMoves(r, kXYZ, {{"rapid", {{"Z", 20}}}, {"rapid", {{"Z", 30}}}, {"rapid", {{"Z", 300}}},
                        {"rapid", {{"Z", 0}}}});  // G49 after the return: Z0 = machine 0
  EXPECT_EQ(r.blocks[1].modal.length_offset_sign, 0);
}

TEST(Coordinates, G27ChecksTheReferencePosition) {
  Lowered r = lower(Dialect::FanucM, "G00 X0\nG27 X-10.\n", machine());  // G54 X10: X-10 is machine 0
  expectMoves(r, kXYZ, {{"rapid", {{"X", 10}}}, {"rapid", {{"X", 0}}}});
  ASSERT_EQ(r.blocks.back().ops.size(), 2u);
  auto check = std::get<ir::ReferenceCheck>(r.blocks.back().ops.back());
  EXPECT_EQ(check.axes, 1u);
  EXPECT_EQ(check.reference, 1);
  EXPECT_EQ(check.position[0], 0.0);
}

// The reviewer's machine: G54 = [-100, -50, -200], H1 = 100, H2 = 50, start at 0.
std::string lengthMachine(const std::string& params = "") {
  return "[machine]\naxes = [\"X\", \"Y\", \"Z\"]\n[machine.offsets]\nH1 = 100.0\nH2 = 50.0\n"
         "[machine.work]\nG54 = [-100.0, -50.0, -200.0]\n[machine.params]\n" + params +
         "\n[start]\nposition = { X = 0.0, Y = 0.0, Z = 0.0 }\n";
}

// Mazak §12-2: an incremental move with a length change is ±z + (new length - old length).
TEST(ToolLength, IncrementalMoveCarriesTheLengthChangeMazak) {
  Lowered r = lower(Dialect::MazakM, "G90 G54 G00 Z10.\nG91 G43 H1 Z-5.\n", lengthMachine());
  expectMoves(r, kXYZ, {{"rapid", {{"Z", -190}}}, {"rapid", {{"Z", -95}}}});
}

TEST(ToolLength, IncrementalMoveCarriesTheLengthChangeFanuc) {
  Lowered r = lower(Dialect::FanucM, "G90 G54 G00 Z10.\nG91 G43 H1 Z-5.\nG43 H2 Z0\n",
                    lengthMachine());
  // H1 -> H2 with G91 Z0: the axis moves by the change, 50 - 100.
  expectMoves(r, kXYZ, {{"rapid", {{"Z", -190}}}, {"rapid", {{"Z", -95}}}, {"rapid", {{"Z", -145}}}});
}

TEST(ToolLength, IncrementalZeroMoveWithLengthChangeFanuc) {
  Lowered r = lower(Dialect::FanucM, "G43 H2 G91 Z0\n", lengthMachine());
  expectMoves(r, kXYZ, {{"rapid", {{"Z", 50}}}});
}

TEST(ToolLength, SiemensPendingLengthIsTakenUpByTheNextIncrementalMove) {
  Lowered r = lower(Dialect::SiemensIsoM, "G90 G54 G00 Z10.\nG43 H1\nX5.\nG91 Z-5.\nZ-5.\n",
                    lengthMachine());
  // G43 H1 does not move (MD20382 = FALSE); nor does X5.; G91 Z-5. takes up the +100 once.
  expectMoves(r, kXYZ, {{"rapid", {{"Z", -190}}}, {"rapid", {{"X", -95}, {"Z", -190}}},
                        {"rapid", {{"Z", -95}}}, {"rapid", {{"Z", -100}}}});
}

TEST(ToolLength, SiemensPendingLengthWithAbsoluteMove) {
  Lowered r = lower(Dialect::SiemensIsoM, "G90 G54 G00 Z10.\nG43 H1\nZ10.\nG91 Z-5.\n",
                    lengthMachine());
  expectMoves(r, kXYZ, {{"rapid", {{"Z", -190}}}, {"rapid", {{"Z", -90}}}, {"rapid", {{"Z", -95}}}});
}

// G28/G30 cancel the length offset only when the length axis is returned.
TEST(ToolLength, ReferenceReturnOfAnotherAxisKeepsTheLengthOffset) {
  for (Dialect d : {Dialect::FanucM, Dialect::MazakM}) {
    SCOPED_TRACE(static_cast<int>(d));
    Lowered r = lower(d, "G90 G54 G43 H1 X0 Y0 Z50.\nG91 G28 X0\nG90 G00 Z50.\nG91 G30 Y0\nG90 Z50.\n",
                      lengthMachine());
    expectMoves(r, kXYZ, {{"rapid", {{"X", -100}, {"Y", -50}, {"Z", -50}}}, {"rapid", {{"X", 0}, {"Z", -50}}},
                          {"rapid", {{"Y", 0}, {"Z", -50}}}});
    EXPECT_EQ(r.blocks[2].modal.length_offset_sign, 1);
    EXPECT_EQ(r.blocks.back().modal.length_offset_sign, 1);
  }
}

TEST(ToolLength, ReferenceReturnOfTheLengthAxisCancelsIt) {
  Lowered r = lower(Dialect::MazakM, "G90 G54 G43 H1 Z50.\nG91 G28 X0 Z0\nG90 G00 Z50.\n",
                    lengthMachine());
  expectMoves(r, kXYZ, {{"rapid", {{"Z", -50}}}, {"rapid", {{"X", 0}, {"Z", 0}}},
                        {"rapid", {{"Z", -150}}}});
  EXPECT_EQ(r.blocks[1].modal.length_offset_sign, 0);
}

TEST(ToolLength, FanucLengthChangeInArcModeIsAStraightLine) {
  Lowered r = lower(Dialect::FanucM, "G02 I5. F100.\nG43 H1\n", lengthMachine());
  ASSERT_EQ(r.diagText(), "");
  ASSERT_EQ(r.moves.size(), 2u);
  EXPECT_EQ(r.moves[1].kind, "line");
  EXPECT_NEAR(r.moves[1].feed, 100.0, 1e-9);
}

TEST(ToolLength, SiemensLengthChangeInArcModeIsAnError) {
  Lowered r = lower(Dialect::SiemensIsoM, "G02 I5. F100.\nG43 H1\nG01 G43 H1\n",
                    lengthMachine());
  EXPECT_EQ(r.diagText(),
            "2:1: error[NCC2045]: G43 is not allowed while G02 is in force: tool length "
            "compensation changes only in G00/G01 mode\n");
}

}  // namespace
}  // namespace ncc::passes::test
