// The rules that the motion, feed and dwell sections of the ISO manuals' notes give for the
// foundation's G codes (mazak-fusion640m-eia-iso §4.1-4.2, siemens-840di-iso-milling-gcode
// §4.2, 4.3, 4.7), one test each where no older test covers the rule. docs/semantics.md
// ("The foundation's rules against the manuals") lists every rule with its manual section and
// the test that checks it. Also the mixed decimal-point warning (NCC2034) and the codes that
// are real on a control but not built yet.
#include <variant>

#include "absl/strings/str_cat.h"
#include "absl/strings/match.h"
#include "expect_moves.h"
#include "ncc/ir/ir.h"

namespace ncc::passes::test {
namespace {

const std::vector<std::string> kXYZ = {"X", "Y", "Z"};

const ir::Arc& arcOf(const Lowered& r, size_t block) {
  return std::get<ir::Arc>(r.blocks.at(block).ops.at(0));
}

// ---- G00 ----------------------------------------------------------------------------------

TEST(FoundationRules, RapidIsLinearOnMazakAndSiemensPerAxisOnFanuc) {
  struct Case {
    Dialect d;
    ir::RapidType type;
  } cases[] = {{Dialect::MazakM, ir::RapidType::Linear},       // F91 bit 6 = 0
               {Dialect::SiemensIsoM, ir::RapidType::Linear},  // MD20732 = 1
               {Dialect::FanucM, ir::RapidType::PerAxis}};     // LRP = 0
  for (const Case& c : cases) {
    Lowered r = lower(c.d, "G00 X10. Y5.\n");
    ASSERT_EQ(r.diagText(), "");
    EXPECT_EQ(std::get<ir::Rapid>(r.blocks.at(0).ops.at(0)).type, c.type) << dialectName(c.d);
  }
}

// ---- G01 ----------------------------------------------------------------------------------

TEST(FoundationRules, FirstCuttingBlockWithoutFeedIsTheDialectsAlarm) {
  EXPECT_TRUE(
      absl::StrContains(lower(Dialect::MazakM, "G01 X10.\n").diagText(), "1:1: error[816]"));
  EXPECT_TRUE(
      absl::StrContains(lower(Dialect::SiemensIsoM, "G01 X10.\n").diagText(), "1:1: error[10860]"));
}

// ---- G02/G03 ------------------------------------------------------------------------------

TEST(FoundationRules, CentreWordsAreIncrementalEvenInG90) {
  for (Dialect d : {Dialect::MazakM, Dialect::SiemensIsoM}) {
    Lowered r = lower(d, "G90 G00 X10. Y0\nG02 X-10. Y0 I-10. F100.\n");
    expectMoves(r, kXYZ,
                {{"rapid", {{"X", 10}}},
                 {"arc", {{"X", -10}, {"Y", 0}}, {{"X", 0}, {"Y", 0}}, true, 100}});
  }
}

TEST(FoundationRules, G19TakesJAndK) {
  Lowered r = lower(Dialect::SiemensIsoM, "G19 G02 Y10. Z10. K10. F100.\n");
  expectMoves(r, kXYZ, {{"arc", {{"Y", 10}, {"Z", 10}}, {{"Y", 0}, {"Z", 10}}, true, 100}});
  EXPECT_EQ(arcOf(r, 0).plane, ir::Plane::YZ);
}

TEST(FoundationRules, CentreWithoutEndPointIsAFullCircle) {
  for (Dialect d : {Dialect::MazakM, Dialect::SiemensIsoM, Dialect::FanucM}) {
    Lowered r = lower(d, "G17 G03 I10. F100.\n");
    expectMoves(r, kXYZ, {{"arc", {{"X", 0}, {"Y", 0}}, {{"X", 10}, {"Y", 0}}, false, 100}});
    EXPECT_EQ(arcOf(r, 0).extra_turns, 0u);
  }
}

TEST(FoundationRules, RadiusDifferenceAboveToleranceIsAnAlarmBelowASpiral) {
  // Mazak §6-5: above F19 alarm 817 and no motion; below it the spiral to the end point.
  EXPECT_EQ(lower(Dialect::MazakM, "G02 X20.05 I10. F100.\n").diagText(),
            "1:1: error[817]: the end point is not on the arc: start radius 10.000, end radius "
            "10.050 (difference above arc_radius_tolerance 0.010)\n");
  Lowered r = lower(Dialect::MazakM, "G02 X20.005 I10. F100.\n");
  expectMoves(r, kXYZ, {{"arc", {{"X", 20.005}, {"Y", 0}}, {{"X", 10}, {"Y", 0}}, true, 100}});
}

TEST(FoundationRules, SignOfRSelectsTheShortOrTheLongArc) {
  Lowered shorter = lower(Dialect::SiemensIsoM, "G02 X10. Y10. R10. F100.\n");
  expectMoves(shorter, kXYZ, {{"arc", {{"X", 10}, {"Y", 10}}, {{"X", 10}, {"Y", 0}}, true, 100}});
  Lowered longer = lower(Dialect::SiemensIsoM, "G02 X10. Y10. R-10. F100.\n");
  expectMoves(longer, kXYZ, {{"arc", {{"X", 10}, {"Y", 10}}, {{"X", 0}, {"Y", 10}}, true, 100}});
}

TEST(FoundationRules, RShorterThanHalfTheChordIsTheDialectsAlarm) {
  EXPECT_TRUE(absl::StrContains(lower(Dialect::MazakM, "G02 X30. R10. F100.\n").diagText(),
                                "error[818]"));
  EXPECT_TRUE(absl::StrContains(lower(Dialect::SiemensIsoM, "G02 X30. R10. F100.\n").diagText(),
                                "error[14040]"));
}

TEST(FoundationRules, RBeatsCentreWordsButNotAnIJFullCircle) {
  // Mazak §6-6 examples 3 and 4.
  Lowered by_r = lower(Dialect::MazakM, "G02 X20. Y0 J5. R10. F100.\n");
  expectMoves(by_r, kXYZ, {{"arc", {{"X", 20}, {"Y", 0}}, {{"X", 10}, {"Y", 0}}, true, 100}});
  Lowered full = lower(Dialect::MazakM, "G17 G02 I10. J0 R5. F100.\n");
  expectMoves(full, kXYZ, {{"arc", {{"X", 0}, {"Y", 0}}, {{"X", 10}, {"Y", 0}}, true, 100}});
}

TEST(FoundationRules, RFullCircleDoesNotMove) {
  Lowered r = lower(Dialect::MazakM, "G02 R10. F100.\n");
  ASSERT_EQ(r.diagText(), "");
  EXPECT_TRUE(r.moves.empty());
}

// ---- helical turns: Mazak P, Siemens L ----------------------------------------------------

TEST(FoundationRules, MazakHelicalPAddsFullTurnsToAnOpenArc) {
  // §6-7: l = Z / ((2 pi p + theta) / 2 pi): a quarter arc with P2 runs 2.25 turns.
  Lowered r = lower(Dialect::MazakM, "G00 X10. Y0\nG17 G03 X0 Y10. Z-9. I-10. P2 F100.\n");
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 10}}},
               {"arc", {{"X", 0}, {"Y", 10}, {"Z", -9}}, {{"X", 0}, {"Y", 0}}, false, 100}});
  EXPECT_EQ(arcOf(r, 1).extra_turns, 2u);
  // P omitted: the arc alone (p = 0).
  Lowered plain = lower(Dialect::MazakM, "G00 X10. Y0\nG17 G03 X0 Y10. Z-9. I-10. F100.\n");
  ASSERT_EQ(plain.diagText(), "");
  EXPECT_EQ(arcOf(plain, 1).extra_turns, 0u);
}

