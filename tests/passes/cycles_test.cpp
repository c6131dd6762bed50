// Canned hole cycles (lowering_cycles.cpp, the `cycles` pass in cycle_expansion.cpp).
//
// The golden matrix drills three holes with each of G81, G83, G84 and G85 in every plane
// (G17/G18/G19), with G98 and G99, in G90 and in G91, once and with K3 repeats, and compares the
// move list with one worked out by hand from the manuals' sequence (Mazak §13-1-1 "seven
// movements", Siemens ISO §4.1.1, the FANUC family alike):
//   1. position in the plane (rapid), 2. rapid to R, 3. the cycle's way to the bottom,
//   4. the actions at the bottom, 5. back to R (feed for G84/G85, else rapid), 6. rapid to
//   the initial level (G98 only).
// Moves of zero length are not listed (the harness, like a conformance case, leaves them out).
#include <map>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "expect_moves.h"
#include "gmock/gmock.h"
#include "ncc/ir/ir.h"

namespace ncc::passes::test {
namespace {

const std::vector<std::string> kXYZ = {"X", "Y", "Z"};

struct PlaneCase {
  const char* g;
  const char* a;  // first plane axis
  const char* b;  // second plane axis
  const char* d;  // drilling axis (the plane's normal)
};
constexpr PlaneCase kPlanes[] = {
    {"G17", "X", "Y", "Z"}, {"G18", "Z", "X", "Y"}, {"G19", "Y", "Z", "X"}};

// The hand-worked sequence of one cycle between R (5) and the bottom (-10), the tool at R:
// the moves of steps 3-5 (the way back ends at R, or is the rapid of step 6 for G81/G83).
// F100 throughout.
std::vector<std::pair<std::string, double>> bottomSteps(int cycle) {
  switch (cycle) {
    case 81:  // §13-2 G81: feed to Z, rapid out
      return {{"line", -10}};
    case 83:  // G83 Q6, d = 1 (peck_clearance): feed 6, rapid to R, rapid to d above, ...
      return {{"line", -1}, {"rapid", 5}, {"rapid", 0}, {"line", -7},
              {"rapid", 5}, {"rapid", -6}, {"line", -10}};
    case 84:  // G84: feed to Z, spindle reverse, feed back to R
      return {{"line", -10}, {"line", 5}};
    case 85:  // G85: feed in, feed out to R
      return {{"line", -10}, {"line", 5}};
  }
  return {};
}

struct MatrixCase {
  int cycle;
  PlaneCase plane;
  bool g99;
  bool incremental;
  int repeats;
};

std::string matrixProgram(const MatrixCase& c) {
  const PlaneCase& p = c.plane;
  std::string q = c.cycle == 83 ? " Q6." : "";
  std::string spindle = c.cycle == 84 ? "M03 S100\n" : "";
  std::string k = c.repeats > 1 ? absl::StrCat(" K", c.repeats) : "";
  // The initial level: the drilling axis at 50 before the first cycle block.
  std::string head = absl::StrCat(spindle, p.g, " G90 G00 ", p.d, "50.\n");
  // G90: R5 and the bottom -10 as levels; G91: R-45 from the initial level (50 - 45 = 5) and
  // the bottom -15 from R (5 - 15 = -10); the hole increments 10 and 5 on each repeat.
  std::string cycle =
      c.incremental
          ? absl::StrCat(c.g99 ? "G99" : "G98", " G91 G", c.cycle, " ", p.a, "10. ", p.b, "5. R-45. ",
                         p.d, "-15.", q, " F100.", k, "\n")
          : absl::StrCat(c.g99 ? "G99" : "G98", " G90 G", c.cycle, " ", p.a, "10. ", p.b, "5. R5. ",
                         p.d, "-10.", q, " F100.", k, "\n");
  // A second hole by its position only (the data stay modal), then G80.
  std::string second = c.incremental ? absl::StrCat(p.a, "10.\n") : absl::StrCat(p.a, "40.\n");
  return absl::StrCat(head, cycle, second, "G80\n");
}

std::vector<Expected> matrixMoves(const MatrixCase& c) {
  const PlaneCase& p = c.plane;
  std::vector<Expected> out;
  std::map<std::string, double> at = {{"X", 0}, {"Y", 0}, {"Z", 0}};
  auto move = [&](const std::string& kind, const std::string& axis, double v, double feed) {
    if (at[axis] == v) return;
    at[axis] = v;
    out.push_back({kind, at, {}, false, feed});
  };
  move("rapid", p.d, 50, -1);
  const double level = c.g99 ? 5 : 50;
  auto hole = [&](double a, double b) {
    // 1. positioning in the plane: one rapid of both plane axes.
    if (at[p.a] != a || at[p.b] != b) {
      at[p.a] = a;
      at[p.b] = b;
      out.push_back({"rapid", at});
    }
    move("rapid", p.d, 5, -1);  // 2. rapid to R
    for (const auto& [kind, v] : bottomSteps(c.cycle))
      move(kind, p.d, v, kind == "line" ? 100 : -1);
    move("rapid", p.d, level, -1);  // 6. (or 5. for G81/G83) rapid to the return level
  };
  double a = 0, b = 0;
  const int n = c.repeats;
  for (int i = 0; i < n; ++i) {
    a = c.incremental ? a + 10 : 10;
    b = c.incremental ? b + 5 : 5;
    hole(a, b);
  }
  hole(c.incremental ? a + 10 : 40, b);  // the second block: one hole (K is one-shot)
  return out;
}

class CycleMatrix : public testing::TestWithParam<MatrixCase> {};

TEST_P(CycleMatrix, MovesAsWorkedOutByHand) {
  const MatrixCase& c = GetParam();
  std::string program = matrixProgram(c);
  SCOPED_TRACE(program);
  Lowered r = lower(Dialect::FanucM, program);
  expectMoves(r, kXYZ, matrixMoves(c));
}

std::vector<MatrixCase> allMatrixCases() {
  std::vector<MatrixCase> out;
  for (int cycle : {81, 83, 84, 85})
    for (const PlaneCase& p : kPlanes)
      for (bool g99 : {false, true})
        for (bool inc : {false, true})
          for (int k : {1, 3}) out.push_back({cycle, p, g99, inc, k});
  return out;
}

std::string matrixName(const testing::TestParamInfo<MatrixCase>& info) {
  const MatrixCase& c = info.param;
  return absl::StrCat("G", c.cycle, "_", c.plane.g, c.g99 ? "_G99" : "_G98",
                      c.incremental ? "_G91" : "_G90", "_K", c.repeats);
}

INSTANTIATE_TEST_SUITE_P(Fanuc, CycleMatrix, testing::ValuesIn(allMatrixCases()), matrixName);

// ---- literal sequences ----

TEST(Cycles, G73HighSpeedPeckBacksOffD) {
  // FANUC-family G73: feed Q, rapid back d (peck_return), feed d + Q, ... to Z; rapid out.
  // R2 bottom -10 Q5 d 0.5: 2 -> -3, back -2.5, -> -8, back -7.5, -> -10, out to 50 (G98).
  Lowered r = lower(Dialect::FanucM, "G00 Z50.\nG98 G73 X5. R2. Z-10. Q5. F80.\nG80\n",
                    xyzMachine("peck_return = 0.5"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", 50}}},
               {"rapid", {{"X", 5}, {"Y", 0}, {"Z", 50}}},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -3}}, {}, false, 80},
               {"rapid", {{"Z", -2.5}}},
               {"line", {{"Z", -8}}, {}, false, 80},
               {"rapid", {{"Z", -7.5}}},
               {"line", {{"Z", -10}}, {}, false, 80},
               {"rapid", {{"X", 5}, {"Z", 50}}}});
}

