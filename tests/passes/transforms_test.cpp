// Coordinate transforms (lowering_transforms.cpp, transform_pass.cpp): G68/G69 rotation, G51/G50
// scaling, G51.1/G50.1 mirror and Mazak's G92.5, per dialect. Every expected point is worked out
// by hand from the manuals' rules (the arithmetic is in the comment above each case), never
// copied from a run. A rotation by a about (cx, cy) takes (x, y) to
//   (cx + (x-cx) cos a - (y-cy) sin a,  cy + (x-cx) sin a + (y-cy) cos a),
// counter-clockwise seen from the plane's third axis (G17: from +Z, G18: from +Y with Z the first
// axis, G19: from +X with Y the first axis). A scaling by f about c takes x to c + f (x - c).
#include <string>
#include <vector>

#include "expect_moves.h"
#include "ncc/passes/dialect_table.h"

namespace ncc::passes::test {
namespace {

const std::vector<std::string> kXYZ = {"X", "Y", "Z"};
constexpr Dialect kAll[] = {Dialect::FanucM, Dialect::MazakM, Dialect::SiemensIsoM};

// Decimal points everywhere in these programs; "calculator" also reads X0 as 0 mm.
std::string machine(const std::string& params = "") {
  return xyzMachine("decimal_point = \"calculator\"\n" + params);
}

// X Y Z with G54 at zero and G55 at (100, 100, 0) (the Mazak §14-13 examples' G55).
std::string g55Machine(const std::string& params = "") {
  return "[machine]\naxes = [\"X\", \"Y\", \"Z\"]\n[machine.work]\nG54 = [0.0, 0.0, 0.0]\n"
         "G55 = [100.0, 100.0, 0.0]\n[machine.params]\ndecimal_point = \"calculator\"\n" +
         params + "\n[start]\nposition = { X = 0.0, Y = 0.0, Z = 0.0 }\n";
}

Lowered run(Dialect d, const std::string& program, const std::string& params = "") {
  return lower(d, program, machine(params));
}

const char* name(Dialect d) {
  return d == Dialect::FanucM ? "fanuc-m" : d == Dialect::MazakM ? "mazak-m" : "siemens-iso-m";
}

// The first diagnostic's "line:col: severity[CODE]" (the message is the implementation's).
std::string firstDiag(const Lowered& r) {
  const std::string text = r.diagText();
  const size_t end = text.find("]:");
  return end == std::string::npos ? text : text.substr(0, end + 1);
}

// ---- G68 2-D ------------------------------------------------------------------------------

TEST(Transforms, RotationG17LineAndArcKeepsTheArcDirection) {
  // R90 about (0, 0): (10, 0) -> (0, 10); the G02 (10, 0) -> (20, 0) about (15, 0) ends at
  // (0, 20) about (0, 15), still clockwise (a rotation keeps the sense). After G69 (30, 5) is
  // reached unrotated. All three manuals: centre absolute, + counter-clockwise.
  for (Dialect d : kAll) {
    SCOPED_TRACE(name(d));
    Lowered r = run(d,
                    "G17 G68 X0 Y0 R90.\nG01 X10. Y0 F100.\nG02 X20. Y0 I5. J0\nG69\n"
                    "G01 X30. Y5.\nM30\n");
    expectMoves(r, kXYZ,
                {{"line", {{"X", 0}, {"Y", 10}, {"Z", 0}}},
                 {"arc", {{"X", 0}, {"Y", 20}}, {{"X", 0}, {"Y", 15}}, true},
                 {"line", {{"X", 30}, {"Y", 5}}}});
  }
}

TEST(Transforms, RotationG18TurnsAboutY) {
  // G18: the plane Z-X, Z its first axis; R90 turns +Z towards +X, so (X, Z) = (10, 0), i.e.
  // (z, x) = (0, 10): z' = 0 cos90 - 10 sin90 = -10, x' = 0 sin90 + 10 cos90 = 0 -> X0 Z-10.
  // The G02 to (X20, Z0) about (X15, Z0): end X0 Z-20, centre X0 Z-15, still clockwise.
  for (Dialect d : kAll) {
    SCOPED_TRACE(name(d));
    Lowered r = run(d, "G18 G68 Z0 X0 R90.\nG01 X10. Z0 F100.\nG02 X20. Z0 I5. K0\nM30\n");
    expectMoves(r, kXYZ,
                {{"line", {{"X", 0}, {"Y", 0}, {"Z", -10}}},
                 {"arc", {{"X", 0}, {"Z", -20}}, {{"X", 0}, {"Z", -15}}, true}});
  }
}

TEST(Transforms, RotationG19TurnsAboutX) {
  // G19: the plane Y-Z; R90 turns +Y towards +Z: (Y10, Z0) -> (Y0, Z10). X is untouched.
  for (Dialect d : kAll) {
    SCOPED_TRACE(name(d));
    Lowered r = run(d, "G19 G68 Y0 Z0 R90.\nG01 X3. Y10. Z0 F100.\nM30\n");
    expectMoves(r, kXYZ, {{"line", {{"X", 3}, {"Y", 0}, {"Z", 10}}}});
  }
}

TEST(Transforms, RotationCentreOmittedIsWhereTheG68BlockIs) {
  // Mazak §13-8 3.2, Siemens §3.1.9, FANUC: the centre is the current position (10, 10);
  // (20, 10) is (10, 0) from it, turned 90 deg -> (0, 10) from it = (10, 20).
  for (Dialect d : kAll) {
    SCOPED_TRACE(name(d));
    Lowered r = run(d, "G00 X10. Y10.\nG68 R90.\nG00 X20. Y10.\nM30\n");
    expectMoves(r, kXYZ, {{"rapid", {{"X", 10}, {"Y", 10}}}, {"rapid", {{"X", 10}, {"Y", 20}}}});
  }
}

TEST(Transforms, RotationAngleOmitted) {
  // FANUC No.5410 / Siemens SD42150: the default angle (90 here): (10, 0) -> (0, 10).
  for (Dialect d : {Dialect::FanucM, Dialect::SiemensIsoM}) {
    SCOPED_TRACE(name(d));
    Lowered r = run(d, "G68 X0 Y0\nG00 X10. Y0\nM30\n", "default_rotation_angle = 90");
    expectMoves(r, kXYZ, {{"rapid", {{"X", 0}, {"Y", 10}}}});
  }
  // Mazak §13-8 2.: R belongs to the format; without it the block is a format error (807).
  Lowered m = run(Dialect::MazakM, "G68 X0 Y0\nG00 X10. Y0\nM30\n");
  EXPECT_EQ(firstDiag(m), "1:1: error[807]");
  EXPECT_TRUE(m.moves.empty());
}

TEST(Transforms, IncrementalAngleFanucAbsoluteUnlessRinMazakAddsToTheAngleInForce) {
  // R30 then, in G91, R60 about the same centre; (10, 0) is then turned by
  //   FANUC (RIN = 0): R always absolute -> 60 deg: (10 cos60, 10 sin60) = (5, 8.6603);
  //   FANUC with rotation_angle_incremental = true, and Mazak §13-8 3.3 (R in G90 or G91,
  //   G68 in G68 replaces the angle): 30 + 60 = 90 deg -> (0, 10).
  const std::string program = "G68 X0 Y0 R30.\nG91 G68 X0 Y0 R60.\nG90 G01 X10. Y0 F100.\nM30\n";
  expectMoves(run(Dialect::FanucM, program), kXYZ, {{"line", {{"X", 5}, {"Y", 8.6603}}}});
  expectMoves(run(Dialect::FanucM, program, "rotation_angle_incremental = true"), kXYZ,
              {{"line", {{"X", 0}, {"Y", 10}}}});
  expectMoves(run(Dialect::MazakM, program), kXYZ, {{"line", {{"X", 0}, {"Y", 10}}}});
  // G91 R with no rotation in force counts from 0: R45 -> (7.0711, 7.0711) on all three.
  for (Dialect d : kAll) {
    SCOPED_TRACE(name(d));
    Lowered r = run(d, "G91\nG68 X0 Y0 R45.\nG90\nG00 X10. Y0\nM30\n");
    expectMoves(r, kXYZ, {{"rapid", {{"X", 7.0711}, {"Y", 7.0711}}}});
  }
}

TEST(Transforms, SiemensIncrementalAngleInASecondG68) {
  // Siemens §3.1.9: R is "absolute or incremental per G90/G91"; with R30 in force an
  // incremental R60 adds 60 to the angle in force, 30 + 60 = 90 deg in all: (10, 0) -> (0, 10).
  // (Read as base frame 2 composed on frame 1 (§3.1.10), an incremental R in the empty frame 2
  // is also 60, again 90 in all.) ncc adds the 30 to the second G68's angle (90) AND stacks it
  // on the first: 120 deg, (-5, 8.6603).
  Lowered r = run(Dialect::SiemensIsoM,
                  "G68 X0 Y0 R30.\nG91\nG68 X0 Y0 R60.\nG90\nG01 X10. Y0 F100.\nM30\n");
  expectMoves(r, kXYZ, {{"line", {{"X", 0}, {"Y", 10}}}});
}

TEST(Transforms, G68InsideG68MazakAndFanucReplaceSiemensStacks) {
  // R90 about (0, 0), then R90 about (10, 0); the point (20, 0):
  //   Mazak §13-8 3.4 and FANUC 2-D: the second replaces the first: about (10, 0): (10, 10).
  //   Siemens §3.1.10 base frames 1 and 2: the second, given in the first's coordinates, acts
  //   first: (20, 0) about (10, 0) -> (10, 10), then about (0, 0) by 90 -> (-10, 10).
  const std::string program = "G68 X0 Y0 R90.\nG68 X10. Y0 R90.\nG00 X20. Y0\nM30\n";
  expectMoves(run(Dialect::MazakM, program), kXYZ, {{"rapid", {{"X", 10}, {"Y", 10}}}});
  expectMoves(run(Dialect::FanucM, program), kXYZ, {{"rapid", {{"X", 10}, {"Y", 10}}}});
  expectMoves(run(Dialect::SiemensIsoM, program), kXYZ, {{"rapid", {{"X", -10}, {"Y", 10}}}});
  // Siemens: a third G68 replaces the second (R45 about the origin), on top of the first:
  // 90 + 45 = 135 deg: (10, 0) -> (-7.0711, 7.0711). G69 cancels both: (10, 0) again.
  expectMoves(run(Dialect::SiemensIsoM,
                  "G68 X0 Y0 R90.\nG68 X10. Y0 R90.\nG68 X0 Y0 R45.\nG00 X10. Y0\nG69\n"
                  "G00 X10. Y0\nM30\n"),
              kXYZ,
              {{"rapid", {{"X", -7.0711}, {"Y", 7.0711}}}, {"rapid", {{"X", 10}, {"Y", 0}}}});
}

TEST(Transforms, FanucThreeDimensionalNestsTwiceAThirdIsAnAlarm) {
  // Two 3-D rotations about Z by 45 compose to 90: (10, 0) -> (0, 10); G69 ends both.
  expectMoves(run(Dialect::FanucM,
                  "G68 X0 Y0 Z0 I0 J0 K1. R45.\nG68 X0 Y0 Z0 I0 J0 K1. R45.\nG00 X10. Y0\n"
                  "G69\nG00 X10. Y0\nM30\n"),
              kXYZ, {{"rapid", {{"X", 0}, {"Y", 10}}}, {"rapid", {{"X", 10}, {"Y", 0}}}});
  Lowered r = run(Dialect::FanucM,
                  "G68 X0 Y0 Z0 I0 J0 K1. R10.\nG68 X0 Y0 Z0 I0 J0 K1. R10.\n"
                  "G68 X0 Y0 Z0 I0 J0 K1. R10.\nG00 X10.\nM30\n");
  EXPECT_EQ(firstDiag(r), "3:1: error[NCC2115]");
}

TEST(Transforms, Siemens2dG68MustStandAlone) {
  // §3.1.9 / §3.2.3: G68, G69, G51, G50 blocks hold no other G code but the plane.
  EXPECT_EQ(firstDiag(run(Dialect::SiemensIsoM, "G90 G68 X0 Y0 R30.\nM30\n")),
            "1:1: error[NCC2112]");
  EXPECT_EQ(firstDiag(run(Dialect::SiemensIsoM, "G51 G01 X0 Y0 P2.\nM30\n")),
            "1:5: error[NCC2112]");
  EXPECT_EQ(firstDiag(run(Dialect::SiemensIsoM, "G68 X0 Y0 R30.\nG69 G00 X5.\nM30\n")),
            "2:5: error[NCC2112]");
  EXPECT_EQ(firstDiag(run(Dialect::SiemensIsoM, "G50 G00 X5.\nM30\n")), "1:5: error[NCC2112]");
  // The plane is allowed: `G18 G68 Z X R` is the manual's own format; FANUC has no such rule.
  EXPECT_EQ(run(Dialect::SiemensIsoM, "G18 G68 Z0 X0 R30.\nM30\n").diagText(), "");
  EXPECT_EQ(run(Dialect::FanucM, "G90 G68 X0 Y0 R30.\nG69 G00 X5.\nM30\n").diagText(), "");
}

TEST(Transforms, RotationAxisOffThePlaneIsNoCentre) {
  // G17 G68 with a Z word: Z is no centre of a rotation in the XY plane (I J K make it 3-D).
  EXPECT_EQ(firstDiag(run(Dialect::FanucM, "G17 G68 X0 Y0 Z5. R30.\nM30\n")),
            "1:15: error[NCC2014]");
}

TEST(Transforms, RotationCentreIsAbsoluteEvenInG91) {
  // All three manuals: the centre is absolute whatever G90/G91. From (10, 10), `G91 G68 X5. Y5.
  // R90.` turns about (5, 5) (not (15, 15)): (15, 5) is (10, 0) from it -> (0, 10): (5, 15).
  // (About (15, 15) it would be (25, 15).) Siemens: G91 in its own block (the alone-rule).
  expectMoves(run(Dialect::FanucM, "G00 X10. Y10.\nG91 G68 X5. Y5. R90.\nG90 G00 X15. Y5.\nM30\n"),
              kXYZ, {{"rapid", {{"X", 10}, {"Y", 10}}}, {"rapid", {{"X", 5}, {"Y", 15}}}});
  expectMoves(run(Dialect::MazakM, "G00 X10. Y10.\nG91 G68 X5. Y5. R90.\nG90 G00 X15. Y5.\nM30\n"),
              kXYZ, {{"rapid", {{"X", 10}, {"Y", 10}}}, {"rapid", {{"X", 5}, {"Y", 15}}}});
  expectMoves(run(Dialect::SiemensIsoM,
                  "G00 X10. Y10.\nG91\nG68 X5. Y5. R90.\nG90\nG00 X15. Y5.\nM30\n"),
              kXYZ, {{"rapid", {{"X", 10}, {"Y", 10}}}, {"rapid", {{"X", 5}, {"Y", 15}}}});
}

TEST(Transforms, IncrementalMovesRunInTheRotatedSystem) {
  // R90 about (0, 0): `G91 X10.` twice goes along the turned X axis, i.e. +Y: (0, 10), (0, 20).
  for (Dialect d : kAll) {
    SCOPED_TRACE(name(d));
    expectMoves(run(d, "G68 X0 Y0 R90.\nG91 G01 X10. F100.\nX10.\nM30\n"), kXYZ,
                {{"line", {{"X", 0}, {"Y", 10}}}, {"line", {{"X", 0}, {"Y", 20}}}});
  }
}

TEST(Transforms, RotationRefusals) {
  // An angle beyond +-360 (Mazak §13-8 2.: -360.000 to 360.000; 809 "number not allowed").
  EXPECT_EQ(firstDiag(run(Dialect::FanucM, "G68 X0 Y0 R400.\nM30\n")), "1:11: error[NCC2116]");
  EXPECT_EQ(firstDiag(run(Dialect::MazakM, "G68 X0 Y0 R400.\nM30\n")), "1:11: error[809]");
  EXPECT_EQ(firstDiag(run(Dialect::SiemensIsoM, "G68 X0 Y0 R-361.\nM30\n")),
            "1:11: error[NCC2116]");
  // G68 and G51 both take the axis words: one block cannot hold both.
  for (Dialect d : {Dialect::FanucM, Dialect::MazakM}) {
    SCOPED_TRACE(name(d));
    EXPECT_EQ(firstDiag(run(d, "G51 G68 X0 Y0 R10. P2.\nM30\n")), "1:1: error[NCC2021]");
  }
}

TEST(Transforms, MachineCoordinateMovesAreNotTurned) {
  // Mazak ch. 22 §5.3 "le mode G68 n'affecte aucunement la commande G53"; FANUC alike:
  // G53 X10. Y0 goes to machine (10, 0) under R90, where a work move to (10, 0) goes to (0, 10).
  for (Dialect d : {Dialect::FanucM, Dialect::MazakM}) {
    SCOPED_TRACE(name(d));
    expectMoves(run(d, "G68 X0 Y0 R90.\nG53 X10. Y0\nG00 X10. Y0\nM30\n"), kXYZ,
                {{"rapid", {{"X", 10}, {"Y", 0}}}, {"rapid", {{"X", 0}, {"Y", 10}}}});
  }
}

TEST(Transforms, MazakNestedThreeDimensionalRotationsCompose) {
  // Ch. 22 §4: nested 3-D G68 compose: 45 + 45 about Z: (10, 0) -> (0, 10).
  expectMoves(run(Dialect::MazakM,
                  "G68 X0 Y0 Z0 I0 J0 K1. R45.\nG68 X0 Y0 Z0 I0 J0 K1. R45.\nG00 X10. Y0\nM30\n"),
              kXYZ, {{"rapid", {{"X", 0}, {"Y", 10}}}});
}

// ---- G68 3-D ------------------------------------------------------------------------------

TEST(Transforms, ThreeDimensionalAnyVectorFanucAndSiemens) {
  // Siemens §3.1.10 and FANUC: any I J K. 120 deg about (1, 1, 1) permutes the axes
  // X -> Y -> Z: (10, 0, 0) -> (0, 10, 0).
  for (Dialect d : {Dialect::FanucM, Dialect::SiemensIsoM}) {
    SCOPED_TRACE(name(d));
    Lowered r = run(d, "G68 X0 Y0 Z0 I1. J1. K1. R120.\nG01 X10. Y0 Z0 F100.\nM30\n");
    expectMoves(r, kXYZ, {{"line", {{"X", 0}, {"Y", 10}, {"Z", 0}}}});
  }
}

TEST(Transforms, SiemensZeroVectorIsThePlaneNormalAndTheCentreTheWorkOrigin) {
  // §3.1.10: I0 J0 K0 in G18 turns about Y: X10 -> Z-10 (as in RotationG18TurnsAboutY).
  expectMoves(run(Dialect::SiemensIsoM, "G18\nG68 I0 J0 K0 R90.\nG00 X10. Y0 Z0\nM30\n"), kXYZ,
              {{"rapid", {{"X", 0}, {"Y", 0}, {"Z", -10}}}});
  // Centre omitted: Siemens the work origin -> (10, 0) turned 90 about (0, 0) = (0, 10);
  // FANUC the current position (5, 5): (5, -5) from it -> (5, 5) from it = (10, 10).
  const std::string program = "G00 X5. Y5.\nG68 I0 J0 K1. R90.\nG00 X10. Y0\nM30\n";
  expectMoves(run(Dialect::SiemensIsoM, program), kXYZ,
              {{"rapid", {{"X", 5}, {"Y", 5}}}, {"rapid", {{"X", 0}, {"Y", 10}}}});
  expectMoves(run(Dialect::FanucM, program), kXYZ,
              {{"rapid", {{"X", 5}, {"Y", 5}}}, {"rapid", {{"X", 10}, {"Y", 10}}}});
}

TEST(Transforms, MazakThreeDimensionalNeedsOneUnitAxis) {
  // Ch. 22 §2 "Précaution": I J K all given, exactly one of them 1. I1: about X by 90:
  // (Y10, Z0) -> (Y0, Z10).
  expectMoves(run(Dialect::MazakM, "G68 X0 Y0 Z0 I1. J0 K0 R90.\nG00 X0 Y10. Z0\nM30\n"), kXYZ,
              {{"rapid", {{"X", 0}, {"Y", 0}, {"Z", 10}}}});
  // "1 at two or more of I, J, K" (the manual's `I1 J1 K0`), all three 0, or a component that
  // is neither 0 nor 1: alarm 807 at the G68.
  EXPECT_EQ(firstDiag(run(Dialect::MazakM, "G68 X0 Y0 Z0 I1. J1. K0 R-90.\nM30\n")),
            "1:1: error[807]");
  EXPECT_EQ(firstDiag(run(Dialect::MazakM, "G68 X0 Y0 Z0 I0 J0 K0 R-90.\nM30\n")),
            "1:1: error[807]");
  EXPECT_EQ(firstDiag(run(Dialect::MazakM, "G00 X1.\nG68 X0 Y0 Z0 I0 J0 K0.5 R90.\nM30\n")),
            "2:1: error[807]");
  // FANUC and Siemens take any vector.
  EXPECT_EQ(run(Dialect::FanucM, "G68 X0 Y0 Z0 I1. J1. R90.\nM30\n").diagText(), "");
}

TEST(Transforms, MazakThreeDimensionalNeedsAllOfIJK) {
  // ch. 22 §2 "Précaution": "I, J and K are required. If one or two of them are omitted,
  // alarm 807"; the manual's own example `G68 X0 Y0 Z0 I1 K0 R-45.` is a "format error".
  EXPECT_EQ(firstDiag(run(Dialect::MazakM, "G68 X0 Y0 Z0 I1. K0 R-45.\nM30\n")),
            "1:1: error[807]");
  EXPECT_EQ(firstDiag(run(Dialect::MazakM, "G68 X0 Y0 Z0 I1. R90.\nM30\n")), "1:1: error[807]");
}

TEST(Transforms, MazakThreeDimensionalG68StandsAlone) {
  // ch. 22 §5.2: "if a G code other than G17, G18 and G19 is given with G68 or G69 in the
  // same block, alarm 807".
  EXPECT_EQ(firstDiag(run(Dialect::MazakM, "G90 G68 X0 Y0 Z0 I0 J0 K1. R45.\nM30\n")),
            "1:1: error[807]");
  EXPECT_EQ(run(Dialect::MazakM, "G17 G68 X0 Y0 Z0 I0 J0 K1. R45.\nM30\n").diagText(), "");
}

TEST(Transforms, MazakThreeDimensionalModeRefusesScalingAndWorkOffsets) {
  // ch. 22 §2: "an incompatible G code in 3-D coordinate conversion mode: alarm 943"; the
  // §5.1 table marks G50/G51 and G54-G59 "x" in G68 mode. (In a 2-D G68,
  // G51 is fine: §13-10 5.10.)
  EXPECT_EQ(firstDiag(run(Dialect::MazakM,
                          "G68 X0 Y0 Z0 I0 J0 K1. R45.\nG51 X0 Y0 P2.\nM30\n")),
            "2:1: error[943]");
  EXPECT_EQ(firstDiag(run(Dialect::MazakM, "G68 X0 Y0 Z0 I0 J0 K1. R45.\nG55\nM30\n")),
            "2:1: error[943]");
  EXPECT_EQ(run(Dialect::MazakM, "G68 X0 Y0 R45.\nG51 X0 Y0 P2.\nM30\n").diagText(), "");
}

TEST(Transforms, ThreeDimensionalCentreIsTheNewProgramZero) {
  // the 3-D G68's X Y Z move the program zero there, then the system turns about I J K:
  // Mazak ch. 22 §4 "on établit un nouveau système de coordonnées de programme en déplaçant le
  // point zéro de pièce actuel jusqu'à la position désignée par X, Y et Z et en tournant ...";
  // Siemens §3.1.10 "回転中心点の座標は原点オフセットのように作用します" (the centre acts like
  // a zero offset). So a programmed point p goes to c + R p, not c + R (p - c).
  // `G68 X10. Y0 Z0 I0 J0 K1. R90.`: X0 Y0 Z0 -> (10, 0, 0); X5. -> (10, 0, 0) + (0, 5, 0).
  // ncc turns about (10, 0, 0) without moving the zero: (10, -10, 0) and (10, -5, 0).
  for (Dialect d : {Dialect::MazakM, Dialect::SiemensIsoM}) {
    SCOPED_TRACE(name(d));
    expectMoves(run(d, "G68 X10. Y0 Z0 I0 J0 K1. R90.\nG00 X0 Y0 Z0\nX5.\nM30\n"), kXYZ,
                {{"rapid", {{"X", 10}, {"Y", 0}, {"Z", 0}}},
                 {"rapid", {{"X", 10}, {"Y", 5}, {"Z", 0}}}});
  }
}

TEST(Transforms, MazakThreeDimensionalManualExampleNested) {
  // As ThreeDimensionalCentreIsTheNewProgramZero: ch. 22 §4's example: (2) `G68 X10. Y0
  // Z0 I0 J1 K0 R-30.` is system A, zero at (10, 0, 0), turned 30 deg clockwise about Y;
  // (3) `G68 X0 Y10. Z0 I1 J0 K0 R45.` is system B, zero at A's (0, 10, 0), turned 45 deg
  // counter-clockwise about X; (4) G69 restores the work system. Work = cA + RA (cB + RB p),
  // RA = Ry(-30): (x, y, z) -> (x cos30 - z sin30, y, x sin30 + z cos30).
  //   B (0, 0, 0): cA + RA (0, 10, 0) = (10, 10, 0).
  //   B (10, 0, 0): RB keeps it; + cB = (10, 10, 0); RA -> (8.6603, 10, 5); + cA:
  //   (18.6603, 10, 5).
  //   B (0, 10, 0): RB -> (0, 7.0711, 7.0711); + cB = (0, 17.0711, 7.0711); RA ->
  //   (-3.5355, 17.0711, 6.1237); + cA: (6.4645, 17.0711, 6.1237).
  //   After G69 (0, 0, 0) is the work zero again.
  Lowered r = run(Dialect::MazakM,
                  "G68 X10. Y0 Z0 I0 J1. K0 R-30.\nG68 X0 Y10. Z0 I1. J0 K0 R45.\nG00 X0 Y0 Z0\n"
                  "X10.\nX0 Y10.\nG69\nG00 X0 Y0 Z0\nM30\n");
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 10}, {"Y", 10}, {"Z", 0}}},
               {"rapid", {{"X", 18.6603}, {"Y", 10}, {"Z", 5}}},
               {"rapid", {{"X", 6.4645}, {"Y", 17.0711}, {"Z", 6.1237}}},
               {"rapid", {{"X", 0}, {"Y", 0}, {"Z", 0}}}});
}