TEST(FoundationRules, MazakHelicalPCountsTheTurnsOfAClosedArc) {
  // End = start (theta = 0): P3 is three turns; P omitted is one ("P may be omitted when the
  // number of pitches is 1"); P0 describes no arc.
  Lowered three = lower(Dialect::MazakM, "G17 G02 I10. Z-6. P3 F100.\n");
  ASSERT_EQ(three.diagText(), "");
  EXPECT_EQ(arcOf(three, 0).extra_turns, 2u);
  Lowered one = lower(Dialect::MazakM, "G17 G02 I10. Z-6. F100.\n");
  ASSERT_EQ(one.diagText(), "");
  EXPECT_EQ(arcOf(one, 0).extra_turns, 0u);
  EXPECT_EQ(lower(Dialect::MazakM, "G17 G02 I10. Z-6. P0 F100.\n").diagText(),
            "1:19: error[NCC2031]: the number of helical pitches P must be 1 to 9999 for an arc "
            "that ends at its start\n");
}

TEST(FoundationRules, MazakHelicalPIsNotReadWithR) {
  EXPECT_EQ(lower(Dialect::MazakM, "G02 X20. Y0 Z-1. R10. P2 F100.\n").diagText(),
            "1:23: error[NCC2014]: address P has no meaning in this block\n");
}