TEST(Cycles, MazakG73BacksOffAtTheFixedReturnSpeed) {
  // Mazak §13-1-6: the return d is at f2 = 9999 mm/min (F12 = peck_return).
  Lowered r = lower(Dialect::MazakM, "G00 Z50.\nG98 G73 R2. Z-6. Q5. F80.\nG80\n",
                    xyzMachine("decimal_point = \"calculator\"\npeck_return = 1.0"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", 50}}},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -3}}, {}, false, 80},
               {"line", {{"Z", -2}}, {}, false, 9999},
               {"line", {{"Z", -6}}, {}, false, 80},
               {"rapid", {{"Z", 50}}}});
}

TEST(Cycles, MazakDInAPeckCycleIsTheReturnAmount) {
  // §13-1-6: D is d0, the return distance (F12 only when D is omitted or 0); it is cycle data
  // here, not a radius offset number, and stays modal.
  Lowered r = lower(Dialect::MazakM, "G00 Z10.\nG98 G73 R2. Z-6. Q3. D2. F100.\nX1.\nG80\n",
                    xyzMachine("decimal_point = \"calculator\""));
  std::vector<Expected> hole = {{"rapid", {{"Z", 2}}},
                                {"line", {{"Z", -1}}, {}, false, 100},
                                {"line", {{"Z", 1}}, {}, false, 9999},
                                {"line", {{"Z", -4}}, {}, false, 100},
                                {"line", {{"Z", -2}}, {}, false, 9999},
                                {"line", {{"Z", -6}}, {}, false, 100},
                                {"rapid", {{"Z", 10}}}};
  std::vector<Expected> all = {{"rapid", {{"Z", 10}}}};
  all.insert(all.end(), hole.begin(), hole.end());
  all.push_back({"rapid", {{"X", 1}, {"Z", 10}}});
  all.insert(all.end(), hole.begin(), hole.end());
  expectMoves(r, kXYZ, all);
}