TEST(Transforms, MazakThreeDimensionalCentreOmittedIsTheWorkZero) {
  // ch. 22 §2: "if X, Y and Z are omitted, the current work zero is taken as the new
  // program zero" (not the current position). From (5, 5): `G68 I0 J0 K1. R90.` turns about
  // (0, 0): (10, 0) -> (0, 10). ncc turns about (5, 5): (10, 10).
  expectMoves(run(Dialect::MazakM, "G00 X5. Y5.\nG68 I0 J0 K1. R90.\nG00 X10. Y0\nM30\n"), kXYZ,
              {{"rapid", {{"X", 5}, {"Y", 5}}}, {"rapid", {{"X", 0}, {"Y", 10}}}});
}

TEST(Transforms, ATiltedArcIsRefused) {
  // 30 deg about X tilts the XY plane: the G02's image is an ellipse in no principal plane.
  for (Dialect d : {Dialect::FanucM, Dialect::SiemensIsoM}) {
    SCOPED_TRACE(name(d));
    Lowered r = run(d, "G68 X0 Y0 Z0 I1. J0 K0 R30.\nG01 X10. Y0 Z0 F100.\nG02 X20. Y0 I5. J0\n"
                       "M30\n");
    EXPECT_EQ(firstDiag(r), "3:1: error[NCC2110]");
  }
  // 90 deg about X lays the XY arc into the ZX plane (y -> z): the ends (10, 0, 0), (20, 0, 0)
  // and the centre (15, 0, 0) stay, its middle (15, 5, 0) goes to (15, 0, 5). A G18 arc, seen
  // from +Y ((z, x) coordinates about the centre): (0, -5) -> (5, 0) -> (0, 5), the angle
  // growing from -90 to 90 deg: counter-clockwise. (The XY normal +Z went to -Y: clockwise
  // seen from -Y is counter-clockwise seen from +Y.)
  Lowered r = run(Dialect::SiemensIsoM,
                  "G68 X0 Y0 Z0 I1. J0 K0 R90.\nG01 X10. Y0 Z0 F100.\nG02 X20. Y0 I5. J0\nM30\n");
  expectMoves(r, kXYZ,
              {{"line", {{"X", 10}, {"Y", 0}, {"Z", 0}}},
               {"arc", {{"X", 20}, {"Y", 0}, {"Z", 0}}, {{"X", 15}, {"Y", 0}, {"Z", 0}}, false}});
}