TEST(FoundationRules, SiemensLRepeatsAFullCircle) {
  // §2.1.3: `G17 G02 I.. J.. F.. Ln` runs the full circle n times; L omitted: once.
  Lowered r = lower(Dialect::SiemensIsoM, "G17 G02 I10. J0 F100. L3\n");
  expectMoves(r, kXYZ, {{"arc", {{"X", 0}, {"Y", 0}}, {{"X", 10}, {"Y", 0}}, true, 100}});
  EXPECT_EQ(arcOf(r, 0).extra_turns, 2u);
  EXPECT_EQ(lower(Dialect::SiemensIsoM, "G17 G02 I10. J0 F100. L0\n").diagText(),
            "1:23: error[NCC2031]: the number of full-circle repeats L must be 1 to 9999\n");
  // L belongs to the full circle only.
  EXPECT_EQ(lower(Dialect::SiemensIsoM, "G02 X20. Y0 I10. F100. L2\n").diagText(),
            "1:24: error[NCC2014]: address L has no meaning in this block\n");
}

TEST(FoundationRules, FanucArcsTakeNoTurnCount) {
  EXPECT_EQ(lower(Dialect::FanucM, "G02 I10. Z-6. P3 F100.\n").diagText(),
            "1:15: error[NCC2014]: address P has no meaning in this block\n");
}

TEST(FoundationRules, MazakHelixMayCarryTwoLinearAxes) {
  // §6-7 note: "two linear interpolation axes may be given": both move linearly with the arc.
  const std::string machine =
      "[machine]\naxes = [\"X\", \"Y\", \"Z\", \"U\"]\n[machine.work]\n"
      "G54 = [0.0, 0.0, 0.0, 0.0]\n[machine.params]\n\n[start]\n"
      "position = { X = 0.0, Y = 0.0, Z = 0.0, U = 0.0 }\n";
  Lowered r = lower(Dialect::MazakM, "G17 G02 X20. Y0 I10. Z-2. U5. F100.\n", machine);
  ASSERT_EQ(r.diagText(), "");
  ASSERT_EQ(r.moves.size(), 1u);
  EXPECT_EQ(r.moves[0].kind, "arc");
  EXPECT_NEAR(r.moves[0].to[0], 20.0, 1e-9);
  EXPECT_NEAR(r.moves[0].to[2], -2.0, 1e-9);
  EXPECT_NEAR(r.moves[0].to[3], 5.0, 1e-9);
  EXPECT_NEAR(r.moves[0].center[0], 10.0, 1e-9);
}

// ---- helical feed -------------------------------------------------------------------------

