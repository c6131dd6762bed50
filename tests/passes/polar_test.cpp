// G15/G16 polar coordinate command (lowering_polar.cpp): the plane's first axis word is the
// radius, the second the angle (degrees, counter-clockwise from the first axis); the pole is
// the work origin (absolute radius or none) or the current position (incremental radius).
// Every expected point below is worked out by hand: r cos a, r sin a about the pole.
#include <string>
#include <vector>

#include "expect_moves.h"
#include "ncc/passes/dialect_table.h"

namespace ncc::passes::test {
namespace {

const std::vector<std::string> kXYZ = {"X", "Y", "Z"};

std::string calculator() { return xyzMachine("decimal_point = \"calculator\""); }
std::string standard() { return xyzMachine("decimal_point = \"standard\""); }

bool reports(const Lowered& r, const std::string& text) {
  return r.diagText().find(text) != std::string::npos;
}

TEST(Polar, TablesCarryTheRulesWhereTheManualHasG16) {
  for (Dialect d : {Dialect::FanucM, Dialect::SiemensIsoM}) {
    const DialectTable* t = dialectTable(d);
    ASSERT_NE(t->polar, nullptr);
    EXPECT_EQ(t->findG(160)->action, GAction::PolarOn);
    EXPECT_EQ(t->findG(150)->action, GAction::PolarOff);
    EXPECT_TRUE(t->findG(150)->power_on_default);
    EXPECT_EQ(t->alarm(Alarm::PolarNotAllowed), "NCC2088");
  }
  // Mazak: no G16 in the manual, so no rules and no code.
  EXPECT_EQ(dialectTable(Dialect::MazakM)->polar, nullptr);
  EXPECT_EQ(dialectTable(Dialect::MazakM)->findG(160), nullptr);
  EXPECT_FALSE(dialectTable(Dialect::FanucM)->polar->angle_from_axis_at_current_pole);
  EXPECT_TRUE(dialectTable(Dialect::SiemensIsoM)->polar->angle_from_axis_at_current_pole);
}

TEST(Polar, SiemensManualExampleE12) {
  // §4.5: N10 radius 100 at 45 deg about the work origin; N15 (G91) radius 100 at 0 deg about
  // the current position; N20 no radius: the origin is the pole, radius sqrt(170.711^2 +
  // 70.711^2) = 184.776, at 90 deg.
  Lowered r = lower(Dialect::SiemensIsoM,
                    "N5 G17 G90 X0 Y0\nN10 G16 X100. Y45.\nN15 G91 X100 Y0\nN20 G90 Y90\nG15\n"
                    "G90 X1. Y2.\nM30\n",
                    calculator());
  expectMoves(r, kXYZ,  // (N5 does not move: the harness machine starts at the origin)
              {{"rapid", {{"X", 70.7107}, {"Y", 70.7107}}},
               {"rapid", {{"X", 170.7107}, {"Y", 70.7107}}},
               {"rapid", {{"X", 0}, {"Y", 184.7759}}},
               {"rapid", {{"X", 1}, {"Y", 2}}}});  // G15: Cartesian again
}

TEST(Polar, PoleAtTheCurrentPositionFanucKeepsTheAngleSiemensCountsFromTheAxis) {
  // From 100 at 45 deg (70.711, 70.711): `G91 X100. Y0` is radius 100 about that point. FANUC:
  // the incremental angle 0 continues the position's 45 deg -> (141.421, 141.421); Siemens
  // (§4.5 N15): 0 deg from +X -> (170.711, 70.711).
  const std::string program = "G90 G16 X100. Y45.\nG91 X100. Y0\nM30\n";
  expectMoves(lower(Dialect::FanucM, program, calculator()), kXYZ,
              {{"rapid", {{"X", 70.7107}, {"Y", 70.7107}}},
               {"rapid", {{"X", 141.4214}, {"Y", 141.4214}}}});
  expectMoves(lower(Dialect::SiemensIsoM, program, calculator()), kXYZ,
              {{"rapid", {{"X", 70.7107}, {"Y", 70.7107}}},
               {"rapid", {{"X", 170.7107}, {"Y", 70.7107}}}});
  // Angle omitted, pole here: FANUC goes on outwards at 45 deg (+7.071 each), Siemens along +X.
  const std::string outwards = "G90 G16 X100. Y45.\nG91 X10.\nM30\n";
  expectMoves(lower(Dialect::FanucM, outwards, calculator()), kXYZ,
              {{"rapid", {{"X", 70.7107}, {"Y", 70.7107}}},
               {"rapid", {{"X", 77.7817}, {"Y", 77.7817}}}});
  expectMoves(lower(Dialect::SiemensIsoM, outwards, calculator()), kXYZ,
              {{"rapid", {{"X", 70.7107}, {"Y", 70.7107}}},
               {"rapid", {{"X", 80.7107}, {"Y", 70.7107}}}});
}

TEST(Polar, RadiusOrAngleOmitted) {
  for (Dialect d : {Dialect::FanucM, Dialect::SiemensIsoM}) {
    SCOPED_TRACE(static_cast<int>(d));
    // From (30, 40): no radius -> 50 about the origin, at 90 deg -> (0, 50); no angle -> the
    // position's angle atan2(50, 0) = 90 deg, radius 20 -> (0, 20). G91 angle with no radius:
    // about the origin, 90 - 30 = 60 deg, radius 20 -> (10, 17.3205).
    Lowered r = lower(d, "G90 X30. Y40.\nG16 Y90.\nX20.\nG91 Y-30.\nM30\n", calculator());
    expectMoves(r, kXYZ,
                {{"rapid", {{"X", 30}, {"Y", 40}}},
                 {"rapid", {{"X", 0}, {"Y", 50}}},
                 {"rapid", {{"X", 0}, {"Y", 20}}},
                 {"rapid", {{"X", 10}, {"Y", 17.3205}}}});
  }
}

TEST(Polar, StandardNotationReadsTheAngleInThousandthsOfADegree) {
  // "standard": Y45000 is 45 deg (0.001 deg increments), X100000 is 100 mm.
  Lowered r = lower(Dialect::FanucM, "G16 X100000 Y45000\nM30\n", standard());
  expectMoves(r, kXYZ, {{"rapid", {{"X", 70.7107}, {"Y", 70.7107}}}});
  // Inch input: the radius in inches, the angle in degrees.
  Lowered inch = lower(Dialect::FanucM, "G20 G16 X1. Y90.\nM30\n", standard());
  expectMoves(inch, kXYZ, {{"rapid", {{"X", 0}, {"Y", 25.4}}}});
}

TEST(Polar, PlanesG18AndG19) {
  // G18: Z is the radius, X the angle (from +Z towards +X); G19: Y the radius, Z the angle.
  expectMoves(lower(Dialect::FanucM, "G18 G16 Z10. X30.\nM30\n", calculator()), kXYZ,
              {{"rapid", {{"X", 5}, {"Y", 0}, {"Z", 8.6603}}}});
  expectMoves(lower(Dialect::SiemensIsoM, "G19 G16 Y10. Z30. X3.\nM30\n", calculator()), kXYZ,
              {{"rapid", {{"X", 3}, {"Y", 8.6603}, {"Z", 5}}}});
}

TEST(Polar, TheLocalOriginIsThePoleAndSetupCodesKeepTheirWords) {
  // G52 X10 Y10: the pole moves with it (radius 10 at 90 deg -> machine (10, 20)); G52's own
  // words, G04's X and G92's are no polar words.
  Lowered r = lower(Dialect::FanucM,
                    "G16 G52 X10. Y10.\nX10. Y90.\nG04 X1.\nG52 X0 Y0\nG92 X0 Y0\nX5. Y0\nM30\n",
                    calculator());
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 10}, {"Y", 20}}},
               {"dwell", {}, {}, false, -1, 1.0},
               {"rapid", {{"X", 15}, {"Y", 20}}}});  // G92 made (10, 20) the origin
}