// ---- G51 / G50 ----------------------------------------------------------------------------

TEST(Transforms, ScaleFactorWithAndWithoutDecimalPoint) {
  // P0.5 -> 0.5; P500 -> 500 x 0.001 (scale_factor_unit, FANUC SCR = 1 / MD22910 = 0) = 0.5;
  // with scale_factor_unit = 0.00001, P50000 = 0.5. About (0, 0): (10, 20) -> (5, 10).
  for (Dialect d : {Dialect::FanucM, Dialect::SiemensIsoM}) {
    SCOPED_TRACE(name(d));
    for (const char* p : {"P0.5", "P500"}) {
      Lowered r = run(d, std::string("G51 X0 Y0 ") + p + "\nG01 X10. Y20. F100.\nM30\n");
      expectMoves(r, kXYZ, {{"line", {{"X", 5}, {"Y", 10}}}});
    }
    Lowered fine = run(d, "G51 X0 Y0 P50000\nG01 X10. Y20. F100.\nM30\n",
                       "scale_factor_unit = 0.00001");
    expectMoves(fine, kXYZ, {{"line", {{"X", 5}, {"Y", 10}}}});
  }
  // Mazak §13-10 3.A / 4.7: P counts 0.000001 without a point (P500000 = 0.5), and a point is
  // read only after G51: `P0.5 G51` is P = 0, i.e. x1.
  for (const auto& [block, x, y] : {std::tuple{"G51 X0 Y0 P0.5", 5.0, 10.0},
                                    std::tuple{"P0.5 G51 X0 Y0", 10.0, 20.0},
                                    std::tuple{"P500000 G51 X0 Y0", 5.0, 10.0},
                                    std::tuple{"G51 X0 Y0 P500000", 5.0, 10.0}}) {
    SCOPED_TRACE(block);
    Lowered r = run(Dialect::MazakM, std::string(block) + "\nG01 X10. Y20. F100.\nM30\n");
    expectMoves(r, kXYZ, {{"line", {{"X", x}, {"Y", y}}}});
  }
}

