// ,C / ,R corner chamfer and rounding (the corners pass, passes/src/corners.cpp): every pair of
// line and arc on fanuc-m and siemens-iso-m, Mazak's line-line rule, the planes, the alarms.
// The expected points are worked out from the geometry in the comments (machine = work here).
#include "expect_moves.h"

namespace ncc::passes::test {
namespace {

// The diagnostics contain `part` (printed in full otherwise).
#define EXPECT_DIAG(text, part)                                          \
  do {                                                                   \
    const std::string t_ = (text);                                       \
    EXPECT_NE(t_.find(part), std::string::npos) << t_ << "lacks " << part; \
  } while (0)

const std::vector<std::string> kXYZ = {"X", "Y", "Z"};

std::string metric() { return xyzMachine("decimal_point = \"standard\""); }

// ---- line - line ----

TEST(Corners, LineLineChamfer) {
  // (0,0)->(50,0) then ->(50,50): the chamfer runs from 10 before the virtual corner (40,0)
  // to 10 after it (50,10); the second line keeps its end point.
  Lowered r = lower(Dialect::FanucM, "G90 G01 X50. F100. ,C10.\nY50.\nM30\n", metric());
  expectMoves(r, kXYZ,
              {{"line", {{"X", 40}, {"Y", 0}}, {}, false, 100},
               {"line", {{"X", 50}, {"Y", 10}}, {}, false, 100},
               {"line", {{"X", 50}, {"Y", 50}}, {}, false, 100}});
  // The insert belongs to the ,C block.
  ASSERT_EQ(r.blocks[0].ops.size(), 2u);
  EXPECT_FALSE(r.blocks[0].corner.has_value());
}

TEST(Corners, LineLineChamferOblique) {
  // Mazak §13-14-1's example: G91 X100. then X100. Y100.; the second line's direction is
  // (1,1)/sqrt2, so the chamfer ends at (100 + 10/sqrt2, 10/sqrt2) = (107.0711, 7.0711).
  Lowered r = lower(Dialect::MazakM, "G91 G01 X100.,C10. F100\nX100. Y100.\nM30\n", metric());
  expectMoves(r, kXYZ,
              {{"line", {{"X", 90}, {"Y", 0}}},
               {"line", {{"X", 107.0711}, {"Y", 7.0711}}},
               {"line", {{"X", 200}, {"Y", 100}}}});
}

TEST(Corners, LineLineRoundLeftAndRight) {
  // Left turn: +X then +Y. The arc of radius 10 tangent to y = 0 and x = 50 has its centre
  // (40,10) on the inside; it runs counter-clockwise from (40,0) to (50,10).
  Lowered left = lower(Dialect::FanucM, "G01 X50. F100. ,R10.\nY50.\nM30\n", metric());
  expectMoves(left, kXYZ,
              {{"line", {{"X", 40}, {"Y", 0}}},
               {"arc", {{"X", 50}, {"Y", 10}}, {{"X", 40}, {"Y", 10}}, false, 100},
               {"line", {{"X", 50}, {"Y", 50}}}});
  // Right turn: +X then -Y: centre (40,-10), clockwise to (50,-10).
  Lowered right = lower(Dialect::FanucM, "G01 X50. F100. ,R10.\nY-50.\nM30\n", metric());
  expectMoves(right, kXYZ,
              {{"line", {{"X", 40}, {"Y", 0}}},
               {"arc", {{"X", 50}, {"Y", -10}}, {{"X", 40}, {"Y", -10}}, true, 100},
               {"line", {{"X", 50}, {"Y", -50}}}});
}

TEST(Corners, ConsecutiveCornersAndTheThirdAxis) {
  // A square corner after corner: each next move starts where the insert ended. The first
  // line also moves Z: it reaches Z-1 where the rounding starts; the arc moves no Z.
  Lowered r = lower(Dialect::FanucM,
                    "G01 X50. Z-1. F100. ,R10.\nY50. ,R10.\nX0 ,C5.\nY0\nM30\n", metric());
  expectMoves(r, kXYZ,
              {{"line", {{"X", 40}, {"Y", 0}, {"Z", -1}}},
               {"arc", {{"X", 50}, {"Y", 10}, {"Z", -1}}, {{"X", 40}, {"Y", 10}}, false},
               {"line", {{"X", 50}, {"Y", 40}}},
               {"arc", {{"X", 40}, {"Y", 50}}, {{"X", 40}, {"Y", 40}}, false},
               {"line", {{"X", 5}, {"Y", 50}}},
               {"line", {{"X", 0}, {"Y", 45}}},
               {"line", {{"X", 0}, {"Y", 0}}}});
}

TEST(Corners, StraightOnNothingIsInserted) {
  // Two collinear lines have no corner (Siemens §4.8.2: within 1 degree the insert has zero
  // length).
  Lowered r = lower(Dialect::SiemensIsoM, "G01 X50. F100. ,R10.\nX80.\nM30\n", metric());
  expectMoves(r, kXYZ, {{"line", {{"X", 50}}}, {"line", {{"X", 80}}}});
}

// ---- lines and arcs ----

TEST(Corners, LineArc) {
  // Line (0,0)->(50,0), then G02 around (70,0), r 20, to (70,20): it leaves (50,0) upwards, a
  // left turn. Rounding r 5: the centre is 5 above the line (y = 5) and 25 from (70,0) (the
  // outside of the clockwise arc): x = 70 - sqrt(625 - 25) = 45.5051. Tangent points: (45.5051,0)
  // on the line, (70,0) + 20 (q - c) / 25 = (50.4041, 4) on the arc.
  Lowered r = lower(Dialect::FanucM, "G01 X50. F100. ,R5.\nG02 X70. Y20. I20.\nM30\n", metric());
  expectMoves(r, kXYZ,
              {{"line", {{"X", 45.5051}, {"Y", 0}}},
               {"arc", {{"X", 50.4041}, {"Y", 4}}, {{"X", 45.5051}, {"Y", 5}}, false},
               {"arc", {{"X", 70}, {"Y", 20}}, {{"X", 70}, {"Y", 0}}, true}});
  // Chamfer 5: on the arc the point 5 from the corner (chord): u = 25/40 = 0.625 along x,
  // v = sqrt(25 - 0.625^2) = 4.9608.
  Lowered c = lower(Dialect::FanucM, "G01 X50. F100. ,C5.\nG02 X70. Y20. I20.\nM30\n", metric());
  expectMoves(c, kXYZ,
              {{"line", {{"X", 45}, {"Y", 0}}},
               {"line", {{"X", 50.625}, {"Y", 4.9608}}},
               {"arc", {{"X", 70}, {"Y", 20}}, {{"X", 70}, {"Y", 0}}, true}});
}

TEST(Corners, ArcLine) {
  // G02 around (0,0), r 20, from (0,20) to (20,0): it arrives going down (-Y); then +X, a
  // left turn. Rounding r 5: the centre is at y = 5, 25 from (0,0): x = sqrt(600) = 24.4949.
  // Tangent points: 20 q / 25 = (19.5959, 4) on the arc, (24.4949, 0) on the line.
  Lowered r = lower(Dialect::SiemensIsoM,
                    "G00 Y20.\nG02 X20. Y0 J-20. F100. ,R5.\nG01 X40.\nM30\n", metric());
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 0}, {"Y", 20}}},
               {"arc", {{"X", 19.5959}, {"Y", 4}}, {{"X", 0}, {"Y", 0}}, true},
               {"arc", {{"X", 24.4949}, {"Y", 0}}, {{"X", 24.4949}, {"Y", 5}}, false},
               {"line", {{"X", 40}, {"Y", 0}}}});
  // Chamfer 5: (20,0) - the point of the circle 5 away: x = 20 - 0.625, y = 4.9608.
  Lowered c = lower(Dialect::SiemensIsoM,
                    "G00 Y20.\nG02 X20. Y0 J-20. F100. ,C5.\nG01 X40.\nM30\n", metric());
  expectMoves(c, kXYZ,
              {{"rapid", {{"X", 0}, {"Y", 20}}},
               {"arc", {{"X", 19.375}, {"Y", 4.9608}}, {{"X", 0}, {"Y", 0}}, true},
               {"line", {{"X", 25}, {"Y", 0}}},
               {"line", {{"X", 40}, {"Y", 0}}}});
}