TEST(Cycles, G82DwellsPMillisecondsAtTheBottom) {
  Lowered r = lower(Dialect::FanucM, "G00 Z20.\nG99 G82 X1. R2. Z-3. P1500 F50.\nG80\n");
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", 20}}},
               {"rapid", {{"X", 1}, {"Z", 20}}},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -3}}, {}, false, 50},
               {"dwell", {}, {}, false, -1, 1.5},
               {"rapid", {{"Z", 2}}}});
}

TEST(Cycles, MazakTappingDwellIsInSecondsAndPositionsByTheGroup01Code) {
  // §13-1-2: G84 P in seconds; §13-1-1 movement 1: in G01 the positioning is a feed move.
  Lowered r = lower(Dialect::MazakM, "M03 S500\nG01 Z30. F200.\nG98 G84 X4. R2. Z-5. P1. F100.\nG80\n",
                    xyzMachine("decimal_point = \"calculator\""));
  expectMoves(r, kXYZ,
              {{"line", {{"Z", 30}}, {}, false, 200},
               {"line", {{"X", 4}, {"Z", 30}}, {}, false, 100},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -5}}, {}, false, 100},
               {"dwell", {}, {}, false, -1, 1.0},
               {"line", {{"Z", 2}}, {}, false, 100},
               {"rapid", {{"Z", 30}}}});
  // The spindle reverses at the bottom and turns forward again at R.
  std::vector<ir::MachineFunction::Kind> spindle;
  for (const ir::Block& b : r.blocks)
    for (const ir::Operation& op : b.ops)
      if (auto* f = std::get_if<ir::MachineFunction>(&op)) spindle.push_back(f->kind);
  using K = ir::MachineFunction::Kind;
  EXPECT_THAT(spindle, testing::Contains(K::SpindleCCW));
  EXPECT_EQ(spindle.back(), K::SpindleCW);
}

TEST(Cycles, MazakSynchronousTappingFeedsThePitchPerRevolution) {
  // §13-1-22 3.: G84.2 F is the pitch; P dwells at Z and at R; the way out at K90 %
  // (tap_retract_percent 50 here).
  Lowered r = lower(Dialect::MazakM, "M03 S500\nG00 Z10.\nG98 G84.2 R2. Z-5. P1. F1.25\nG80\n",
                    xyzMachine("decimal_point = \"calculator\"\ntap_retract_percent = 50"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -5}}, {}, false, 1.25},
               {"dwell", {}, {}, false, -1, 1.0},
               {"line", {{"Z", 2}}, {}, false, 0.625},
               {"dwell", {}, {}, false, -1, 1.0},
               {"rapid", {{"Z", 10}}}});
  int per_rev = 0;
  for (const ir::Operation& op : r.blocks[2].ops)
    if (auto* l = std::get_if<ir::Linear>(&op)) per_rev += l->feed_per_rev;
  EXPECT_EQ(per_rev, 2);
}

