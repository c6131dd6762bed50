// Mazak §13-12 line angle: `G01 Aa` with one end coordinate in the plane (the machine has no
// A axis); the other coordinate follows from the angle.
#include <cmath>

#include "expect_moves.h"

namespace ncc::passes::test {
namespace {

const std::vector<std::string> kXYZ = {"X", "Y", "Z"};

std::string metric() { return xyzMachine("decimal_point = \"standard\""); }

TEST(LineAngle, OneCoordinateAndTheAngle) {
  // From (0,0) at 30 degrees to X10.: Y = 10 tan 30 = 5.7735. Then at 120 degrees to Y20.:
  // t = (20 - 5.7735) / sin 120 = 16.4273, X = 10 + t cos 120 = 1.7863.
  Lowered r = lower(Dialect::MazakM, "G90 G01 A30. X10. F100\nA120. Y20.\nM30\n", metric());
  expectMoves(r, kXYZ,
              {{"line", {{"X", 10}, {"Y", 5.7735}}}, {"line", {{"X", 1.7863}, {"Y", 20}}}});
}

TEST(LineAngle, BothCoordinatesIgnoreTheAngleAndG18) {
  Lowered both = lower(Dialect::MazakM, "G01 A30. X5. Y5. F100\nM30\n", metric());
  expectMoves(both, kXYZ, {{"line", {{"X", 5}, {"Y", 5}}}});
  // G18: the angle from +Z (the plane's first axis): 45 degrees to Z-10. gives X-10.
  Lowered zx = lower(Dialect::MazakM, "G18 G01 A45. Z-10. F100\nM30\n", metric());
  expectMoves(zx, kXYZ, {{"line", {{"X", -10}, {"Z", -10}}}});
}

TEST(LineAngle, ErrorsAndOtherDialects) {
  Lowered geometric = lower(Dialect::MazakM, "G01 A30. F100\nM30\n", metric());
  EXPECT_NE(geometric.diagText().find("error[NCC2011]: the geometric command"), std::string::npos)
      << geometric.diagText();
  Lowered vertical = lower(Dialect::MazakM, "G01 A90. X10. F100\nM30\n", metric());
  EXPECT_NE(vertical.diagText().find("never changes X"), std::string::npos) << vertical.diagText();
  // Not in G00, and FANUC's A is no line angle (an improper address without an A axis).
  Lowered rapid = lower(Dialect::MazakM, "G00 A30. X10.\nM30\n", metric());
  EXPECT_NE(rapid.diagText().find("error[NCC2014]"), std::string::npos) << rapid.diagText();
  Lowered fanuc = lower(Dialect::FanucM, "G01 A30. X10. F100.\nM30\n", metric());
  EXPECT_NE(fanuc.diagText().find("error[PS0009]"), std::string::npos) << fanuc.diagText();
}

}  // namespace
}  // namespace ncc::passes::test