TEST(Polar, LinesAndFanucArcsByR) {
  // G01 to radius 50 at 0 deg, G03 R50 to 90 deg: the arc about the origin ends at (0, 50).
  Lowered r = lower(Dialect::FanucM, "G16 G01 X50. Y0 F100.\nG03 X50. Y90. R50.\nM30\n",
                    calculator());
  expectMoves(r, kXYZ,
              {{"line", {{"X", 50}, {"Y", 0}}, {}, false, 100},
               {"arc", {{"X", 0}, {"Y", 50}}, {{"X", 0}, {"Y", 0}}, false}});
}

TEST(Polar, BoltHoleCircleWithCannedCycles) {
  // FANUC's example: G81 at radius 100, 30 deg, then 150 and 270 deg (absolute angles).
  const std::string absolute =
      "G17 G90 G16\nG81 X100. Y30. Z-20. R-5. F200.\nY150.\nY270.\nG15 G80\nM30\n";
  Lowered a = lower(Dialect::FanucM, absolute, calculator());
  ASSERT_EQ(a.diagText(), "");
  std::vector<std::pair<double, double>> holes;
  for (const Move& m : a.moves)
    if (m.kind == "line") holes.emplace_back(m.to[0], m.to[1]);
  ASSERT_EQ(holes.size(), 3u);
  EXPECT_NEAR(holes[0].first, 86.6025, 1e-3);
  EXPECT_NEAR(holes[0].second, 50, 1e-3);
  EXPECT_NEAR(holes[1].first, -86.6025, 1e-3);
  EXPECT_NEAR(holes[1].second, 50, 1e-3);
  EXPECT_NEAR(holes[2].first, 0, 1e-3);
  EXPECT_NEAR(holes[2].second, -100, 1e-3);
  // Incremental angles with K: 30 deg, then `G91 Y120. K2` drills at 150 and 270 deg, each
  // repeat turning on from the previous hole.
  const std::string repeated =
      "G17 G90 G16\nG81 X100. Y30. Z-20. R-5. F200.\nG91 Y120. K2\nG15 G80\nM30\n";
  Lowered k = lower(Dialect::FanucM, repeated, calculator());
  ASSERT_EQ(k.diagText(), "");
  std::vector<std::pair<double, double>> again;
  for (const Move& m : k.moves)
    if (m.kind == "line") again.emplace_back(m.to[0], m.to[1]);
  ASSERT_EQ(again.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(again[i].first, holes[i].first, 1e-3) << i;
    EXPECT_NEAR(again[i].second, holes[i].second, 1e-3) << i;
  }
}