TEST(FoundationRules, HelicalFeedIsAlongTheHelixOnMazakAndSiemensAlongTheArcOnFanuc) {
  // A quarter arc of radius 10 (15.708 mm) with Z -5: the helix is 16.485 mm long. Mazak §6-7
  // and Siemens §2.1.4: F is the tool's tangential speed; FANUC: F is the speed along the arc,
  // so the tool runs 100 x 16.485 / 15.708 = 104.94 mm/min along the helix.
  const char* program = "G00 X10. Y0\nG17 G03 X0 Y10. Z-5. I-10. F100.\n";
  for (Dialect d : {Dialect::MazakM, Dialect::SiemensIsoM}) {
    Lowered r = lower(d, program);
    expectMoves(r, kXYZ,
                {{"rapid", {{"X", 10}}}, {"arc", {{"X", 0}, {"Y", 10}, {"Z", -5}}, {}, false, 100}});
  }
  Lowered fanuc = lower(Dialect::FanucM, program);
  expectMoves(fanuc, kXYZ,
              {{"rapid", {{"X", 10}}},
               {"arc", {{"X", 0}, {"Y", 10}, {"Z", -5}}, {}, false, 104.9439}});
  // An arc in its plane is the same in all three.
  Lowered flat = lower(Dialect::FanucM, "G00 X10. Y0\nG17 G03 X0 Y10. I-10. F100.\n");
  expectMoves(flat, kXYZ, {{"rapid", {{"X", 10}}}, {"arc", {{"X", 0}, {"Y", 10}}, {}, false, 100}});
}

// ---- G93 ----------------------------------------------------------------------------------

TEST(FoundationRules, MazakInverseTimeArcFIsSpeedPerRadius) {
  // §7-10 E8: G93 G02 Y-200. R100. F5 cuts at 5 x 100 = 500 mm/min; on FANUC and Siemens F is
  // 1 / the block's time in minutes, so the feed is F x the arc length (5 x 314.16).
  const char* program = "G93 G02 X0 Y-200. R100. F5\n";
  Lowered mazak = lower(Dialect::MazakM, program);
  expectMoves(mazak, kXYZ, {{"arc", {{"X", 0}, {"Y", -200}}, {{"X", 0}, {"Y", -100}}, true, 500}});
  Lowered siemens = lower(Dialect::SiemensIsoM, program);
  expectMoves(siemens, kXYZ,
              {{"arc", {{"X", 0}, {"Y", -200}}, {{"X", 0}, {"Y", -100}}, true,
                5 * 100 * 3.14159265}});
}

TEST(FoundationRules, InverseTimeNeedsFInEveryCuttingBlock) {
  EXPECT_EQ(lower(Dialect::MazakM, "G93 G01 X10. F2.\nX20.\n").diagText(),
            "2:1: error[816]: no feed rate: in inverse time feed (G93) every cutting block needs "
            "its own F\n");
}

// ---- G04 ----------------------------------------------------------------------------------

TEST(FoundationRules, MazakDwellXBeforeG04InInchIsReadAsACoordinate) {
  // §8-1: in inch input `X5. G04` is X50000 (0.0001 in), counted in 0.001 s: 50 s. After G04
  // and without a point X is the time: 5 s. In metric both readings give 5 s.
  Lowered r = lower(Dialect::MazakM, "G20\nX5. G04\nG04 X5.\nG04 X5000\nG21\nX5. G04\n");
  expectMoves(r, kXYZ,
              {{"dwell", {}, {}, false, -1, 50}, {"dwell", {}, {}, false, -1, 5},
               {"dwell", {}, {}, false, -1, 5}, {"dwell", {}, {}, false, -1, 5}});
  // Not a FANUC rule: there X is the time wherever it is written.
  Lowered fanuc = lower(Dialect::FanucM, "G20\nX5. G04\n");
  expectMoves(fanuc, kXYZ, {{"dwell", {}, {}, false, -1, 5}});
}