TEST(Cycles, MazakFeedStartAndSlowZone) {
  // §13-1-15 G83: K3 = the feed starts 3 below R (R 2: at -1, reached by rapid); I3 J50 = an
  // infeed that starts within 3 of the bottom (-10) runs at 50 % of F. Q4, d = peck_clearance 1:
  // -1 -> -5 (starts 9 above the bottom: F200); R; -4 -> -9 (6 above: F200); R; -8 -> -10 (2
  // above: F100); out to R (G99).
  Lowered r = lower(Dialect::MazakM,
                    "M03 S500\nG00 Z10.\nG99 G83 R2. Z-10. Q4. K3. I3. J50 F200.\nG80\n",
                    xyzMachine("decimal_point = \"calculator\""));
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"rapid", {{"Z", 2}}},
               {"rapid", {{"Z", -1}}},
               {"line", {{"Z", -5}}, {}, false, 200},
               {"rapid", {{"Z", 2}}},
               {"rapid", {{"Z", -4}}},
               {"line", {{"Z", -9}}, {}, false, 200},
               {"rapid", {{"Z", 2}}},
               {"rapid", {{"Z", -8}}},
               {"line", {{"Z", -10}}, {}, false, 100},
               {"rapid", {{"Z", 2}}}});
  // §13-1-14 G82: D is where the feed starts (not a radius offset number). D4: from -2, 8 above
  // the bottom, F200; D9: from -7, 3 above, within I3: F100. Back to the initial level (G98).
  Lowered g82 = lower(Dialect::MazakM,
                      "M03 S500\nG00 Z10.\nG98 G82 R2. Z-10. D4. I3. J50 F200.\nD9. X5.\nG80\n",
                      xyzMachine("decimal_point = \"calculator\""));
  expectMoves(g82, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"rapid", {{"Z", 2}}},
               {"rapid", {{"Z", -2}}},
               {"line", {{"Z", -10}}, {}, false, 200},
               {"rapid", {{"Z", 10}}},
               {"rapid", {{"X", 5}, {"Z", 10}}},
               {"rapid", {{"X", 5}, {"Z", 2}}},
               {"rapid", {{"X", 5}, {"Z", -7}}},
               {"line", {{"X", 5}, {"Z", -10}}, {}, false, 100},
               {"rapid", {{"X", 5}, {"Z", 10}}}});
  // J is a percentage above 0.
  Lowered j0 = lower(Dialect::MazakM, "G00 Z10.\nG83 R2. Z-10. Q4. I3. J0 F200.\n",
                     xyzMachine("decimal_point = \"calculator\""));
  EXPECT_NE(j0.diagText().find("2:23: error[NCC2031]: G83 J0: the slowed feed must be a percentage "
                               "above 0"),
            std::string::npos)
      << j0.diagText();
  // FANUC reads no such words: K is the repeat count there, I J have no meaning in G83.
  Lowered fanuc = lower(Dialect::FanucM, "G00 Z10.\nG83 R2. Z-10. Q4. I3. F200.\n");
  EXPECT_NE(fanuc.diagText().find("2:19: error[NCC2014]"), std::string::npos) << fanuc.diagText();
}

TEST(Cycles, FanucDeepHoleRigidTappingPecksOnlyAfterM29) {
  // Lathe manual §4.4 (notes §4.5), PCP = 0: tap q, back off d (peck_return 1), tap d + q, ...;
  // the back-offs and the way out at the retract speed (100 % here). From R 2 to Z-7, Q3:
  // -1, back to 0, -4, back to -3, -7; out to R 2.
  // M29 after the G00: a group-01 code ends rigid mode as it ends a cycle (and G80).
  const std::string rigid_program = "M03 S500\nG00 Z10.\nM29 S500\nG99 G84 R2. Z-7. Q3. F500.\nG80\n";
  const char* program = "M03 S500\nG00 Z10.\nG99 G84 R2. Z-7. Q3. F500.\nG80\n";
  Lowered floating = lower(Dialect::FanucM, program);
  expectMoves(floating, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -7}}, {}, false, 500},
               {"line", {{"Z", 2}}, {}, false, 500}});
  Lowered rigid = lower(Dialect::FanucM, rigid_program);
  expectMoves(rigid, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -1}}, {}, false, 500},
               {"line", {{"Z", 0}}, {}, false, 500},
               {"line", {{"Z", -4}}, {}, false, 500},
               {"line", {{"Z", -3}}, {}, false, 500},
               {"line", {{"Z", -7}}, {}, false, 500},
               {"line", {{"Z", 2}}, {}, false, 500}});
  // PCP = 1 (peck_tapping_type = "peck"): out to R after each infeed, back to d (peck_clearance
  // 0.5) above the last depth at the retract speed (tap_retract_percent 200: 1000).
  Lowered peck = lower(Dialect::FanucM, rigid_program,
                       xyzMachine("peck_tapping_type = \"peck\"\npeck_clearance = 0.5\n"
                                  "tap_retract_percent = 200"));
  expectMoves(peck, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -1}}, {}, false, 500},
               {"line", {{"Z", 2}}, {}, false, 1000},
               {"line", {{"Z", -0.5}}, {}, false, 1000},
               {"line", {{"Z", -4}}, {}, false, 500},
               {"line", {{"Z", 2}}, {}, false, 1000},
               {"line", {{"Z", -3.5}}, {}, false, 1000},
               {"line", {{"Z", -7}}, {}, false, 500},
               {"line", {{"Z", 2}}, {}, false, 1000}});
}

