// The golden suite of cutter radius compensation: every case of golden_cases.cpp (start-up
// types x corner kinds x element pairs, cancel, G38/G39, I J vectors, blocks without motion,
// changes of side and radius, temporary cancel, robustness) against its hand-worked moves and
// diagnostics; and the cases whose result is not only the plane's points (helix, feed).
#include <cmath>
#include <tuple>
#include <variant>

#include "compensation_harness.h"
#include "golden_cases.h"
#include "gtest/gtest.h"

namespace ncc::passes::testing {
namespace {

using Side = ir::CutterComp::Side;

std::vector<std::string> codes(const DiagnosticEngine& d, Severity severity) {
  std::vector<std::string> out;
  for (const Diagnostic& x : d.diagnostics())
    if (x.severity == severity) out.push_back(x.code);
  return out;
}

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MovesAndDiagnosticsAreTheHandWorkedOnes) {
  const GoldenCase& g = GetParam();
  CompProgram p = g.build();
  const std::string moves = p.run();
  if (!g.expected.empty()) {
    EXPECT_EQ(moves, g.expected) << g.title;
  }
  EXPECT_EQ(codes(p.diagnostics(), Severity::Error), g.errors) << g.title;
  EXPECT_EQ(codes(p.diagnostics(), Severity::Warning), g.warnings) << g.title;
}

INSTANTIATE_TEST_SUITE_P(Compensation, Golden, ::testing::ValuesIn(goldenCases()),
                         [](const auto& info) { return info.param.name; });

TEST(CompensationGolden, TheGrooveIsAnErrorAndTheBlocksFromItOnAreNotCompensated) {
  // The compensated bottom of the groove (line 5) would run from x = 25 back to x = 18. The
  // alarm is an error (the driver writes no program then); from the groove's block on, the
  // blocks pass as programmed, so no compensated point of the bottom (y = -5) is emitted.
  CompProgram p;
  p.rapid(-10, 10).side(Side::Left, 5).line(0, 0).line(20, 0).line(20, -10).line(23, -10)
      .line(23, 0).line(40, 0).cancel().line(50, 10);
  const std::string moves = p.run();
  EXPECT_TRUE(p.diagnostics().hasErrors());
  const size_t from = moves.find("5: ");
  ASSERT_NE(from, std::string::npos) << moves;
  EXPECT_EQ(moves.substr(from),
            "5: L 23.000 -10.000\n6: L 23.000 0.000\n7: L 40.000 0.000\n8: L 50.000 10.000\n");
}

TEST(CompensationGolden, AHelixKeepsItsZAndIsOffsetInThePlane) {
  // The full circle of the golden case with Z going down 5: the same plane points, Z -5.
  CompProgram p;
  p.rapid(0, 20).side(Side::Left, 5).line(0, 0).arc(0, 0, 20, 0, false, -5).cancel()
      .line(0, -20, -5);
  EXPECT_EQ(p.run(),
            "1: R 0.000 20.000\n2: L 5.000 0.000\n3: A 5.000 0.000 20.000 0.000 ccw z-5.000\n"
            "4: L 0.000 -20.000\n");
  EXPECT_FALSE(p.diagnostics().hasErrors());
}

TEST(CompensationGolden, InverseTimeFeedScalesWithTheCompensatedLength) {
  // G93: lowering turns F (1/min) into mm/min over the programmed length, so a block that keeps
  // its time 1/F has its feed scaled by compensated / programmed length. G42 r = 5 round an
  // inner right turn:
  //   lead-in (-20,0) -> (0,0), F1 (feed 20): cut (-20,0) -> (0,-5), sqrt(425) mm: 20.616;
  //   A (0,0) -> (40,0), F10 (feed 400): cut (0,-5) -> (35,-5): 400 * 35 / 40 = 350;
  //   B (40,0) -> (40,-30), F2 (feed 60): cut (35,-5) -> (35,-30) (a straight cancel after
  //   it): 60 * 25 / 30 = 50;
  //   the G40 move (40,-30) -> (40,-40), F3 (feed 30): from (35,-30), sqrt(125) mm: 33.541.
  CompProgram p;
  p.feedMode(ir::FeedMode::InverseTime);
  p.rapid(-20, 0).side(Side::Right, 5).line(0, 0, 0, 20).line(40, 0, 0, 400)
      .line(40, -30, 0, 60).cancel().line(40, -40, 0, 30);
  const std::vector<ir::Block> out = p.runBlocks();
  ASSERT_EQ(out.size(), 5u);
  EXPECT_EQ(movesText(out),
            "1: R -20.000 0.000\n2: L 0.000 -5.000\n3: L 35.000 -5.000\n4: L 35.000 -30.000\n"
            "5: L 40.000 -40.000\n");
  auto feed = [&](size_t i) { return std::get<ir::Linear>(out[i].ops.at(0)).feed; };
  EXPECT_NEAR(feed(1), std::sqrt(425.0), 1e-9);
  EXPECT_NEAR(feed(2), 350.0, 1e-9);
  EXPECT_NEAR(feed(3), 50.0, 1e-9);
  EXPECT_NEAR(feed(4), 3 * std::sqrt(125.0), 1e-9);
}

TEST(CompensationGolden, PerMinuteFeedIsNotScaled) {
  CompProgram p;
  p.rapid(-20, 0).side(Side::Right, 5).line(0, 0, 0, 20).line(40, 0, 0, 400).cancel()
      .line(40, -40, 0, 30);
  const std::vector<ir::Block> out = p.runBlocks();
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(std::get<ir::Linear>(out[2].ops.at(0)).feed, 400.0);
  EXPECT_EQ(std::get<ir::Linear>(out[3].ops.at(0)).feed, 30.0);
}

TEST(CompensationGolden, TheAlarmsAreTheDialects) {
  // The groove of the golden case (interference at line 5), and the line into the ccw arc of
  // la_inner with r = 12: the offset circle's radius 20 - 12 = 8 never reaches y = 12 (no
  // intersection at line 4).
  for (const auto& [dialect, interference, no_intersection] :
       {std::tuple{Dialect::FanucM, "PS0041", "PS0033"}, std::tuple{Dialect::MazakM, "837", "836"},
        std::tuple{Dialect::SiemensIsoM, "NCC2127", "NCC2126"}}) {
    CompProgram groove(dialect);
    groove.rapid(-10, 10).side(Side::Left, 5).line(0, 0).line(20, 0).line(20, -10).line(23, -10)
        .line(23, 0).line(40, 0).cancel().line(50, 10);
    groove.run();
    ASSERT_EQ(groove.diagnostics().diagnostics().size(), 1u);
    EXPECT_EQ(groove.diagnostics().diagnostics()[0].code, interference);
    EXPECT_EQ(groove.diagnostics().diagnostics()[0].location.line, 5u);
    CompProgram miss(dialect);
    miss.rapid(-20, 0).side(Side::Left, 12).line(0, 0).line(40, 0).arc(20, 20, 20, 0, false)
        .cancel().line(10, 20);
    miss.run();
    ASSERT_EQ(miss.diagnostics().diagnostics().size(), 1u);
    EXPECT_EQ(miss.diagnostics().diagnostics()[0].code, no_intersection);
    EXPECT_EQ(miss.diagnostics().diagnostics()[0].location.line, 4u);
  }
}

TEST(CompensationGolden, ANegativeRadiusIsTheOtherSide) {
  // G41 D-5 and G42 D5 give the same moves on every element pair.
  auto build = [](Side side, double r) {
    CompProgram p;
    p.rapid(20, 40).side(side, r).line(20, 20).arc(40, 0, 40, 20, false).line(40, -30)
        .arc(20, -50, 20, -30, true).line(0, -50).cancel().line(-10, -50);
    return p;
  };
  CompProgram left = build(Side::Left, -5), right = build(Side::Right, 5);
  EXPECT_EQ(left.run(), right.run());
}

}  // namespace
}  // namespace ncc::passes::testing
