// The golden suite of cutter radius compensation: every case of golden_cases.cpp (start-up
// types x corner kinds x element pairs, cancel, G38/G39, I J vectors, blocks without motion,
// changes of side and radius, temporary cancel, robustness) against its hand-worked moves and
// diagnostics; and the cases whose result is not only the plane's points (helix, feed).
#include <cmath>
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
  if (!g.expected.empty()) EXPECT_EQ(moves, g.expected) << g.title;
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
  // G93, G42 r = 5 round an inner right turn: A (0,0) -> (40,0) at F10 (1/min, 4 s) is cut
  // from (0,-5) to (35,-5): 35 mm in the same time, F 10 * 35 / 40 = 8.75. B (40,0) ->
  // (40,-30) F20 runs from (35,-5) to (35,-30) (the straight cancel after it): 25/30 * 20 =
  // 16.667. The lead-in (a start-up from (-20,0) to (0,-5), 20.616 mm for 20) F5: 5.154.
  CompProgram p;
  p.feedMode(ir::FeedMode::InverseTime);
  p.rapid(-20, 0).side(Side::Right, 5).line(0, 0, 0, 5).line(40, 0, 0, 10).line(40, -30, 0, 20)
      .cancel().line(40, -40, 0, 30);
  const std::vector<ir::Block> out = p.runBlocks();
  ASSERT_EQ(out.size(), 5u);
  auto feed = [&](size_t i) { return std::get<ir::Linear>(out[i].ops.at(0)).feed; };
  EXPECT_NEAR(feed(1), 5 * std::sqrt(20.0 * 20 + 25) / 20, 1e-9);
  EXPECT_NEAR(feed(2), 8.75, 1e-9);
  EXPECT_NEAR(feed(3), 20.0 * 25 / 30, 1e-9);
  // The cancel move from (35,-30) to (40,-40): sqrt(125) mm for 10.
  EXPECT_NEAR(feed(4), 30.0, 1e-9) << "the cancel move is not compensated: its feed stays";
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
