// G00/G01/G02/G03 on fanuc-m (default machine: X Y Z, standard decimal point, IS-B).
#include "absl/strings/str_cat.h"
#include "expect_moves.h"
#include "ncc/ir/ir.h"

namespace ncc::passes::test {
namespace {

const std::vector<std::string> kXYZ = {"X", "Y", "Z"};

TEST(Motion, RapidLinearAndNoMotionBlocks) {
  Lowered r = lower(Dialect::FanucM, "G90 G00 X10. Y5.\nX10. Y5.\nG01 Z-5. F100.\nZ-5.\nM30\n");
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 10}, {"Y", 5}, {"Z", 0}}}, {"line", {{"X", 10}, {"Y", 5}, {"Z", -5}}, {}, false, 100}});
  // Every block is in the IR, with the modal state in force; no-motion blocks carry no op.
  ASSERT_EQ(r.blocks.size(), 5u);
  EXPECT_TRUE(r.blocks[1].ops.empty());
  EXPECT_EQ(r.blocks[2].modal.feed, 100.0);
  EXPECT_TRUE(r.program_end);
  auto* rapid = std::get_if<ir::Rapid>(&r.blocks[0].ops[0]);
  ASSERT_NE(rapid, nullptr);
  EXPECT_EQ(rapid->type, ir::RapidType::PerAxis);  // FANUC LRP = 0 by default
  EXPECT_EQ(rapid->space, ir::Space::Machine);
}

TEST(Motion, RapidTypeParameter) {
  Lowered r = lower(Dialect::FanucM, "G00 X1.\n", xyzMachine("rapid_type = \"linear\""));
  ASSERT_EQ(r.blocks.size(), 1u);
  EXPECT_EQ(std::get<ir::Rapid>(r.blocks[0].ops[0]).type, ir::RapidType::Linear);
}

TEST(Motion, IncrementalArcWithIJ) {
  Lowered r = lower(Dialect::FanucM, "G91 G03 X-10. Y10. I-10. F200.\n");
  expectMoves(r, kXYZ, {{"arc", {{"X", -10}, {"Y", 10}}, {{"X", -10}, {"Y", 0}}, false, 200}});
}

TEST(Motion, HelicalFullCircleWithThirdAxis) {
  Lowered r = lower(Dialect::FanucM, "G17 G02 I5. Z-2. F50.\n");
  // FANUC: F50 is the speed along the arc (31.416 mm); along the helix (31.480 mm) it is
  // 50 x 31.480 / 31.416 = 50.101 (HTG = 0; Mazak and Siemens keep 50, see FoundationRules).
  expectMoves(r, kXYZ, {{"arc", {{"X", 0}, {"Y", 0}, {"Z", -2}}, {{"X", 5}, {"Y", 0}}, true, 50.1012}});
}

TEST(Motion, G18ArcDirectionSeenFromPlusY) {
  Lowered r = lower(Dialect::FanucM, "G18 G03 X10. Z10. K10. F100.\n");
  // (Z,X) plane: start (0,0), centre Z10 X0, end Z10 X10: counter-clockwise from +Y.
  expectMoves(r, kXYZ, {{"arc", {{"X", 10}, {"Z", 10}}, {{"X", 0}, {"Z", 10}}, false, 100}});
  EXPECT_EQ(std::get<ir::Arc>(r.blocks[0].ops[0]).plane, ir::Plane::ZX);
}

TEST(Motion, ArcRadiusWithinTolerance) {
  // End radius 10.005 vs start radius 10: within the 0.01 default tolerance.
  Lowered r = lower(Dialect::FanucM, "G02 X20.005 I10. F100.\n");
  ASSERT_EQ(r.diagText(), "");
  ASSERT_EQ(r.moves.size(), 1u);
}

TEST(Motion, InverseTimeFeed) {
  Lowered r = lower(Dialect::FanucM, "G93 G01 X30. Y40. F2.\n");
  // 50 mm in 1/2 min: 100 mm/min.
  expectMoves(r, kXYZ, {{"line", {{"X", 30}, {"Y", 40}}, {}, false, 100}});
  EXPECT_EQ(r.blocks[0].modal.feed_mode, ir::FeedMode::InverseTime);
}