TEST(Transforms, PerAxisFactorsAndANegativeOneMirrors) {
  // scale_per_axis = true (FANUC XSC, MD22914 = 1): I J K per axis, 0.001 each:
  // I2000 J-1000 -> x2, y-1: (10, 5) -> (20, -5).
  for (Dialect d : {Dialect::FanucM, Dialect::SiemensIsoM}) {
    SCOPED_TRACE(name(d));
    expectMoves(run(d, "G51 X0 Y0 I2000 J-1000\nG01 X10. Y5. F100.\nM30\n",
                    "scale_per_axis = true"),
                kXYZ, {{"line", {{"X", 20}, {"Y", -5}}}});
    // I1000 J-1000 mirrors Y: the G02 (10, 0) -> (15, 5) about (15, 0) ends at (15, -5) about
    // (15, 0), counter-clockwise.
    expectMoves(run(d, "G51 X0 Y0 I1000 J-1000\nG01 X10. Y0 F100.\nG02 X15. Y5. I5. J0\nM30\n",
                    "scale_per_axis = true"),
                kXYZ,
                {{"line", {{"X", 10}, {"Y", 0}}},
                 {"arc", {{"X", 15}, {"Y", -5}}, {{"X", 15}, {"Y", 0}}, false}});
    // x2 y1: the arc's image is an ellipse: refused (NCC2110) at its block.
    EXPECT_EQ(firstDiag(run(d, "G51 X0 Y0 I2000 J1000\nG01 X10. Y0 F100.\nG02 X15. Y5. I5. J0\n"
                               "M30\n",
                            "scale_per_axis = true")),
              "3:1: error[NCC2110]");
  }
}

TEST(Transforms, ArcsAndIncrementalMovesUnderUniformScaling) {
  // x2 about (0, 0): the line to (10, 0) -> (20, 0); the G02 to (20, 0) by R5 (centre (15, 0))
  // -> (40, 0) about (30, 0), radius 10, still clockwise.
  for (Dialect d : kAll) {
    SCOPED_TRACE(name(d));
    expectMoves(run(d, "G51 X0 Y0 P2.\nG01 X10. Y0 F100.\nG02 X20. Y0 R5.\nM30\n"), kXYZ,
                {{"line", {{"X", 20}, {"Y", 0}}},
                 {"arc", {{"X", 40}, {"Y", 0}}, {{"X", 30}, {"Y", 0}}, true}});
  }
  // Incremental moves are scaled too: x0.5, G91 X10. twice: (5, 0), (10, 0).
  expectMoves(run(Dialect::MazakM, "G51 X0 Y0 P0.5\nG91 G01 X10. F100.\nX10.\nM30\n"), kXYZ,
              {{"line", {{"X", 5}, {"Y", 0}}}, {"line", {{"X", 10}, {"Y", 0}}}});
}

TEST(Transforms, TheFactorWordTheParameterDoesNotReadIsIgnoredWithAWarning) {
  // MD22914 = 1 (scale_per_axis): "P is ignored"; = 0: "IJK are ignored" (§3.2.3 note).
  // I2000 J2000 -> x2: (10, 5) -> (20, 10); P500 -> x0.5: (5, 2.5).
  expectMoves(run(Dialect::SiemensIsoM, "G51 X0 Y0 I2000 J2000 P500\nG00 X10. Y5.\nM30\n",
                  "scale_per_axis = true"),
              kXYZ, {{"rapid", {{"X", 20}, {"Y", 10}}}}, 0.001,
              "1:23: warning[NCC2014]: G51 P is ignored: the factors are I, J, K "
              "(scale_per_axis = true)\n");
  expectMoves(run(Dialect::SiemensIsoM, "G51 X0 Y0 I2000 J2000 P500\nG00 X10. Y5.\nM30\n"), kXYZ,
              {{"rapid", {{"X", 5}, {"Y", 2.5}}}}, 0.001,
              "1:11: warning[NCC2014]: G51 I is ignored: the factor is P (scale_per_axis = false)\n"
              "1:17: warning[NCC2014]: G51 J is ignored: the factor is P (scale_per_axis = "
              "false)\n");
}

TEST(Transforms, MazakScalesOnlyTheAxesWhoseCentreIsGiven) {
  // §13-10 example II (3): `G51 X-100. P0.5`: X about -100 by 0.5, Y unscaled:
  // (-50, -50) -> (-100 + 0.5 x 50, -50) = (-75, -50).
  expectMoves(run(Dialect::MazakM, "G51 X-100. P0.5\nG00 X-50. Y-50.\nM30\n"), kXYZ,
              {{"rapid", {{"X", -75}, {"Y", -50}}}});
  // The centre follows G91 (§13-10 3.A): from (10, 10), G91 X5. Y5. is the centre (15, 15);
  // (25, 25) -> 15 + 0.5 x 10 = (20, 20).
  expectMoves(run(Dialect::MazakM, "G00 X10. Y10.\nG91 G51 X5. Y5. P0.5\nG90 G00 X25. Y25.\nM30\n"),
              kXYZ, {{"rapid", {{"X", 10}, {"Y", 10}}}, {"rapid", {{"X", 20}, {"Y", 20}}}});
}

// §13-10 5.3 "Mouvement fondamental III" (N01 G92 X0 Y0 ... N12 M02), N02 in its variants.
std::string mazakExampleIII(const std::string& g51) {
  return "N01 G92 X0 Y0\nN02 G90 " + g51 +
         "\nN03 G00 X-50. Y-50.\nN04 G01 Y-150. F1000\nN05 G02 X-100. I-25.\nN06 G01 X-150.\n"
         "N07 G02 X-200. I-25.\nN08 G01 X-250. Y-100.\nN09 Y-50.\nN10 X-50.\nN11 G00 G50\n"
         "N12 M02\n";
}