TEST(Polar, RefusedCombinations) {
  // FANUC: an arc's radius by R only; no ,C / ,R in G16.
  Lowered ijk = lower(Dialect::FanucM, "G16 G01 X50. Y0 F100.\nG03 X50. Y90. I-50.\nM30\n",
                      calculator());
  EXPECT_TRUE(reports(ijk, "2:15: error[NCC2088]: an arc in the polar coordinate mode (G16) "
                           "takes its radius by R, not by the centre (I)"))
      << ijk.diagText();
  Lowered chamfer = lower(Dialect::FanucM, "G16 G01 X50. Y0 ,C2. F100.\nX50. Y90.\nM30\n",
                          calculator());
  EXPECT_TRUE(reports(chamfer, "1:17: error[NCC2088]: ,C (chamfer / corner rounding)"))
      << chamfer.diagText();
  // Siemens: §4.5 says nothing of arcs in G16; corners are allowed.
  Lowered arc = lower(Dialect::SiemensIsoM, "G16 G01 X50. Y0 F100.\nG03 X50. Y90. R50.\nM30\n",
                      calculator());
  EXPECT_TRUE(reports(arc, "2:1: error[NCC2088]: G02/G03 in the polar coordinate mode (G16) is "
                           "not supported"))
      << arc.diagText();
  Lowered rounded = lower(Dialect::SiemensIsoM,
                          "G16 G01 X50. Y0 F100.\nX50. Y90. ,R5.\nX0 Y0\nM30\n", calculator());
  EXPECT_EQ(rounded.diagText(), "");
  // G28's words name the axes that return: not read as polar.
  Lowered g28 = lower(Dialect::FanucM, "G16 X50. Y90.\nG28 X0\nM30\n", calculator());
  EXPECT_TRUE(reports(g28, "2:1: error[NCC2088]: G28 with X or Y in the polar coordinate mode"))
      << g28.diagText();
}

TEST(Polar, APlaneWithoutItsAxes) {
  const std::string xz =
      "[machine]\naxes = [\"X\", \"Z\"]\n[machine.params]\ndecimal_point = \"calculator\"\n";
  Lowered r = lower(Dialect::FanucM, "G17 G16\nM30\n", xz);
  EXPECT_TRUE(reports(r, "1:5: error[NCC2080]: polar coordinates (G16) in the XY plane (G17) "
                         "need the radius axis X and the angle axis Y; the machine has no Y"))
      << r.diagText();
  // In G18 the same machine has both.
  Lowered zx = lower(Dialect::FanucM, "G18 G16 Z10. X90.\nM30\n", xz);
  EXPECT_EQ(zx.diagText(), "");
  ASSERT_EQ(zx.moves.size(), 1u);
  EXPECT_NEAR(zx.moves[0].to[0], 10, 1e-9);
  EXPECT_NEAR(zx.moves[0].to[1], 0, 1e-9);
}

TEST(Polar, AfterARejectedG16BlockThePlaneWordsAreNotGuessed) {
  // The G16 block without F is rejected: whether G16 is in force is unknown, so the next block's
  // plane words are neither polar nor Cartesian and it is not judged (in G16 its I would be
  // NCC2088). G15 and absolute words make the state known again: the last arc is judged.
  Lowered r = lower(Dialect::FanucM,
                    "G16 G01 X10. Y20.\nG03 X50. Y90. I-50. F100.\nG15 G90 G00 X5. Y6.\n"
                    "G02 X20. Y6. R2.\nM30\n",
                    calculator());
  EXPECT_TRUE(reports(r, "1:5: error[PS0011]")) << r.diagText();
  EXPECT_TRUE(reports(r, "4:14: error[PS0020]")) << r.diagText();
  EXPECT_EQ(r.diags.size(), 2u) << r.diagText();
}

}  // namespace
}  // namespace ncc::passes::test