TEST(Cycles, SiemensPeckTappingByTheTappingType) {
  // §4.1.13, _ZSFI[1] = 3 (tapping_type "peck"): tap Q, out to R, back at F to d above the
  // last depth, tap d + Q. d = 0.5: -1, R 2, -0.5, -4, R 2, -3.5, -7, out to R.
  const char* program = "M03 S500\nG00 Z10.\nG99 G84 R2. Z-7. Q3. F500.\nG80\n";
  Lowered peck = lower(Dialect::SiemensIsoM, program,
                       xyzMachine("decimal_point = \"calculator\"\ntapping_type = \"peck\"\n"
                                  "peck_clearance = 0.5"));
  expectMoves(peck, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -1}}, {}, false, 500},
               {"line", {{"Z", 2}}, {}, false, 500},
               {"line", {{"Z", -0.5}}, {}, false, 500},
               {"line", {{"Z", -4}}, {}, false, 500},
               {"line", {{"Z", 2}}, {}, false, 500},
               {"line", {{"Z", -3.5}}, {}, false, 500},
               {"line", {{"Z", -7}}, {}, false, 500},
               {"line", {{"Z", 2}}, {}, false, 500}});
  // _ZSFI[1] = 0 (rigid, the default): Q is cycle data only, one infeed.
  Lowered rigid = lower(Dialect::SiemensIsoM, program, xyzMachine("decimal_point = \"calculator\""));
  expectMoves(rigid, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -7}}, {}, false, 500},
               {"line", {{"Z", 2}}, {}, false, 500}});
}

TEST(Cycles, FanucTappingDwellsAtTheBottomAndAtR) {
  Lowered r = lower(Dialect::FanucM, "M03 S500\nG00 Z10.\nG99 G84 R2. Z-5. P200 F100.\nG80\n");
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -5}}, {}, false, 100},
               {"dwell", {}, {}, false, -1, 0.2},
               {"line", {{"Z", 2}}, {}, false, 100},
               {"dwell", {}, {}, false, -1, 0.2}});
}

TEST(Cycles, G86StopsTheSpindleAndRapidsOut) {
  Lowered r = lower(Dialect::FanucM, "M03 S500\nG00 Z10.\nG98 G86 R2. Z-5. F100.\nG80\n");
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -5}}, {}, false, 100},
               {"rapid", {{"Z", 10}}}});
  std::vector<ir::MachineFunction::Kind> spindle;
  for (const ir::Operation& op : r.blocks[2].ops)
    if (auto* f = std::get_if<ir::MachineFunction>(&op)) spindle.push_back(f->kind);
  using K = ir::MachineFunction::Kind;
  EXPECT_EQ(spindle, (std::vector<K>{K::SpindleStop, K::SpindleCW}));
}

TEST(Cycles, G76ShiftsOffTheWallInTheConfiguredDirection) {
  // boring_shift_direction 3: + second plane axis (Y in G17). Q2: shift 2 at the bottom.
  Lowered r = lower(Dialect::FanucM, "M03 S500\nG00 Z10.\nG99 G76 X5. R2. Z-5. Q2. F100.\nG80\n",
                    xyzMachine("boring_shift_direction = 3"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"rapid", {{"X", 5}, {"Y", 0}, {"Z", 10}}},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -5}}, {}, false, 100},
               {"rapid", {{"X", 5}, {"Y", 2}, {"Z", -5}}},
               {"rapid", {{"X", 5}, {"Y", 2}, {"Z", 2}}},
               {"rapid", {{"X", 5}, {"Y", 0}, {"Z", 2}}}});
}