TEST(Motion, FeedPerRevolution) {
  Lowered r = lower(Dialect::FanucM, "G95 G01 X10. F25\n");
  ASSERT_EQ(r.diagText(), "");
  auto line = std::get<ir::Linear>(r.blocks[0].ops[0]);
  EXPECT_DOUBLE_EQ(line.feed, 0.25);  // standard notation: F25 = 0.25 mm/rev
  EXPECT_TRUE(line.feed_per_rev);
}

TEST(Motion, InchFeedIsConverted) {
  Lowered r = lower(Dialect::FanucM, "G20 G01 X1. F10.\n");
  expectMoves(r, kXYZ, {{"line", {{"X", 25.4}}, {}, false, 254}});
  EXPECT_EQ(r.blocks[0].modal.units, ir::Units::Inch);
}

// G94/G95 after G93 need a new F: the inverse-time F is not a feed per minute.
TEST(Motion, FeedPerMinuteAfterInverseTimeNeedsANewF) {
  struct Case {
    Dialect d;
    const char* code;
  };
  for (Case c : {Case{Dialect::FanucM, "PS0011"}, Case{Dialect::MazakM, "816"},
                 Case{Dialect::SiemensIsoM, "10860"}}) {
    Lowered r = lower(c.d, "G93 G01 X30. F2.\nG94 G01 X50.\n");
    EXPECT_EQ(r.diagText(), absl::StrCat("2:5: error[", c.code,
                                         "]: no feed rate: after inverse time feed (G93), G94 "
                                         "needs a new F word\n"));
  }
  Lowered rev = lower(Dialect::FanucM, "G93 G01 X30. F2.\nG95\nG00 X0\nG01 X10.\n");
  EXPECT_EQ(rev.diagText(),
            "4:1: error[PS0011]: no feed rate: after inverse time feed (G93), G95 needs a new F "
            "word\n");
  Lowered ok = lower(Dialect::FanucM, "G93 G01 X30. F2.\nG94 G01 X50. F100.\nX60.\n");
  expectMoves(ok, kXYZ, {{"line", {{"X", 30}}, {}, false, 60}, {"line", {{"X", 50}}, {}, false, 100},
                         {"line", {{"X", 60}}, {}, false, 100}});
  EXPECT_EQ(ok.blocks[1].modal.feed, 100.0);
}

// Between G94 and G95 the F is kept, reread in the new mode (docs/semantics.md, Feed).
TEST(Motion, FeedIsKeptBetweenG94AndG95) {
  Lowered r = lower(Dialect::FanucM, "G94 G01 X1. F100.\nG95 X2.\n");
  expectMoves(r, kXYZ, {{"line", {{"X", 1}}, {}, false, 100}, {"line", {{"X", 2}}, {}, false, 100}});
}

TEST(Motion, ValuesAtTheFormatLimitAreAccepted) {
  Lowered r = lower(Dialect::FanucM, "G01 X99999.999 F99999.999\nG04 P99999999\nT99999999 M99999999\n");
  EXPECT_EQ(r.diagText(), "");
  Lowered c = lower(Dialect::FanucM, "G00 X9999.9999\n", xyzMachine("increment_system = \"IS-C\""));
  EXPECT_EQ(c.diagText(), "");
}

TEST(Motion, PowerOnStateFromTheResetParameters) {
  Lowered r = lower(Dialect::FanucM, "X1. F10.\n",
                    xyzMachine("reset_unit = \"G20\"\nreset_motion_mode = \"G01\"\n"
                               "reset_plane = \"G18\""));
  expectMoves(r, kXYZ, {{"line", {{"X", 25.4}}, {}, false, 254}});
  EXPECT_EQ(r.blocks[0].modal.plane, ir::Plane::ZX);
}

}  // namespace
}  // namespace ncc::passes::test