TEST(Transforms, MazakManualExampleIIIScaledInXAndY) {
  // (2) `G51 X-125. Y-100. P0.5`: x -> -125 + 0.5 (x + 125), y -> -100 + 0.5 (y + 100).
  // N03 (-50, -50) -> (-87.5, -75); N04 Y-150 -> -125; N05 the half circle to X-100 about X-75
  // -> to -112.5 about -100 (radius 12.5), clockwise; N06 X-150 -> -137.5; N07 to X-200 about
  // -175 -> to -162.5 about -150; N08 (-250, -100) -> (-187.5, -100); N09 Y-50 -> -75;
  // N10 X-50 -> -87.5; N11 G00 G50: back to the programmed (-50, -50) (§13-10 3.B).
  expectMoves(run(Dialect::MazakM, mazakExampleIII("G51 X-125. Y-100. P0.5")), kXYZ,
              {{"rapid", {{"X", -87.5}, {"Y", -75}}},
               {"line", {{"X", -87.5}, {"Y", -125}}},
               {"arc", {{"X", -112.5}, {"Y", -125}}, {{"X", -100}, {"Y", -125}}, true},
               {"line", {{"X", -137.5}, {"Y", -125}}},
               {"arc", {{"X", -162.5}, {"Y", -125}}, {{"X", -150}, {"Y", -125}}, true},
               {"line", {{"X", -187.5}, {"Y", -100}}},
               {"line", {{"X", -187.5}, {"Y", -75}}},
               {"line", {{"X", -87.5}, {"Y", -75}}},
               {"rapid", {{"X", -50}, {"Y", -50}}}});
}

TEST(Transforms, MazakManualExampleIIIScaledInXOnly) {
  // §13-10 5.3 (3) "Avec cadrage appliqué seulement en X": `G51 X-125. P0.5` on the same
  // program with its two G02 half circles is one of the manual's own worked examples, and
  // §13-10 4.5 says how: "in circular interpolation, scaling applies only to the axis (of the
  // plane's two) that is scaled" -- the end point and centre are scaled in X, the arc is still
  // cut as a circle (the radii at both ends agree; the affine image would be an ellipse).
  // x -> -125 + 0.5 (x + 125), y unscaled: N05 (-87.5, -150) -> (-112.5, -150) about
  // (-100, -150), radius 12.5 at both ends; N07 (-137.5, -150) -> (-162.5, -150) about
  // (-150, -150).
  expectMoves(run(Dialect::MazakM, mazakExampleIII("G51 X-125. P0.5")), kXYZ,
              {{"rapid", {{"X", -87.5}, {"Y", -50}}},
               {"line", {{"X", -87.5}, {"Y", -150}}},
               {"arc", {{"X", -112.5}, {"Y", -150}}, {{"X", -100}, {"Y", -150}}, true},
               {"line", {{"X", -137.5}, {"Y", -150}}},
               {"arc", {{"X", -162.5}, {"Y", -150}}, {{"X", -150}, {"Y", -150}}, true},
               {"line", {{"X", -187.5}, {"Y", -100}}},
               {"line", {{"X", -187.5}, {"Y", -50}}},
               {"line", {{"X", -87.5}, {"Y", -50}}},
               {"rapid", {{"X", -50}, {"Y", -50}}}});
}

TEST(Transforms, MazakG51InG51AddsAxesManualExample11) {
  // §13-10 5.11: N02 X about -150 by 0.75 (Y unscaled): X-50 -> -150 + 0.75 x 100 = -75,
  // X-250 -> -150 - 75 = -225. N08 adds Y about -125 and P0.5 applies to both: X-100 -> -125,
  // X-200 -> -175, Y-75 -> -125 + 25 = -100, Y-175 -> -150. N14 G50 X0 Y0: unscaled (0, 0).
  Lowered r = run(Dialect::MazakM,
                  "G51 X-150. P0.75\nG00 X-50. Y-25.\nG01 X-250. F1000.\nY-225.\nX-50.\nY-25.\n"
                  "G51 Y-125. P0.5\nG00 X-100. Y-75.\nG01 X-200.\nY-175.\nX-100.\nY-75.\n"
                  "G00 G50 X0 Y0\nM30\n");
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", -75}, {"Y", -25}}},
               {"line", {{"X", -225}, {"Y", -25}}},
               {"line", {{"X", -225}, {"Y", -225}}},
               {"line", {{"X", -75}, {"Y", -225}}},
               {"line", {{"X", -75}, {"Y", -25}}},
               {"rapid", {{"X", -125}, {"Y", -100}}},
               {"line", {{"X", -175}, {"Y", -100}}},
               {"line", {{"X", -175}, {"Y", -150}}},
               {"line", {{"X", -125}, {"Y", -150}}},
               {"line", {{"X", -125}, {"Y", -100}}},
               {"rapid", {{"X", 0}, {"Y", 0}}}});
}

TEST(Transforms, MazakG50AloneMovesBackFanucDoesNot) {
  // Mazak §13-10 3.B: G50 removes the deviation on every axis, in the motion mode in force:
  // (10, 10) scaled 0.5 about (0, 0) is (5, 5); G50 then goes to (10, 10).
  expectMoves(run(Dialect::MazakM, "G51 X0 Y0 P0.5\nG00 X10. Y10.\nG50\nM30\n"), kXYZ,
              {{"rapid", {{"X", 5}, {"Y", 5}}}, {"rapid", {{"X", 10}, {"Y", 10}}}});
  expectMoves(run(Dialect::MazakM, "G51 X0 Y0 P0.5\nG01 X10. Y10. F100.\nG50\nM30\n"), kXYZ,
              {{"line", {{"X", 5}, {"Y", 5}}}, {"line", {{"X", 10}, {"Y", 10}}}});
  // FANUC: G50 alone moves nothing; the next move goes to the unscaled (20, 10).
  expectMoves(run(Dialect::FanucM, "G51 X0 Y0 P0.5\nG00 X10. Y10.\nG50\nG00 X20.\nM30\n"), kXYZ,
              {{"rapid", {{"X", 5}, {"Y", 5}}}, {"rapid", {{"X", 20}, {"Y", 10}}}});
}

TEST(Transforms, ScaleFactorRangeAlarms) {
  // FANUC: 0.001..999.999, PS0142 "illegal scale rate" at the P word (column 11).
  EXPECT_EQ(firstDiag(run(Dialect::FanucM, "G51 X0 Y0 P1000.\nM30\n")), "1:11: error[PS0142]");
  EXPECT_EQ(firstDiag(run(Dialect::FanucM, "G51 X0 Y0 P0\nM30\n")), "1:11: error[PS0142]");
  // Mazak §13-10 3.A: above 99.999999 -> 809; below 0.000001 counts as 1 (no alarm, x1).
  EXPECT_EQ(firstDiag(run(Dialect::MazakM, "G51 X0 Y0 P100.\nM30\n")), "1:11: error[809]");
  expectMoves(run(Dialect::MazakM, "G51 X0 Y0 P0.0000001\nG00 X10. Y20.\nM30\n"), kXYZ,
              {{"rapid", {{"X", 10}, {"Y", 20}}}});
}

TEST(Transforms, ScaleCentreOmittedPerDialect) {
  // From (10, 10), `G51 P2.` and a move to (20, 10):
  //   FANUC: the centre is the current position (10, 10): (10 + 2 x 10, 10) = (30, 10);
  //   Siemens §3.2.3 "always the work origin": (40, 20);
  //   Mazak §13-10 3.A: only axes whose centre is given are scaled, none here: (20, 10).
  const std::string program = "G00 X10. Y10.\nG51 P2.\nG00 X20. Y10.\nM30\n";
  expectMoves(run(Dialect::FanucM, program), kXYZ,
              {{"rapid", {{"X", 10}, {"Y", 10}}}, {"rapid", {{"X", 30}, {"Y", 10}}}});
  expectMoves(run(Dialect::SiemensIsoM, program), kXYZ,
              {{"rapid", {{"X", 10}, {"Y", 10}}}, {"rapid", {{"X", 40}, {"Y", 20}}}});
  expectMoves(run(Dialect::MazakM, program), kXYZ,
              {{"rapid", {{"X", 10}, {"Y", 10}}}, {"rapid", {{"X", 20}, {"Y", 10}}}});
}

TEST(Transforms, DefaultScaleFactorWhenPIsOmitted) {
  // FANUC No.5411 / Mazak F20 / SD42140: the parameter's factor (0.5): (10, 20) -> (5, 10).
  for (Dialect d : kAll) {
    SCOPED_TRACE(name(d));
    expectMoves(run(d, "G51 X0 Y0\nG00 X10. Y20.\nM30\n", "default_scale_factor = 0.5"), kXYZ,
                {{"rapid", {{"X", 5}, {"Y", 10}}}});
  }
}

// ---- G51.1 / G50.1 ------------------------------------------------------------------------

