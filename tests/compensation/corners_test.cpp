// The compensation pass on hand-built blocks: start-up, the corners of the offset mode and
// cancel, by the rules docs/compensation.md states. Expected points worked out by hand.
#include "compensation_harness.h"

#include "gtest/gtest.h"

namespace ncc::passes::testing {
namespace {

using Side = ir::CutterComp::Side;
using Startup = ir::CutterComp::Startup;

TEST(CompensationCorners, InnerCornersOfARectangleMeetWhereTheOffsetLinesCross) {
  // siemens-iso-m g41-inner-corners: counterclockwise, G41 D1 = 5: every corner is inner.
  CompProgram p(Dialect::SiemensIsoM);
  p.rapid(20, 15).side(Side::Left, 5).line(20, 0).line(40, 0).line(40, 30).line(0, 30).line(0, 0)
      .line(20, 0).cancel().line(20, 15);
  EXPECT_EQ(p.run(),
            "1: R 20.000 15.000\n"
            "2: L 25.000 5.000\n"
            "3: L 35.000 5.000\n"
            "4: L 35.000 25.000\n"
            "5: L 5.000 25.000\n"
            "6: L 5.000 5.000\n"
            "7: L 15.000 5.000\n"
            "8: L 20.000 15.000\n");
  EXPECT_FALSE(p.diagnostics().hasErrors());
}

CompProgram outsideSquare(bool arc_corners) {
  // G42 around a counterclockwise square: the tool outside, every corner outer (obtuse, 90
  // degrees); the start-up and cancel corners are inner.
  CompProgram p;
  p.settings().arc_corners = arc_corners;
  p.rapid(-10, -10).side(Side::Right, 5).line(0, 0).line(40, 0).line(40, 30).line(0, 30)
      .line(0, 0).cancel().line(-10, -10);
  return p;
}

TEST(CompensationCorners, OuterCornersLinearMeetAtTheOffsetLinesIntersection) {
  EXPECT_EQ(outsideSquare(false).run(),
            "1: R -10.000 -10.000\n"
            "2: L 2.071 -5.000\n"
            "3: L 45.000 -5.000\n"
            "4: L 45.000 35.000\n"
            "5: L -5.000 35.000\n"
            "6: L -5.000 2.071\n"
            "7: L -10.000 -10.000\n");
}

TEST(CompensationCorners, OuterCornersCircularGoAroundTheCornerOnAnArc) {
  EXPECT_EQ(outsideSquare(true).run(),
            "1: R -10.000 -10.000\n"
            "2: L 2.071 -5.000\n"
            "3: L 40.000 -5.000\n"
            "3: A 45.000 0.000 40.000 0.000 ccw\n"
            "4: L 45.000 30.000\n"
            "4: A 40.000 35.000 40.000 30.000 ccw\n"
            "5: L 0.000 35.000\n"
            "5: A -5.000 30.000 0.000 30.000 ccw\n"
            "6: L -5.000 2.071\n"
            "7: L -10.000 -10.000\n");
}

CompProgram outerStartAndCancel(Startup type) {
  CompProgram p;
  p.settings().startup = type;
  p.rapid(0, -20).side(Side::Left, 5).line(0, 0).line(40, 0).cancel().line(40, -20);
  return p;
}

TEST(CompensationStartup, TypeAGoesStraightToPerpendicularToTheNextMove) {
  EXPECT_EQ(outerStartAndCancel(Startup::A).run(),
            "1: R 0.000 -20.000\n"
            "2: L 0.000 5.000\n"
            "3: L 40.000 5.000\n"
            "4: L 40.000 -20.000\n");
}

TEST(CompensationStartup, TypeBGoesPerpendicularToItselfThenToTheIntersection) {
  EXPECT_EQ(outerStartAndCancel(Startup::B).run(),
            "1: R 0.000 -20.000\n"
            "2: L -5.000 0.000\n"
            "2: L -5.000 5.000\n"
            "3: L 45.000 5.000\n"
            "3: L 45.000 0.000\n"
            "4: L 40.000 -20.000\n");
}

TEST(CompensationCorners, AnAcuteOuterCornerIsTurnedByTwoExtendedVectors) {
  CompProgram p;
  p.rapid(-10, 0).side(Side::Right, 5).line(0, 0).line(40, 0).line(0, 10).cancel().line(-10, 10);
  const std::string moves = p.run();
  EXPECT_NE(moves.find("3: L 45.000 -5.000\n3: L 46.063 3.638\n"), std::string::npos) << moves;
}

TEST(CompensationInterference, AGrooveNarrowerThanTheToolIsAnAlarmNotACut) {
  CompProgram p;
  p.rapid(-10, 10).side(Side::Left, 5).line(0, 0).line(20, 0).line(20, -10).line(23, -10)
      .line(23, 0).line(40, 0).cancel().line(50, 10);
  p.run();
  ASSERT_EQ(p.diagnostics().diagnostics().size(), 1u);
  const Diagnostic& d = p.diagnostics().diagnostics()[0];
  EXPECT_EQ(d.code, "PS0041");
  EXPECT_EQ(d.location.line, 5u);  // the groove's bottom runs backwards
  EXPECT_NE(d.message.find("interference"), std::string::npos) << d.message;
}

}  // namespace
}  // namespace ncc::passes::testing
