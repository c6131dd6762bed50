// Error recovery: after a rejected block, blocks that depend on what it would have changed are
// not judged (no diagnostic), and their own words determine the state again
// (passes/src/lowering_recovery.cpp, docs/semantics.md "Error recovery").
#include "expect_moves.h"

namespace ncc::passes::test {
namespace {

TEST(Recovery, ArcsAfterARejectedCutterCompBlockAreNotJudged) {
  // After corpus enier-mill_240811_1003.nc, whose G41 blocks were rejected before cutter
  // compensation was lowered; G41.2 (3-D compensation) still is. The rejected block's X/Y are
  // not reached, so the arc after it starts elsewhere (PS0020 before). Its absolute end point
  // fixes X/Y: the next arcs, which fit, are judged and pass.
  Lowered r = lower(Dialect::FanucM,
                    "G90 G17 G00 X0 Y0\n"
                    "G01 X10. F100.\n"
                    "G41.2 X12. Y-1. D1\n"
                    "G03 X15. Y2. I0 J3.\n"
                    "G02 X18. Y5. I3. J0\n"
                    "G01 G40 X20. Y5.\n");
  EXPECT_EQ(r.diagText(),
            "3:1: error[NCC2010]: G41.2 (3-D cutter compensation left) is not supported yet\n");
}

TEST(Recovery, AnUnknownGCodeLeavesEveryGroupUnknown) {
  // corpus pygcode-Mach3_write.tap: G90.1 is not a fanuc-m code; which group it would have
  // set is not known, so arcs (plane, mode, start) are not judged until determined again.
  Lowered r = lower(Dialect::FanucM,
                    "G17 G90 G00 X0 Y0\n"
                    "G90 G90.1\n"
                    "G01 X5. Y0 F600.\n"
                    "G02 X10. Y5. I10. J0\n"
                    "G02 X20. Y5. I15. J5.\n");
  EXPECT_EQ(r.diagText(), "2:5: error[PS0010]: G90.1 is not a G code of fanuc-m\n");
  EXPECT_TRUE(r.moves.empty());  // nothing is emitted while the state is unknown
}

TEST(Recovery, CodesAndAbsoluteWordsDetermineTheStateAgain) {
  Lowered r = lower(Dialect::FanucM,
                    "G17 G90 G00 X0 Y0\n"
                    "G91 X10. Q1.\n"          // rejected: G90/G91 and X unknown
                    "G02 X10. Y0 R2. F100.\n"  // mode unknown: not judged (PS0020 in G90)
                    "G90 G02 X10. Y0 R2.\n"    // start X unknown: not judged; fixes X, Y
                    "G02 X20. Y0 R2.\n");      // judged: chord 10 > 2 R
  EXPECT_EQ(r.diagText(),
            "2:10: error[NCC2014]: address Q (canned cycle data) has no meaning outside a hole cycle\n"
            "5:13: error[PS0020]: no arc of radius 2.000 joins the start and end points 10.000 "
            "apart (the radius must be at least half the chord)\n");
}

TEST(Recovery, AnIncrementalMoveFromAnUnknownPointStaysUnknown) {
  Lowered r = lower(Dialect::FanucM,
                    "G17 G90 G00 X0 Y0\n"
                    "G01 X1. Q1. F100.\n"  // rejected: X unknown
                    "G91 G01 X1.\n"        // X = unknown + 1
                    "G90 G02 X5. Y0 R1.\n");  // from an unknown X: not judged
  EXPECT_EQ(r.diagText(),
            "2:9: error[NCC2014]: address Q (canned cycle data) has no meaning outside a hole cycle\n");
}

TEST(Recovery, AFeedOfARejectedBlockIsUnknownUntilTheNextF) {
  Lowered r = lower(Dialect::FanucM,
                    "G90 G00 X0 Y0\n"
                    "G01 X1. Q1. F100.\n"  // rejected: F unknown (and X)
                    "G01 Y5.\n"            // needs the F in force: not judged
                    "G00 X0 Y0\n"
                    "G94 G01 X1. F0\n");   // its own F: judged (PS0011 at the G01)
  EXPECT_EQ(r.diagText(),
            "2:9: error[NCC2014]: address Q (canned cycle data) has no meaning outside a hole cycle\n"
            "5:5: error[PS0011]: no feed rate: a cutting move needs an F word and none has "
            "been programmed\n");
}

TEST(Recovery, IndependentFaultsAreStillReportedAndOutputResumes) {
  Lowered r = lower(Dialect::FanucM,
                    "G90 G00 X0 Y0\n"
                    "G00 X1. Q1.\n"       // rejected: X and group 01 unknown
                    "G00 Y1. B2.\n"       // no axis B: a fault of its own (Y unknown)
                    "G00 X5.\n"           // fixes X and the group; Y still unknown
                    "G00 Y2.\n");         // everything known again: emitted
  EXPECT_EQ(r.diagText(),
            "2:9: error[NCC2014]: address Q (canned cycle data) has no meaning outside a hole cycle\n"
            "3:9: error[PS0009]: address B: the machine has no axis B\n");
  ASSERT_EQ(r.moves.size(), 1u);
  EXPECT_EQ(r.moves[0].line, 5);
  EXPECT_DOUBLE_EQ(r.moves[0].to[0], 5.0);
  EXPECT_DOUBLE_EQ(r.moves[0].to[1], 2.0);
}

TEST(Recovery, AWorkOffsetOfARejectedBlockMakesEveryAxisUnknown) {
  Lowered r = lower(Dialect::FanucM,
                    "G17 G90 G00 X0 Y0\n"
                    "G55 X1. Q1.\n"           // rejected: the work system is not known
                    "G02 X2. Y0 R0.5 F100.\n");  // start Y unknown too: not judged
  EXPECT_EQ(r.diagText(),
            "2:9: error[NCC2014]: address Q (canned cycle data) has no meaning outside a hole cycle\n");
}

}  // namespace
}  // namespace ncc::passes::test