TEST(Transforms, MirrorOneAxisReversesTheArcTwoAxesKeepIt) {
  // Mirror X about 5: x -> 10 - x. The line to (20, 0) -> (-10, 0); the G02 (20, 0) -> (25, 5)
  // about (25, 0) -> (-15, 5) about (-15, 0), counter-clockwise (Mazak §13-11, Siemens §3.2.4).
  // X about 5 and Y about 0: (-15, -5) about (-15, 0), clockwise again.
  for (Dialect d : kAll) {
    SCOPED_TRACE(name(d));
    expectMoves(run(d, "G51.1 X5.\nG01 X20. Y0 F100.\nG02 X25. Y5. I5. J0\nM30\n"), kXYZ,
                {{"line", {{"X", -10}, {"Y", 0}}},
                 {"arc", {{"X", -15}, {"Y", 5}}, {{"X", -15}, {"Y", 0}}, false}});
    expectMoves(run(d, "G51.1 X5. Y0\nG01 X20. Y0 F100.\nG02 X25. Y5. I5. J0\nM30\n"), kXYZ,
                {{"line", {{"X", -10}, {"Y", 0}}},
                 {"arc", {{"X", -15}, {"Y", -5}}, {{"X", -15}, {"Y", 0}}, true}});
  }
}

TEST(Transforms, MazakMirrorCentreMayBeIncremental) {
  // §13-11: the centre in G90 or G91: from X10, G91 X5. is the centre 15: X25 -> 30 - 25 = 5.
  expectMoves(run(Dialect::MazakM, "G00 X10. Y0\nG91 G51.1 X5.\nG90 G00 X25. Y0\nM30\n"), kXYZ,
              {{"rapid", {{"X", 10}, {"Y", 0}}}, {"rapid", {{"X", 5}, {"Y", 0}}}});
}

TEST(Transforms, MirrorCancel) {
  // G50.1 alone cancels every axis: (20, 5) unmirrored. `G50.1 X0` cancels X only (its value is
  // ignored, Mazak §13-11): Y stays mirrored about 10: (20, 20 - 5) = (20, 15).
  for (Dialect d : kAll) {
    SCOPED_TRACE(name(d));
    expectMoves(run(d, "G51.1 X10. Y10.\nG50.1\nG00 X20. Y5.\nM30\n"), kXYZ,
                {{"rapid", {{"X", 20}, {"Y", 5}}}});
    expectMoves(run(d, "G51.1 X10. Y10.\nG50.1 X0\nG00 X20. Y5.\nM30\n"), kXYZ,
                {{"rapid", {{"X", 20}, {"Y", 15}}}});
  }
}

TEST(Transforms, MirrorWithoutAxisAndIncrementalArcs) {
  // G51.1 names the axis by its centre word: none is a format error (Mazak 807).
  EXPECT_EQ(firstDiag(run(Dialect::FanucM, "G51.1\nM30\n")), "1:1: error[NCC2111]");
  EXPECT_EQ(firstDiag(run(Dialect::MazakM, "G51.1\nM30\n")), "1:1: error[807]");
  // Mirror X about 0: an incremental G02 X10. I5. from (0, 0) goes to (-10, 0) about (-5, 0),
  // counter-clockwise.
  for (Dialect d : kAll) {
    SCOPED_TRACE(name(d));
    expectMoves(run(d, "G51.1 X0\nG91 G02 X10. Y0 I5. F100.\nM30\n"), kXYZ,
                {{"arc", {{"X", -10}, {"Y", 0}}, {{"X", -5}, {"Y", 0}}, false}});
  }
}

TEST(Transforms, SiemensMirrorNotWhileScalingOrRotation) {
  // §3.2.4: mirror, scaling and rotation are switched on in that order: G51.1 (or G50.1) while
  // G51 or G68 is in force is refused at the G51.1.
  EXPECT_EQ(firstDiag(run(Dialect::SiemensIsoM, "G51 X0 Y0 P2.\nG51.1 X0\nM30\n")),
            "2:1: error[NCC2113]");
  EXPECT_EQ(firstDiag(run(Dialect::SiemensIsoM, "G68 X0 Y0 R10.\nG51.1 X0\nM30\n")),
            "2:1: error[NCC2113]");
  EXPECT_EQ(firstDiag(run(Dialect::SiemensIsoM, "G51.1 X0\nG68 X0 Y0 R10.\nG50.1\nM30\n")),
            "3:1: error[NCC2113]");
  // FANUC and Mazak have no such rule.
  EXPECT_EQ(run(Dialect::FanucM, "G51 X0 Y0 P2.\nG51.1 X0\nM30\n").diagText(), "");
  EXPECT_EQ(run(Dialect::MazakM, "G68 X0 Y0 R10.\nG51.1 X0\nM30\n").diagText(), "");
}

// ---- the order of composition -------------------------------------------------------------

TEST(Transforms, MazakRotatesBeforeMirroring) {
  // §13-8 1.3: "rotation is processed before the mirror image". Mirror X about 0, R90 about
  // (0, 0); (10, 0) -> turned (0, 10) -> mirrored (0, 10). Mirroring first would give (-10, 0)
  // turned = (0, -10).
  expectMoves(run(Dialect::MazakM, "G51.1 X0\nG68 X0 Y0 R90.\nG00 X10. Y0\nM30\n"), kXYZ,
              {{"rapid", {{"X", 0}, {"Y", 10}}}});
  // A centre off the mirror axis: R90 about (5, 0): (10, 0) -> (5, 5) -> mirrored (-5, 5)
  // (mirror first: (-10, 0) about (5, 0) -> (5, -15)). The same with G68 given first.
  for (const char* program : {"G51.1 X0\nG68 X5. Y0 R90.\nG00 X10. Y0\nM30\n",
                              "G68 X5. Y0 R90.\nG51.1 X0\nG00 X10. Y0\nM30\n"}) {
    SCOPED_TRACE(program);
    expectMoves(run(Dialect::MazakM, program), kXYZ, {{"rapid", {{"X", -5}, {"Y", 5}}}});
  }
  // §13-11: one mirrored plane axis reverses the arc under the rotation too: the G02 (10, 0)
  // -> (20, 0) about (15, 0) is turned about (0, 0) to (0, 10) -> (0, 20) about (0, 15), then
  // mirrored in X (x = 0 stays): counter-clockwise.
  expectMoves(run(Dialect::MazakM,
                  "G51.1 X0\nG68 X0 Y0 R90.\nG01 X10. Y0 F100.\nG02 X20. Y0 I5. J0\nM30\n"),
              kXYZ,
              {{"line", {{"X", 0}, {"Y", 10}}},
               {"arc", {{"X", 0}, {"Y", 20}}, {{"X", 0}, {"Y", 15}}, false}});
}

TEST(Transforms, SiemensSingleAxisMirrorReversesTheRotation) {
  // §3.2.4 table 3.6: with a mirror on one plane axis "座標回転: CW と CCW (回転方向) が入れ
  // 替わります" (the coordinate rotation's direction is reversed), as G02/G03 and G41/G42 are;
  // and G51.1 sits in base frame [1] (MM_NUM_BASE_FRAMES >= 2) while G68 needs >= 3 (§3.1.9):
  // the rotation is the later frame, applied to the programmed point first, the mirror after it.
  // Mirror X about 0 then R90 about (0, 0): (10, 0) -> R -> (0, 10) -> M -> (0, 10), i.e. R90
  // seen turning clockwise on the mirrored part. Mirroring first would give (-10, 0) -> (0, -10),
  // the rotation not reversed. (FANUC's programmable
  // mirror table, which Siemens ISO mode follows, says the same; no FANUC milling manual is in
  // /work/shared, so only Siemens is asserted.)
  expectMoves(run(Dialect::SiemensIsoM, "G51.1 X0\nG68 X0 Y0 R90.\nG00 X10. Y0\nM30\n"), kXYZ,
              {{"rapid", {{"X", 0}, {"Y", 10}}}});
}

TEST(Transforms, ScalingCentreTurnsWithTheRotation) {
  // Mazak §13-10 5.10: G51 in G68: the scaling centre is turned too. R90 about (0, 0), then
  // G51 X10. Y0 P2.: (20, 0) -> scaled about (10, 0): (30, 0) -> turned: (0, 30). (The centre
  // (10, 0) itself lands on (0, 10), the rotated centre.) Scaling acts before rotation in all
  // three orders, so FANUC gives the same.
  for (Dialect d : {Dialect::FanucM, Dialect::MazakM}) {
    SCOPED_TRACE(name(d));
    expectMoves(run(d, "G68 X0 Y0 R90.\nG51 X10. Y0 P2.\nG00 X20. Y0\nX10.\nM30\n"), kXYZ,
                {{"rapid", {{"X", 0}, {"Y", 30}}}, {"rapid", {{"X", 0}, {"Y", 10}}}});
  }
}

// ---- Mazak G92.5 --------------------------------------------------------------------------

TEST(Transforms, MazakWorkRotationByVector) {
  // §14-13 3.: `G17 G92.5 X10. Y20. I1. J2.`: atan(2/1) = 63.435 deg about (10, 20).
  // (11, 20) is (1, 0) from it -> (cos 63.435, sin 63.435) = (0.4472, 0.8944): (10.4472, 20.8944).
  expectMoves(run(Dialect::MazakM, "G17 G92.5 X10. Y20. I1. J2.\nG00 X11. Y20.\nM30\n"), kXYZ,
              {{"rapid", {{"X", 10.4472}, {"Y", 20.8944}}}});
  // The centre kept from power-on (machine zero) when X Y are omitted: (11, 20) turned by
  // 63.435 deg about (0, 0): (11 x 0.4472 - 20 x 0.8944, 11 x 0.8944 + 20 x 0.4472) =
  // (-12.9692, 18.7830).
  expectMoves(run(Dialect::MazakM, "G92.5 I1. J2.\nG00 X11. Y20.\nM30\n"), kXYZ,
              {{"rapid", {{"X", -12.9692}, {"Y", 18.7830}}}});
}