TEST(FoundationRules, DwellTimeIgnoresInchInput) {
  // Mazak §8-1 table (0.0001 inch row: X 0.001-99999.999 s, P x 0.001 s); Siemens §3.3.1
  // ("independent of the input and output unit"); FANUC alike: G04 after G20 is still seconds.
  for (Dialect d : {Dialect::MazakM, Dialect::SiemensIsoM, Dialect::FanucM}) {
    Lowered r = lower(d, "G20\nG04 X1000\nG04 P2500\nG04 X1.5\n",
                      xyzMachine("decimal_point = \"standard\""));
    expectMoves(r, kXYZ,
                {{"dwell", {}, {}, false, -1, 1.0}, {"dwell", {}, {}, false, -1, 2.5},
                 {"dwell", {}, {}, false, -1, 1.5}});
  }
}

TEST(FoundationRules, MazakDwellInG95CountsRevolutionsInThousandths) {
  // §8-2: G95 G04 X_ / P_ in revolutions, input unit 0.001 rev; F92 bit 2 forces seconds.
  Lowered r = lower(Dialect::MazakM, "G95\nG04 X1500\nG04 P2500\nG04 X2.\n");
  expectMoves(r, kXYZ,
              {{"dwell", {}, {}, false, -1, 1.5}, {"dwell", {}, {}, false, -1, 2.5},
               {"dwell", {}, {}, false, -1, 2.0}});
  for (size_t b = 1; b < 4; ++b)
    EXPECT_TRUE(std::get<ir::Dwell>(r.blocks.at(b).ops.at(0)).revolutions);
  Lowered seconds =
      lower(Dialect::MazakM, "G95\nG04 X1500\n", xyzMachine("dwell_always_seconds = true"));
  ASSERT_EQ(seconds.diagText(), "");
  EXPECT_FALSE(std::get<ir::Dwell>(seconds.blocks.at(1).ops.at(0)).revolutions);
}

TEST(FoundationRules, MazakDwellRunsWithMSAndT) {
  // §8-1: M, S, T or B given with G04 run with it.
  Lowered r = lower(Dialect::MazakM, "G04 X1. M08\n");
  ASSERT_EQ(r.diagText(), "");
  EXPECT_EQ(r.blocks.at(0).ops.size(), 2u);
}

TEST(FoundationRules, SiemensDwellPTakesNoDecimalPoint) {
  // §3.3.1 table 3.8: "P takes no decimal point".
  EXPECT_EQ(lower(Dialect::SiemensIsoM, "G04 P2.5\n").diagText(),
            "1:5: error[NCC2030]: G04 P is in milliseconds and takes no decimal point\n");
}

TEST(FoundationRules, SiemensDwellBlockHoldsNothingElse) {
  // §3.3.1: "the block that gives the dwell time contains no command other than G04".
  EXPECT_EQ(lower(Dialect::SiemensIsoM, "G04 X1. M08\n").diagText(),
            "1:9: error[NCC2014]: M cannot be given in a dwell (G04) block: the block holds "
            "nothing but G04 X or G04 P\n");
  EXPECT_EQ(lower(Dialect::SiemensIsoM, "G91 G04 X1.\n").diagText(),
            "1:1: error[NCC2014]: G91 cannot be given in a dwell (G04) block: the block holds "
            "nothing but G04 X or G04 P\n");
  Lowered ok = lower(Dialect::SiemensIsoM, "N10 G04 X1.5\n");
  expectMoves(ok, kXYZ, {{"dwell", {}, {}, false, -1, 1.5}});
}

TEST(FoundationRules, SiemensDwellInG95CountsRevolutionsOnlyWithMD20734Bit2) {
  Lowered seconds = lower(Dialect::SiemensIsoM, "G95\nG04 X2.\n");
  ASSERT_EQ(seconds.diagText(), "");
  EXPECT_FALSE(std::get<ir::Dwell>(seconds.blocks.at(1).ops.at(0)).revolutions);
  Lowered revs = lower(Dialect::SiemensIsoM, "G95\nG04 X2.\n",
                       xyzMachine("dwell_in_revolutions_with_g95 = true"));
  ASSERT_EQ(revs.diagText(), "");
  EXPECT_TRUE(std::get<ir::Dwell>(revs.blocks.at(1).ops.at(0)).revolutions);
}

