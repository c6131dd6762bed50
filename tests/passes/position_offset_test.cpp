// Mazak G45-G48 tool position offset (passes/src/lowering_position_offset.cpp, §12-3).
#include "absl/strings/str_cat.h"
#include "expect_moves.h"

namespace ncc::passes::test {
namespace {

const std::vector<std::string> kXYZ = {"X", "Y", "Z"};

std::string withD(double l) {
  return xyzMachine("decimal_point = \"standard\"",
                    absl::StrCat("[machine.offsets]\nD1 = ", l, "\n"));
}

TEST(PositionOffset, RuleTable) {
  // §12-3 E10: x = 1000 (here 100.), l = 10: G45 110, G46 90, G47 120, G48 80 (incremental,
  // each from the end of the one before).
  Lowered r = lower(Dialect::MazakM,
                    "G91 G01 F100 D1\nG45 X100.\nG46 X100.\nG47 X100.\nG48 X100.\nM30\n", withD(10));
  expectMoves(r, kXYZ,
              {{"line", {{"X", 110}}}, {"line", {{"X", 200}}}, {"line", {{"X", 320}}},
               {"line", {{"X", 400}}}});
  // `G48 X20.` with l = 15 moves X-10: the sign of the move is kept, not of the result.
  Lowered m = lower(Dialect::MazakM, "G91 G48 G01 X20. F100 D1\nM30\n", withD(15));
  expectMoves(m, kXYZ, {{"line", {{"X", -10}}}});
}

TEST(PositionOffset, SignedZeroInG91AndNothingInG90) {
  // G45 X0 +l, G45 X-0 -l, G46 X0 -l, G46 X-0 +l; an absolute zero move stays (G90 X of the
  // current position).
  Lowered r = lower(Dialect::MazakM,
                    "G91 G01 F100 D1\nG45 X0\nG45 X-0\nG46 X0\nG46 X-0\nG90 G45 X0\nM30\n",
                    withD(10));
  expectMoves(r, kXYZ,
              {{"line", {{"X", 10}}}, {"line", {{"X", 0}}}, {"line", {{"X", -10}}},
               {"line", {{"X", 0}}}});
}

TEST(PositionOffset, EveryNamedAxisAndTheArcRadius) {
  // G46 X40. Y40. -> both 30; G45 G03 X10. Y10. J10. -> X20. Y20. J20. (radius 10 -> 20).
  Lowered r = lower(Dialect::MazakM, "G91 G46 G00 X40. Y40. D01\nG45 G03 X10. Y10. J10. F200\nM30\n",
                    withD(10));
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 30}, {"Y", 30}}},
               {"arc", {{"X", 50}, {"Y", 50}}, {{"X", 30}, {"Y", 50}}, false, 200}});
}

TEST(PositionOffset, OneShotAndNotOnFanuc) {
  Lowered r = lower(Dialect::MazakM, "G91 G45 G01 X10. F100 D1\nX10.\nM30\n", withD(10));
  expectMoves(r, kXYZ, {{"line", {{"X", 20}}}, {"line", {{"X", 30}}}});
  Lowered f = lower(Dialect::FanucM, "G91 G45 G01 X10. F100. D1\nM30\n", withD(10));
  EXPECT_NE(f.diagText().find("error[NCC2010]"), std::string::npos) << f.diagText();
}

}  // namespace
}  // namespace ncc::passes::test