TEST(Transforms, MazakWorkRotationRBeatsTheVector) {
  // §14-13 3.: "if the angle and the axis vectors are given in one block, the first
  // (the angle R) has priority": R90 -> (11, 20) is (1, 0) from (10, 20) -> (10, 21). ncc
  // refuses the block: "1:17: error[NCC2014]: address I has no meaning in G92.5".
  expectMoves(run(Dialect::MazakM, "G92.5 X10. Y20. I1. J2. R90.\nG00 X11. Y20.\nM30\n"), kXYZ,
              {{"rapid", {{"X", 10}, {"Y", 21}}}});
}

TEST(Transforms, MazakWorkRotationIgnoresTheAxisOffThePlane) {
  // §14-13 3. (9): "the axis not in the selected plane is ignored": the manual's own
  // `G17 G92.5 X10. Y20. Z30. I1. J2. K3.` turns by 63.435 deg about (10, 20), Z and K
  // ignored; and since X, Y, Z once given stay in force, the following `G19 G92.5 J2. K3.`
  // turns by atan(3/2) = 56.301 deg about (Y20, Z30).
  // (Y21, Z30) is (1, 0) from (20, 30) in the YZ plane -> (0.5547, 0.8321): (Y20.5547, Z30.8321).
  Lowered r = run(Dialect::MazakM,
                  "G17 G92.5 X10. Y20. Z30. I1. J2. K3.\nG00 X11. Y20.\nG19 G92.5 J2. K3.\n"
                  "G00 X0 Y21. Z30.\nM30\n");
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 10.4472}, {"Y", 20.8944}, {"Z", 0}}},
               {"rapid", {{"X", 0}, {"Y", 20.5547}, {"Z", 30.8321}}}});
}

TEST(Transforms, MazakWorkRotationCentreInMachineCoordinates) {
  // §14-13 example 1: G55 = (100, 100); `G92.5 X0 Y0 R90.` turns about the MACHINE zero. Work
  // (0, 0) = machine (100, 100) -> (-100, 100); work (100, 0) = machine (200, 100) ->
  // (-100, 200); work (100, 200) = machine (200, 300) -> (-300, 200).
  Lowered r = lower(Dialect::MazakM,
                    "G17 G90 G55\nG92.5 X0 Y0 R90.\nG00 X0 Y0\nG01 X100. F1000.\nY200.\nM30\n",
                    g55Machine());
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", -100}, {"Y", 100}}},
               {"line", {{"X", -100}, {"Y", 200}}},
               {"line", {{"X", -300}, {"Y", 200}}}});
}

TEST(Transforms, MazakWorkRotationDrillsTurnedHoles) {
  // §14-13 example 2: G55 = (100, 100), G92.5 X100. Y100. R45. (the work zero): hole 1 work
  // (50, 50) = machine (150, 150), (50, 50) from the centre -> (0, 70.7107): (100, 170.7107);
  // hole 2 work (100, 50) = (200, 150): (100, 50) from it -> (100 cos45 - 50 sin45,
  // 100 sin45 + 50 cos45) = (35.3553, 106.0660): (135.3553, 206.0660). Z is not turned: the
  // feed goes to Z-25.
  Lowered r = lower(Dialect::MazakM,
                    "G17 G55 G90\nG92.5 X100. Y100. R45.\nG81 X50. Y50. Z-25. R-5. F500.\nX100.\n"
                    "G80\nM30\n",
                    g55Machine());
  ASSERT_EQ(r.diagText(), "");
  std::vector<Move> feeds;
  for (const Move& m : r.moves)
    if (m.kind == "line") feeds.push_back(m);
  ASSERT_EQ(feeds.size(), 2u);
  EXPECT_NEAR(feeds[0].to[0], 100, 1e-3);
  EXPECT_NEAR(feeds[0].to[1], 170.7107, 1e-3);
  EXPECT_NEAR(feeds[0].to[2], -25, 1e-3);
  EXPECT_NEAR(feeds[1].to[0], 135.3553, 1e-3);
  EXPECT_NEAR(feeds[1].to[1], 206.0660, 1e-3);
  EXPECT_NEAR(feeds[1].to[2], -25, 1e-3);
}

TEST(Transforms, MazakWorkRotationCancelAndKeptCentre) {
  // §14-13 3.: R0 cancels; the centre once given stays: R90 about (10, 0), cancel, then
  // `G92.5 R90.` turns about (10, 0) again: (20, 0) -> (10, 10).
  expectMoves(run(Dialect::MazakM,
                  "G92.5 X10. Y0 R90.\nG00 X20. Y0\nG92.5 R0\nG00 X20. Y0\nG92.5 R90.\n"
                  "G00 X20. Y0\nM30\n"),
              kXYZ,
              {{"rapid", {{"X", 10}, {"Y", 10}}},
               {"rapid", {{"X", 20}, {"Y", 0}}},
               {"rapid", {{"X", 10}, {"Y", 10}}}});
  // R omitted is R0: `G92.5 X0. Y0.` cancels.
  expectMoves(run(Dialect::MazakM, "G92.5 X0 Y0 R90.\nG92.5 X0 Y0\nG00 X20. Y0\nM30\n"), kXYZ,
              {{"rapid", {{"X", 20}, {"Y", 0}}}});
}

TEST(Transforms, MazakArcRightAfterWorkRotationIs817) {
  // §14-13 5.: the move after G92.5 must be G00/G01; an arc is alarm 817 at its G code.
  EXPECT_EQ(firstDiag(run(Dialect::MazakM, "G92.5 X0 Y0 R90.\nG02 X10. Y0 I5. F100.\nM30\n")),
            "2:1: error[817]");
  // After one line an arc is fine: the line to (10, 0) -> (0, 10); the G03 to (0, 10) about
  // (0, 0) -> (-10, 0) about (0, 0), counter-clockwise.
  expectMoves(run(Dialect::MazakM,
                  "G92.5 X0 Y0 R90.\nG01 X10. Y0 F100.\nG03 X0 Y10. I-10. J0\nM30\n"),
              kXYZ,
              {{"line", {{"X", 0}, {"Y", 10}}},
               {"arc", {{"X", -10}, {"Y", 0}}, {{"X", 0}, {"Y", 0}}, false}});
}

TEST(Transforms, MazakWorkRotationCancelManualExamples) {
  // §14-13 5.1 examples 1 (G91) and 2 (G90): R20 about the machine zero; Y50 -> (-50 sin20,
  // 50 cos20) = (-17.1010, 46.9846); X100 -> (100 cos20 - 50 sin20, 100 sin20 + 50 cos20) =
  // (76.8683, 81.1866); `G92.5 R0` cancels and the next move is not turned: "Déplacement au
  // point (100,0)"; then (0, 0).
  for (const char* program :
       {"N1 G28 X0 Y0\nN2 G17 G92.5 X0 Y0 R20.\nN3 G91 G01 Y50. F1000.\nN4 X100.\n"
        "N5 G92.5 R0\nN6 Y-50.\nN7 X-100.\nN8 M30\n",
        "N1 G28 X0 Y0\nN2 G17 G92.5 X0 Y0 R20.\nN3 G90 G01 Y50. F1000.\nN4 X100.\n"
        "N5 G92.5 R0\nN6 Y0\nN7 X0\nN8 M30\n"}) {
    SCOPED_TRACE(program);
    Lowered r = run(Dialect::MazakM, program);
    ASSERT_EQ(r.diagText(), "");
    std::vector<Move> lines;
    for (const Move& m : r.moves)
      if (m.kind == "line") lines.push_back(m);
    ASSERT_EQ(lines.size(), 4u);
    const double want[4][2] = {{-17.1010, 46.9846}, {76.8683, 81.1866}, {100, 0}, {0, 0}};
    for (size_t i = 0; i < 4; ++i) {
      EXPECT_NEAR(lines[i].to[0], want[i][0], 1e-3) << i;
      EXPECT_NEAR(lines[i].to[1], want[i][1], 1e-3) << i;
    }
  }
  // §14-13 5.1: the manual's own 817 example (an arc as the first move after G92.5).
  EXPECT_EQ(firstDiag(run(Dialect::MazakM, "N1 G28 X0 Y0\nN2 G91 G01 X50. F1000.\n"
                                           "N3 G17 G92.5 X0 Y0 R20.\nN4 G02 X40. Y40. I40.\n"
                                           "N5 M30\n")),
            "4:4: error[817]");
}