// ---- coordinate words without a decimal point (NCC2034) -----------------------------------

TEST(DecimalPointWarning, OnceAtTheFirstWordWithTheCount) {
  Lowered r = lower(Dialect::FanucM, "G00 X10. Y5.\nG01 Z3 F100.\nX20 Y1.5\nG00 X30. Y5\n");
  EXPECT_EQ(r.diagText(),
            "2:5: warning[NCC2034]: 3 coordinate words without a decimal point are read as least "
            "input increments (the first: Z3 = 0.003 mm) in a program that also writes decimal "
            "points; write the point (`Z3.`) for whole units, or set decimal_point = "
            "\"calculator\"\n");
  EXPECT_EQ(r.moves.size(), 4u);  // a warning: the program is still compiled as written
}

TEST(DecimalPointWarning, NotForOneNotationOnly) {
  EXPECT_EQ(lower(Dialect::FanucM, "G00 X10. Y5.\nG01 Z3. F100\n").diagText(), "");
  EXPECT_EQ(lower(Dialect::MazakM, "G91 G00 X20000 Y20000\nG01 X20000 F300\n").diagText(), "");
}

TEST(DecimalPointWarning, ZerosAndDwellTimesDoNotCount) {
  // X0 reads the same either way; G04 X1000 is a time, not a coordinate.
  EXPECT_EQ(lower(Dialect::FanucM, "G00 X0 Y0\nG01 Z-1. F100.\nG04 X1000\n").diagText(), "");
}

TEST(DecimalPointWarning, NotInCalculatorNotation) {
  // Siemens MD10884 = 1: `Z3` is 3 mm, as meant.
  Lowered r = lower(Dialect::SiemensIsoM, "G00 X10. Y5\nZ3\n");
  expectMoves(r, kXYZ, {{"rapid", {{"X", 10}, {"Y", 5}}}, {"rapid", {{"Z", 3}}}});
}

// ---- codes real on the control, not built yet ---------------------------------------------

TEST(NotSupportedYet, RealCodesSaySoAsWritten) {
  struct Case {
    Dialect d;
    const char* program;
    const char* expected;
  } cases[] = {
      {Dialect::FanucM, "G05.1 X1.",
       "1:1: error[NCC2010]: G05.1 (AI contour control / nano smoothing) is not supported yet"},
      {Dialect::FanucM, "G5.1 X1.",
       "1:1: error[NCC2010]: G5.1 (AI contour control / nano smoothing) is not supported yet"},
      {Dialect::FanucM, "G12.1",
       "1:1: error[NCC2010]: G12.1 (polar coordinate interpolation) is not supported yet"},
      {Dialect::FanucM, "G68.2 X0 Y0 Z0",
       "1:1: error[NCC2010]: G68.2 (tilted working plane command) is not supported yet"},
      {Dialect::FanucM, "G54.2 P1",
       "1:1: error[NCC2010]: G54.2 (rotary table dynamic fixture offset) is not supported yet"},
      {Dialect::MazakM, "G17.1",
       "1:1: error[NCC2010]: G17.1 (five-face machining: top face mode) is not supported yet"},
      {Dialect::MazakM, "G05 P2",
       "1:1: error[NCC2010]: G05 (high-speed machining mode) is not supported yet"},
      {Dialect::SiemensIsoM, "G07.1",
       "1:1: error[NCC2010]: G07.1 (cylindrical interpolation) is not supported yet"},
      // Codes the manual does not list keep the unknown-G alarm, also as written.
      {Dialect::SiemensIsoM, "G05.1", "1:1: error[12470]: G05.1 is not a G code of siemens-iso-m"},
      {Dialect::FanucM, "G014 X1.", "1:1: error[PS0010]: G014 is not a G code of fanuc-m"},
  };
  for (const Case& c : cases) {
    Lowered r = lower(c.d, c.program);
    EXPECT_EQ(r.diagText(), std::string(c.expected) + "\n") << c.program;
  }
}

}  // namespace
}  // namespace ncc::passes::test
