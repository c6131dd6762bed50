// One negative test per diagnostic: code, line, column and message.
#include "expect_moves.h"

namespace ncc::passes::test {
namespace {

struct Case {
  const char* name;
  Dialect dialect;
  const char* program;
  const char* expected;  // "line:col: error[CODE]: message"
  const char* params = "";
};

class DiagnosticTest : public testing::TestWithParam<Case> {};

TEST_P(DiagnosticTest, ReportsCodeLocationAndMessage) {
  const Case& c = GetParam();
  Lowered r = lower(c.dialect, c.program, c.params[0] ? xyzMachine(c.params) : "");
  EXPECT_EQ(r.diagText(), std::string(c.expected) + "\n");
}

const Case kCases[] = {
    {"MacroExpression", Dialect::FanucM, "G01 X#1 F100.",
     "1:5: error[NCC2001]: macro expressions/statements are not supported yet: X#1"},
    {"NotSupportedCycle", Dialect::MazakM, "G75 X1. Z-1. R1. F100.",
     "1:1: error[NCC2010]: G75 (boring cycle) is not supported yet"},
    {"NotSupportedCutterComp3D", Dialect::FanucM, "G41.2 D1 X1.",
     "1:1: error[NCC2010]: G41.2 (3-D cutter compensation left) is not supported yet"},
    {"NotSupportedSubprogram", Dialect::FanucM, "M98 P100",
     "1:1: error[NCC2010]: M98 (subprogram call) is not supported yet"},
    {"UnknownGFanuc", Dialect::FanucM, "G14 X1.", "1:1: error[PS0010]: G14 is not a G code of fanuc-m"},
    {"UnknownGFanucAsWritten", Dialect::FanucM, "G014.5 X1.",
     "1:1: error[PS0010]: G014.5 is not a G code of fanuc-m"},
    {"NotSupportedHypotheticalAxis", Dialect::FanucM, "G07 X1.",
     "1:1: error[NCC2010]: G07 (hypothetical axis interpolation) is not supported yet"},
    {"UnknownGSiemens", Dialect::SiemensIsoM, "G54.1 P1",
     "1:1: error[12470]: G54.1 is not a G code of siemens-iso-m"},
    {"AddressQ", Dialect::FanucM, "G00 X1. Q2.",
     "1:9: error[NCC2014]: address Q (canned cycle data) has no meaning outside a hole cycle"},
    {"NotAnAxis", Dialect::FanucM, "G00 B10.", "1:5: error[PS0009]: address B: the machine has no axis B"},
    {"AddressWithoutMeaning", Dialect::FanucM, "G01 X1. I2. F100.",
     "1:9: error[NCC2014]: address I has no meaning in this block"},
    {"AddressRepeated", Dialect::FanucM, "G00 X1. X2.",
     "1:9: error[NCC2015]: address X is given twice in the block"},
    {"SameGroupFanuc", Dialect::FanucM, "G90 G91 X1.",
     "1:5: error[NCC2020]: G91 and G90 are both group 03 codes; only one may be given in a block "
     "(same_group_in_block = \"error\")"},
    {"SameGroupMazakOtherThanDistance", Dialect::MazakM, "G00 G01 X1.",
     "1:5: error[NCC2020]: G01 and G00 are both group 01 codes; only one may be given in a block "
     "(same_group_in_block = \"error\")"},
    {"OneShotConflict", Dialect::FanucM, "G28 G53 X0",
     "1:5: error[NCC2021]: G53 and G28 cannot be given in one block"},
    {"DecimalPointFanuc", Dialect::FanucM, "S100.",
     "1:1: error[PS0007]: address S takes an integer; a decimal point is not allowed"},
    {"DwellPWithPointFanuc", Dialect::FanucM, "G04 P1.5",
     "1:5: error[PS0007]: G04 P is in milliseconds and takes no decimal point"},
    {"TooManyM", Dialect::FanucM, "M08 M03 M10 M11",
     "1:13: error[NCC2032]: at most 3 M codes may be given in a block"},
    {"FeedMissingFanuc", Dialect::FanucM, "G01 X10.",
     "1:1: error[PS0011]: no feed rate: a cutting move needs an F word and none has been programmed"},
    {"FeedMissingSiemens", Dialect::SiemensIsoM, "G02 X10. Y10. R10.",
     "1:1: error[10860]: no feed rate: a cutting move needs an F word and none has been programmed"},
    {"FeedMissingInverseTime", Dialect::FanucM, "G01 X1. F100.\nG93 X2.",
     "2:5: error[PS0011]: no feed rate: in inverse time feed (G93) every cutting block needs its own F"},
    {"ArcRadiusMismatchMazak", Dialect::MazakM, "G02 X30. I10. F100",
     "1:1: error[817]: the end point is not on the arc: start radius 10.000, end radius 20.000 "
     "(difference above arc_radius_tolerance 0.010)"},
    {"ArcRadiusMismatchSiemens", Dialect::SiemensIsoM, "G02 X30. I10. F100",
     "1:1: error[14040]: the end point is not on the arc: start radius 10.000, end radius 20.000 "
     "(difference above arc_radius_tolerance 0.010)"},
    {"ArcRadiusTooSmallFanuc", Dialect::FanucM, "G02 X100. R40. F100.",
     "1:11: error[PS0020]: no arc of radius 40.000 joins the start and end points 100.000 apart "
     "(the radius must be at least half the chord)"},
    {"ArcCentreMissing", Dialect::FanucM, "G02 X10. F100.",
     "1:1: error[NCC2043]: G02 needs the centre (I/J/K) or the radius (R)"},
    {"ArcCentreAtStart", Dialect::FanucM, "G03 X10. I0 J0 F100.",
     "1:1: error[NCC2044]: the arc centre is at the start point"},
    {"ArcWrongPlaneWord", Dialect::FanucM, "G02 X10. I5. K1. F100.",
     "1:14: error[NCC2014]: address K is not a centre word of the XY plane (G17)"},
    {"OffsetNumberFanuc", Dialect::FanucM, "G43 Z1. H401",
     "1:9: error[PS0030]: H401 is out of range: offset numbers are 1-400 (offset_count)"},
    {"ReferenceCheckFanuc", Dialect::FanucM, "G27 X10.",
     "1:5: error[PS0092]: G27: X reaches machine position 10.000, not reference point 1 (0.000)"},
    {"ReferencePointNumberFanuc", Dialect::FanucM, "G30 P5 X0",
     "1:5: error[PS0046]: P5: G30 takes P2, P3 or P4"},
    {"DataSetWithoutL", Dialect::FanucM, "G10 P1 X0", "1:1: error[PS0031]: G10 needs L2, L10-L13 or L20"},
    {"DataSetL2PFanuc", Dialect::FanucM, "G10 L2 P7 X0",
     "1:8: error[PS0031]: P7 is out of range: G10 L2 takes P0-P6"},
    {"DataSetL5Mazak", Dialect::MazakM, "G10 L5 P1 X0",
     "1:5: error[903]: G10 L5 is not supported; ncc knows L2, L10-L13 and L20"},
    {"ExtendedOffsetNumberMazak", Dialect::MazakM, "G54.1 P49",
     "1:7: error[809]: P49 is out of range: G54.1 takes P1-P48"},
    {"ExtendedOffsetRequiredMazak", Dialect::MazakM, "G10 L20 X0",
     "1:1: error[807]: G10 L20 without P needs an additional work system to be selected (G54 is)"},
    {"LocalShiftInExtendedMazak", Dialect::MazakM, "G54.1 P1\nG52 X1.",
     "2:1: error[949]: G52 cannot be given while G54.1P1 is selected"},
    {"G921NonZero", Dialect::FanucM, "G92.1 X5.",
     "1:7: error[NCC2031]: G92.1 resets an axis with the value 0; X is given another value"},
    {"NegativeFeed", Dialect::FanucM, "G01 X1. F-5.", "1:9: error[NCC2031]: a feed rate cannot be negative"},
    // Formats (format_digits = 8): integer addresses by digits, values by least increments.
    {"IntegerTooManyDigitsH", Dialect::FanucM, "G43 Z1. H99999999999999999999",
     "1:9: error[PS0003]: address H has more than 8 digits (at most 99999999)"},
    {"IntegerTooManyDigitsT", Dialect::FanucM, "T123456789",
     "1:1: error[PS0003]: address T has more than 8 digits (at most 99999999)"},
    {"IntegerTooManyDigitsMMazak", Dialect::MazakM, "M123456789",
     "1:1: error[809]: address M has more than 8 digits (at most 99999999)"},
    {"IntegerTooManyDigitsTSiemens", Dialect::SiemensIsoM, "T123456789",
     "1:1: error[NCC2033]: address T has more than 8 digits (at most 99999999)"},
    {"IntegerTooManyDigitsG541P", Dialect::FanucM, "G54.1 P99999999999999999999",
     "1:7: error[PS0003]: address P has more than 8 digits (at most 99999999)"},
    {"DwellPTooManyDigits", Dialect::FanucM, "G04 P99999999999999999999",
     "1:5: error[PS0003]: address P has more than 8 digits (at most 99999999)"},
    {"AxisValueTooLong", Dialect::FanucM, "G00 X99999999999999999999999999999999999999.",
     "1:5: error[PS0003]: address X: the value exceeds the 8-digit format (at most ±99999.999 mm)"},
    {"AxisValueJustTooLong", Dialect::FanucM, "G00 X100000.",
     "1:5: error[PS0003]: address X: the value exceeds the 8-digit format (at most ±99999.999 mm)"},
    {"AxisValueTooLongISC", Dialect::FanucM, "G00 Y-10000.",
     "1:5: error[PS0003]: address Y: the value exceeds the 8-digit format (at most ±9999.9999 mm)",
     "increment_system = \"IS-C\""},
    {"AxisValueTooLongInch", Dialect::FanucM, "G20 G00 Z10000.",
     "1:9: error[PS0003]: address Z: the value exceeds the 8-digit format (at most ±9999.9999 in)"},
    {"AxisValueNoPointTooLong", Dialect::FanucM, "G00 X123456789",
     "1:5: error[PS0003]: address X: the value exceeds the 8-digit format (at most ±99999.999 mm)"},
    {"AxisValueTooLongMazak", Dialect::MazakM, "G00 X100000.",
     "1:5: error[809]: address X: the value exceeds the 8-digit format (at most ±99999.999 mm)"},
    {"AxisValueTooLongSiemens", Dialect::SiemensIsoM, "G00 X100000",
     "1:5: error[NCC2033]: address X: the value exceeds the 8-digit format (at most ±99999.999 mm)"},
    {"DwellXTooLong", Dialect::FanucM, "G04 X100000.",
     "1:5: error[PS0003]: address X: the value exceeds the 8-digit format (at most ±99999.999 s)"},
    {"FeedTooLong", Dialect::FanucM, "G01 X1. F99999999999999999999.",
     "1:9: error[PS0003]: address F: the value exceeds the 8-digit format (at most 99999.999 mm/min)"},
    {"FeedRoundsToZero", Dialect::FanucM, "G01 X1. F0.000000000000000000001",
     "1:9: error[PS0011]: no feed rate: F is below half the least input increment and counts as F0"},
    {"FeedRoundsToZeroInverseTime", Dialect::MazakM, "G93 G01 X1. F0.0001",
     "1:5: error[816]: no feed rate: in inverse time feed (G93) every cutting block needs its own F"},
    {"OffsetValueTooLong", Dialect::FanucM, "G10 L10 P1 R100000.",
     "1:12: error[PS0003]: address R: the value exceeds the 8-digit format (at most ±99999.999 mm)"},
    {"OffsetValueHuge", Dialect::FanucM, "G10 L10 P1 R100000000000000000000.",
     "1:12: error[PS0003]: address R: the value exceeds the 8-digit format (at most ±99999.999 mm)"},
    {"LengthCompInArcSiemens", Dialect::SiemensIsoM, "G03 X10. Y10. R10. F100. G44 H1",
     "1:26: error[NCC2045]: G44 is not allowed while G03 is in force: tool length compensation "
     "changes only in G00/G01 mode"},
    {"MacroStatement", Dialect::MazakM, "#101=#4013",
     "1:1: error[NCC2001]: macro expressions/statements are not supported yet (macro statement)"},
};

INSTANTIATE_TEST_SUITE_P(Lowering, DiagnosticTest, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<Case>& info) { return info.param.name; });

TEST(Diagnostics, ErroneousBlockProducesNoIrAndLeavesTheStateAlone) {
  // Whether the bad block's G91 took effect on the control is not known (issue 21): the X1.
  // after it is neither judged nor emitted (recovery_test.cpp). G90 G80 and an absolute X
  // determine the state again, and blocks are emitted again.
  Lowered r = lower(Dialect::FanucM, "G00 X5.\nG91 G81 X1.\nX1.\nG90 G80 X2.\n");
  EXPECT_EQ(r.diags.size(), 1u);
  ASSERT_EQ(r.moves.size(), 2u);
  EXPECT_EQ(r.moves[1].line, 4);
  EXPECT_EQ(r.moves[1].to[0], 2.0);
  EXPECT_EQ(r.blocks.size(), 2u);
}

}  // namespace
}  // namespace ncc::passes::test