TEST(Transforms, ArcRightAfterACancelStartsOffItsCircle) {
  // after a move under a transform the tool stands at the mapped point; cancelling
  // (G69, G50.1, G92.5 R0) and going on with an arc starts it there, off its circle. Each
  // dialect's arc check must refuse it when compiling (FANUC PS0020, Mazak 817 -- §14-13 5.1
  // gives 817 for "the radius at the end point no longer equals the radius at the start point"
  // after G92.5 -- Siemens 14040). ncc compiles all three; the VM then stops with NCC7211 "was
  // the file edited?". R90 about (0, 0): the line to (10, 0) ends at (0, 10); the G02 to
  // (20, 0) about (15, 0) (I5 from the programmed start (10, 0)) starts 18.028 from its centre
  // and ends 5 from it (or, I5 taken from the real start, about (5, 10): 5 and 18.028).
  EXPECT_EQ(firstDiag(run(Dialect::FanucM, "G68 X0 Y0 R90.\nG01 X10. Y0 F100.\nG69\n"
                                           "G02 X20. Y0 I5.\nM30\n")),
            "4:1: error[PS0020]");
  EXPECT_EQ(firstDiag(run(Dialect::MazakM, "G92.5 X0 Y0 R90.\nG01 X10. Y0 F100.\nG92.5 R0\n"
                                           "G02 X20. Y0 I5.\nM30\n")),
            "4:1: error[817]");
  // Mirror X about 0: the line to (10, 0) ends at (-10, 0): 25 and 5 from (15, 0).
  EXPECT_EQ(firstDiag(run(Dialect::SiemensIsoM, "G51.1 X0\nG01 X10. Y0 F100.\nG50.1\n"
                                                "G02 X20. Y0 I5.\nM30\n")),
            "4:1: error[14040]");
}

// ---- interactions -------------------------------------------------------------------------

TEST(Transforms, HoleCycleUnderRotation) {
  // G81 X10. Y0 under R90 about (0, 0): the hole is at (0, 10); Z (the drilling axis, off the
  // plane) is not turned: R2 then the feed to Z-5.
  for (Dialect d : kAll) {
    SCOPED_TRACE(name(d));
    // (M03: Siemens drills only with the spindle turning, alarm 61102.)
    Lowered r = run(d, "M03 S1000\nG68 X0 Y0 R90.\nG81 X10. Y0 Z-5. R2. F100.\nG80\nM30\n");
    ASSERT_EQ(r.diagText(), "");
    ASSERT_FALSE(r.moves.empty());
    for (const Move& m : r.moves) {
      EXPECT_NEAR(m.to[0], 0, 1e-3);
      EXPECT_NEAR(m.to[1], 10, 1e-3);
    }
    bool fed = false;
    for (const Move& m : r.moves)
      if (m.kind == "line") {
        fed = true;
        EXPECT_NEAR(m.to[2], -5, 1e-3);
      }
    EXPECT_TRUE(fed);
  }
}

TEST(Transforms, CornersUnderScalingAreScaled) {
  // `,C2.` between (0,0)->(10,0) and ->(10,10): the chamfer (8, 0) -> (10, 2); x2 about the
  // origin: (16, 0) -> (20, 4) (a 4 mm chamfer), then (20, 20). `,R2.`: the arc (8, 0) ->
  // (10, 2) about (8, 2) counter-clockwise -> (16, 0) -> (20, 4) about (16, 4).
  for (Dialect d : {Dialect::FanucM, Dialect::MazakM}) {
    SCOPED_TRACE(name(d));
    expectMoves(run(d, "G51 X0 Y0 P2.\nG01 X10. Y0 ,C2. F100.\nY10.\nM30\n"), kXYZ,
                {{"line", {{"X", 16}, {"Y", 0}}},
                 {"line", {{"X", 20}, {"Y", 4}}},
                 {"line", {{"X", 20}, {"Y", 20}}}});
    expectMoves(run(d, "G51 X0 Y0 P2.\nG01 X10. Y0 ,R2. F100.\nY10.\nM30\n"), kXYZ,
                {{"line", {{"X", 16}, {"Y", 0}}},
                 {"arc", {{"X", 20}, {"Y", 4}}, {{"X", 16}, {"Y", 4}}, false},
                 {"line", {{"X", 20}, {"Y", 20}}}});
  }
}

TEST(Transforms, MazakHoleCycleShiftAndLevelsAreScaled) {
  // §13-10 4.4: the G76/G87 shift and the cycle's levels are scaled with the axes. x0.5 about
  // (0, 0, 0): the hole (10, 10) -> (5, 5); R-4 -> -2; Z-20 -> -10; the shift Q2 (along +X,
  // ncc's default shift direction) -> 1: (6, 5); back up to the initial level 0 and the hole.
  Lowered r = run(Dialect::MazakM,
                  "M03 S100\nG51 X0 Y0 Z0 P0.5\nG76 X10. Y10. Z-20. R-4. Q2. F100.\nG80\nM30\n");
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 5}, {"Y", 5}, {"Z", 0}}},
               {"rapid", {{"X", 5}, {"Y", 5}, {"Z", -2}}},
               {"line", {{"X", 5}, {"Y", 5}, {"Z", -10}}},
               {"rapid", {{"X", 6}, {"Y", 5}, {"Z", -10}}},
               {"rapid", {{"X", 6}, {"Y", 5}, {"Z", 0}}},
               {"rapid", {{"X", 5}, {"Y", 5}, {"Z", 0}}}});
}

TEST(Transforms, ReferenceReturnUnderRotation) {
  // Mazak §13-8 1.1 (reference returns are not rotated) and ch. 22 §5.3 (G28/G30: only the
  // intermediate point is); FANUC the same. R90 about
  // (5, 5): the intermediate (10, 0) is (5, -5) from it -> (5, 5) from it = (10, 10); the
  // reference point (machine zero) is not turned (turned it would be (10, 0)).
  for (Dialect d : {Dialect::FanucM, Dialect::MazakM}) {
    SCOPED_TRACE(name(d));
    Lowered r = run(d, "G68 X5. Y5. R90.\nG28 X10. Y0\nM30\n");
    expectMoves(r, kXYZ, {{"rapid", {{"X", 10}, {"Y", 10}}}, {"rapid", {{"X", 0}, {"Y", 0}}}});
  }
}

TEST(Transforms, MazakWorkOffsetChangeMovesTheScalingCentre) {
  // §13-10 5.7: G51 X-100. Y-100. P0.5 in G54 (zero); in G55 (100, 100) the centre moves with
  // the work system: work (-50, -50) -> (-75, -75), machine (25, 25).
  Lowered r = lower(Dialect::MazakM,
                    "G90 G54 G00 X0 Y0\nG51 X-100. Y-100. P0.5\nG00 X-50. Y-50.\n"
                    "G55 G00 X-50. Y-50.\nM30\n",
                    g55Machine());
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", -75}, {"Y", -75}}}, {"rapid", {{"X", 25}, {"Y", 25}}}});
}

TEST(Transforms, MazakLocalShiftMovesTheScalingAndMirrorCentres) {
  // §13-10 4.8: "if the coordinate system is shifted by G92 or G52 during scaling, the scaling
  // centre is shifted by the difference": G52 X100. moves the centre (0, 0) to work (100, 0):
  // local (0, 0) = (100, 0) stays; local X10 -> 100 + 0.5 x 10 = 105.
  expectMoves(run(Dialect::MazakM, "G51 X0 Y0 P0.5\nG52 X100. Y0\nG00 X0 Y0\nX10.\nM30\n"), kXYZ,
              {{"rapid", {{"X", 100}, {"Y", 0}}}, {"rapid", {{"X", 105}, {"Y", 0}}}});
  // §13-11: the mirror centre moves with the system too: local X10 mirrored about local 0 ->
  // local -10 = work 90.
  expectMoves(run(Dialect::MazakM, "G51.1 X0\nG52 X100. Y0\nG00 X10. Y0\nM30\n"), kXYZ,
              {{"rapid", {{"X", 90}, {"Y", 0}}}});
}

TEST(Transforms, MazakReferenceReturnEndsScaling) {
  // §13-10 5.5: G28 in G51 cancels scaling "at the intermediate point" (whether the move there
  // is still scaled the text leaves open, so it is not compared); then machine zero; the next
  // move, (20, 0), is no longer scaled (x0.5 it would be (10, 0)).
  Lowered r = run(Dialect::MazakM, "G51 X0 Y0 P0.5\nG28 X20. Y20.\nG00 X20. Y0\nM30\n");
  ASSERT_EQ(r.diagText(), "");
  ASSERT_EQ(r.moves.size(), 3u);
  EXPECT_NEAR(r.moves[1].to[0], 0, 1e-3);
  EXPECT_NEAR(r.moves[1].to[1], 0, 1e-3);
  EXPECT_NEAR(r.moves[2].to[0], 20, 1e-3);
  EXPECT_NEAR(r.moves[2].to[1], 0, 1e-3);
  // FANUC (its table: reference_return_cancels_scaling = false) keeps scaling after G28:
  // (20, 0) -> (10, 0).
  Lowered f = run(Dialect::FanucM, "G51 X0 Y0 P0.5\nG28 X20. Y20.\nG00 X20. Y0\nM30\n");
  ASSERT_EQ(f.diagText(), "");
  ASSERT_FALSE(f.moves.empty());
  EXPECT_NEAR(f.moves.back().to[0], 10, 1e-3);
  EXPECT_NEAR(f.moves.back().to[1], 0, 1e-3);
}

}  // namespace
}  // namespace ncc::passes::test