TEST(Cycles, G87BacksBoresUpwardsAndAlwaysReturnsToTheInitialLevel) {
  // Siemens §4.1 table / FANUC common: orient, shift Q off the axis (+X, RD1 = RD2 = 0), rapid
  // down to R (below the part), shift back, spindle on, bore up to Z, orient, shift, rapid to
  // the initial level (also in G99), shift back.
  Lowered r = lower(Dialect::FanucM, "M03 S500\nG00 Z10.\nG99 G87 X5. R-20. Z-8. Q1.5 F100.\nG80\n");
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"rapid", {{"X", 5}, {"Z", 10}}},
               {"rapid", {{"X", 6.5}, {"Z", 10}}},
               {"rapid", {{"X", 6.5}, {"Z", -20}}},
               {"rapid", {{"X", 5}, {"Z", -20}}},
               {"line", {{"X", 5}, {"Z", -8}}, {}, false, 100},
               {"rapid", {{"X", 6.5}, {"Z", -8}}},
               {"rapid", {{"X", 6.5}, {"Z", 10}}},
               {"rapid", {{"X", 5}, {"Z", 10}}}});
  // Siemens 61101: for G87, R must lie below Z.
  Lowered bad = lower(Dialect::SiemensIsoM, "M3 S100\nG00 Z10.\nG87 X1. R2. Z-5. Q1. F100.\n",
                      xyzMachine("decimal_point = \"calculator\""));
  EXPECT_THAT(bad.diagText(), testing::HasSubstr("3:9: error[61101]"));
}

TEST(Cycles, G88StopsForTheOperatorAtTheBottom) {
  // Mazak §13-1-2 / notes §4.6: "M05 + M00 at the bottom"; after cycle start, rapid out.
  Lowered r = lower(Dialect::MazakM, "M03 S500\nG00 Z10.\nG98 G88 R2. Z-5. P500 F100.\nG80\n",
                    xyzMachine("decimal_point = \"calculator\""));
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -5}}, {}, false, 100},
               {"dwell", {}, {}, false, -1, 0.5},
               {"rapid", {{"Z", 10}}}});
  std::vector<ir::MachineFunction::Kind> functions;
  for (const ir::Operation& op : r.blocks[2].ops)
    if (auto* f = std::get_if<ir::MachineFunction>(&op)) functions.push_back(f->kind);
  using K = ir::MachineFunction::Kind;
  EXPECT_EQ(functions, (std::vector<K>{K::SpindleStop, K::ProgramStop, K::SpindleCW}));
}

TEST(Cycles, StoreOnlyBlocksAndCancel) {
  // K0 stores the data; a block without a positioning word (only F) does not drill; the next
  // position drills with the stored data; a group-01 code ends the cycle (G00 X moves only).
  Lowered r = lower(Dialect::FanucM,
                    "G00 Z10.\nG81 R2. Z-5. F100. K0\nF120.\nX3.\nG00 X6.\n");
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"rapid", {{"X", 3}, {"Z", 10}}},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -5}}, {}, false, 120},
               {"rapid", {{"Z", 10}}},
               {"rapid", {{"X", 6}, {"Z", 10}}}});
}

TEST(Cycles, G80ClearsTheCycleData) {
  // After G80 the data are gone: a new G81 without Z is an error.
  Lowered r = lower(Dialect::FanucM, "G00 Z10.\nG81 X1. R2. Z-5. F100.\nG80\nG81 X2.\n");
  EXPECT_THAT(r.diagText(), testing::HasSubstr("4:1: error[NCC2096]"));
}

// ---- bad input: the manual's alarm and the block's position, and no move of the block ----

struct BadCase {
  Dialect dialect;
  std::string params;
  std::string program;
  std::string where;  // "line:col: error[CODE]"
};

class CycleAlarm : public testing::TestWithParam<BadCase> {};

TEST_P(CycleAlarm, ReportsTheAlarmAtItsPlace) {
  const BadCase& c = GetParam();
  Lowered r = lower(c.dialect, c.program, xyzMachine(c.params));
  EXPECT_THAT(r.diagText(), testing::HasSubstr(c.where)) << c.program;
  // Nothing of the rejected block is emitted: no feed move (the cycle's cut) at all.
  for (const Move& m : r.moves) EXPECT_NE(m.kind, "line");
}

const std::string kCalc = "decimal_point = \"calculator\"";