TEST(Corners, ArcArc) {
  // G02 around (0,0) r 20 from (0,20) to (20,0) (arriving -Y), then G03 around (20,10) r 10
  // to (30,10) (leaving +X): a left turn. Rounding r 2: the centre is 22 from (0,0) (outside
  // the clockwise arc) and 8 from (20,10) (inside the counter-clockwise one); of the two such
  // points the one near the corner is (21.8871, 2.2258). Tangent points: 20 q / 22 =
  // (19.8974, 2.0234); (20,10) + 10 (q - (20,10)) / 8 = (22.3589, 0.2822).
  Lowered r = lower(Dialect::FanucM,
                    "G00 Y20.\nG02 X20. Y0 J-20. F100. ,R2.\nG03 X30. Y10. J10.\nM30\n", metric());
  expectMoves(r, kXYZ,
              {{"rapid", {{"Y", 20}}},
               {"arc", {{"X", 19.8974}, {"Y", 2.0234}}, {{"X", 0}, {"Y", 0}}, true},
               {"arc", {{"X", 22.3589}, {"Y", 0.2822}}, {{"X", 21.8871}, {"Y", 2.2258}}, false},
               {"arc", {{"X", 30}, {"Y", 10}}, {{"X", 20}, {"Y", 10}}, false}});
}

// ---- planes ----

TEST(Corners, PlanesG18AndG19) {
  // G18 (Z, X): -Z then +X turns clockwise seen from +Y: centre (Z-40, X10).
  Lowered zx = lower(Dialect::FanucM, "G18 G01 Z-50. F100. ,R10.\nX50.\nM30\n", metric());
  expectMoves(zx, kXYZ,
              {{"line", {{"X", 0}, {"Z", -40}}},
               {"arc", {{"X", 10}, {"Z", -50}}, {{"X", 10}, {"Z", -40}}, true},
               {"line", {{"X", 50}, {"Z", -50}}}});
  // G19 (Y, Z): chamfer 10 between +Y and +Z.
  Lowered yz = lower(Dialect::FanucM, "G19 G01 Y50. F100. ,C10.\nZ50.\nM30\n", metric());
  expectMoves(yz, kXYZ,
              {{"line", {{"Y", 40}, {"Z", 0}}},
               {"line", {{"Y", 50}, {"Z", 10}}},
               {"line", {{"Y", 50}, {"Z", 50}}}});
}

// ---- words ----

TEST(Corners, MazakLastOfCommaCAndRWins) {
  Lowered r = lower(Dialect::MazakM, "G01 X50. F100 ,C10. ,R10.\nY50.\nM30\n", metric());
  ASSERT_EQ(r.diagText(), "");
  ASSERT_EQ(r.moves.size(), 3u);
  EXPECT_EQ(r.moves[1].kind, "arc");
}

TEST(Corners, CornerWordNeedsACuttingMove) {
  Lowered r = lower(Dialect::FanucM, "G00 X50. ,C10.\nY50.\nM30\n", metric());
  EXPECT_DIAG(r.diagText(), "error[NCC2014]");
  EXPECT_DIAG(r.diagText(), ",C (chamfer) needs a G01, G02 or G03 move");
  Lowered g04 = lower(Dialect::FanucM, "G04 X1. ,R2.\n", metric());
  EXPECT_DIAG(g04.diagText(), "error[NCC2014]");
}

TEST(Corners, DecimalPointRulesApply) {
  // Standard decimal point: ,C5000 is 5000 least increments = 5 mm.
  Lowered r = lower(Dialect::FanucM, "G01 X50. F100. ,C5000\nY50.\nM30\n", metric());
  expectMoves(r, kXYZ,
              {{"line", {{"X", 45}}}, {"line", {{"X", 50}, {"Y", 5}}}, {"line", {{"Y", 50}}}});
}

// ---- alarms ----

TEST(Corners, MazakAlarms) {
  // §13-14: 913 the chamfer longer than its block's move, 914 than the next block's, 912 the
  // next block not a linear move, 911 the next block an arc.
  EXPECT_DIAG(lower(Dialect::MazakM, "G01 X5.,C10. F100\nY50.\nM30\n", metric()).diagText(), "1:8: error[913]");
  EXPECT_DIAG(lower(Dialect::MazakM, "G01 X50.,R10. F100\nY5.\nM30\n", metric()).diagText(), "2:1: error[914]");
  EXPECT_DIAG(lower(Dialect::MazakM, "G01 X50.,C10. F100\nG00 Y50.\nM30\n", metric()).diagText(), "2:1: error[912]");
  EXPECT_DIAG(lower(Dialect::MazakM, "G01 X50.,C10. F100\nM30\n", metric()).diagText(), "2:1: error[912]");
  EXPECT_DIAG(
      lower(Dialect::MazakM, "G01 X50.,R10. F100\nG02 X70. Y20. I20.\nM30\n", metric()).diagText(), "2:1: error[911]");
}

TEST(Corners, FanucAndSiemensAlarms) {
  EXPECT_DIAG(lower(Dialect::FanucM, "G01 X5. F100. ,C10.\nY50.\nM30\n", metric()).diagText(), "error[PS0055]");
  EXPECT_DIAG(lower(Dialect::FanucM, "G01 X50. F100. ,C10.\nG00 Y50.\nM30\n", metric()).diagText(), "error[PS0052]");
  EXPECT_DIAG(
      lower(Dialect::FanucM, "G01 X50. F100. ,C10.\nG18 Z-50.\nM30\n", metric()).diagText(), "2:1: error[PS0051]: the block after a chamfer changes the plane");
  EXPECT_DIAG(lower(Dialect::SiemensIsoM, "G01 X50. F100. ,R10.\nM30\n", metric()).diagText(), "error[NCC2090]");
  // +X, then G03 around (30,0) r 20 leaving +Y: a left turn with the arc's centre inside it. A
  // rounding circle of r 30 would have to lie inside the r 20 circle: there is none.
  EXPECT_DIAG(lower(Dialect::SiemensIsoM, "G01 X50. F100. ,R30.\nG03 X30. Y20. I-20.\nM30\n",
                    metric())
                  .diagText(), "error[NCC2093]");
  // Nothing follows the corner block at all.
  EXPECT_DIAG(lower(Dialect::FanucM, "G01 X50. F100. ,C10.\n", metric()).diagText(), "1:16: error[PS0051]: no block with a move follows the chamfer");
}

}  // namespace
}  // namespace ncc::passes::test