INSTANTIATE_TEST_SUITE_P(
    All, CycleAlarm,
    testing::Values(
        // FANUC: Q missing in G73/G83 is PS0045 (FANUC common); Q0 / negative Q NCC2097; no Z.
        BadCase{Dialect::FanucM, "", "G00 Z10.\nG83 X1. R2. Z-5. F100.\n", "2:1: error[PS0045]"},
        BadCase{Dialect::FanucM, "", "G00 Z10.\nG73 X1. R2. Z-5. Q0 F100.\n", "2:18: error[NCC2097]"},
        BadCase{Dialect::FanucM, "", "G00 Z10.\nG83 X1. R2. Z-5. Q-1. F100.\n", "2:18: error[NCC2097]"},
        BadCase{Dialect::FanucM, "", "G00 Z10.\nG81 X1. R2. F100.\n", "2:1: error[NCC2096]"},
        // A Q tiny against the depth (100,000 pecks at most per block, K included).
        BadCase{Dialect::FanucM, "", "G00 Z10.\nG83 X1. R2. Z-500. Q0.000001 F100.\n",
                "2:20: error[NCC2031]"},
        BadCase{Dialect::FanucM, "", "G00 Z10.\nG83 X1. R2. Z-98. Q0.01 K11 F100.\n",
                "2:19: error[NCC2031]"},
        BadCase{Dialect::FanucM, "", "G00 Z10.\nG81 X1. R2. Z-3.\n", "2:1: error[PS0011]"},
        // Mazak §13-1-6: Q0 -> 809; §13-1-3: Q omitted -> the same alarm.
        BadCase{Dialect::MazakM, kCalc, "G00 Z10.\nG73 X1. R2. Z-5. Q0 F100.\n", "2:18: error[809]"},
        BadCase{Dialect::MazakM, kCalc, "G00 Z10.\nG83 X1. R2. Z-5. F100.\n", "2:1: error[809]"},
        // Siemens App. D: 61808 no depth / no Q, 61003 no feed, 61102 no spindle direction,
        // 61101 R not above the bottom.
        BadCase{Dialect::SiemensIsoM, kCalc, "M3 S100\nG00 Z10.\nG81 X1. R2. F100.\n",
                "3:1: error[61808]"},
        BadCase{Dialect::SiemensIsoM, kCalc, "M3 S100\nG00 Z10.\nG83 X1. R2. Z-5. Q0 F100.\n",
                "3:18: error[61808]"},
        BadCase{Dialect::SiemensIsoM, kCalc, "S100\nG00 Z10.\nG81 X1. R2. Z-5. F100.\n",
                "3:1: error[61102]"},
        BadCase{Dialect::SiemensIsoM, kCalc, "M3 S100\nG00 Z10.\nG81 X1. R-8. Z-5. F100.\n",
                "3:9: error[61101]"}));

TEST(Cycles, SiemensTakesQPositive) {
  // §4.1: "Q must be positive (the sign is ignored)".
  Lowered r = lower(Dialect::SiemensIsoM, "M3 S100\nG00 Z10.\nG83 R2. Z-5. Q-4. F100.\nG80\n",
                    xyzMachine(kCalc));
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"rapid", {{"Z", 2}}},
               {"line", {{"Z", -2}}, {}, false, 100},
               {"rapid", {{"Z", 2}}},
               {"rapid", {{"Z", -1}}},
               {"line", {{"Z", -5}}, {}, false, 100},
               {"rapid", {{"Z", 10}}}});
}

TEST(Cycles, TheLoweredIrHoldsOneHoleCyclePerHole) {
  // Before the cycles pass (as `--print-after=lower` shows it): the holes as data.
  Lowered r = lower(Dialect::FanucM, "G00 Z10.\nG91 G81 X5. R-8. Z-7. F100. K2\n");
  ASSERT_EQ(r.diagText(), "");
  // After the pipeline every HoleCycle is expanded: none reaches machine space.
  for (const ir::Block& b : r.blocks)
    for (const ir::Operation& op : b.ops) EXPECT_FALSE(std::holds_alternative<ir::HoleCycle>(op));
  EXPECT_EQ(r.moves.size(), 1u + 2u * 4u);  // Z10, then per hole: X, R (Z2), line to -5, rapid to 10
}

}  // namespace
}  // namespace ncc::passes::test
