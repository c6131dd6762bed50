// The conformance cases of /work/shared/conformance this layer must get right, with their
// programs and [machine]/[start] tables copied verbatim and the expected moves of case.toml.
#include "expect_moves.h"

namespace ncc::passes::test {
namespace {

const std::vector<std::string> kXYZ = {"X", "Y", "Z"};

std::string mazak(const std::string& params, const std::string& start,
                  const std::string& offsets = "", const std::string& work = "G54 = [0.0, 0.0, 0.0]\n") {
  return "[machine]\naxes = [\"X\", \"Y\", \"Z\"]\n[machine.offsets]\n" + offsets +
         "[machine.work]\n" + work + "[machine.params]\ndecimal_point = \"standard\"\n" + params +
         "[start]\nposition = " + start + "\n";
}

std::string siemens(const std::string& params, const std::string& start = "{ X = 0.0, Y = 0.0, Z = 0.0 }",
                    const std::string& offsets = "", const std::string& work = "G54 = [0.0, 0.0, 0.0]\n") {
  return "[machine]\naxes = [\"X\", \"Y\", \"Z\"]\n[machine.offsets]\n" + offsets +
         "[machine.work]\n" + work +
         "[machine.params]\ndecimal_point = \"calculator\"\nreset_unit = \"G21\"\n" + params +
         "[start]\nposition = " + start + "\n";
}

const char* kOrigin = "{ X = 0.0, Y = 0.0, Z = 0.0 }";
const char* kRef1 = "reference_point_1 = { X = 0.0, Y = 0.0, Z = 0.0 }\n";

TEST(MazakConformance, DecimalPointStandardType1) {
  Lowered r = lower(Dialect::MazakM, "G90 G0X123.45\nG0Y12345\nM30\n", mazak("", kOrigin));
  // The program mixes both notations on purpose: the mixed-notation warning says so.
  expectMoves(r, kXYZ, {{"rapid", {{"X", 123.45}, {"Y", 0}}}, {"rapid", {{"X", 123.45}, {"Y", 12.345}}}},
              0.001,
              "2:3: warning[NCC2034]: 1 coordinate word without a decimal point is read as least input "
              "increments (the first: Y12345 = 12.345 mm) in a program that also writes decimal "
              "points; write the point (`Z3.`) for whole units, or set decimal_point = "
              "\"calculator\"\n");
}

TEST(MazakConformance, G01IncrementalPathLeastIncrement) {
  Lowered r = lower(Dialect::MazakM,
                "G91 G00 X20000 Y20000\nG01 X20000 Y30000 F300\nX30000\nX-20000 Y-30000\nX-30000\nM30\n",
                mazak("", kOrigin));
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 20}, {"Y", 20}}},
               {"line", {{"X", 40}, {"Y", 50}}, {}, false, 300},
               {"line", {{"X", 70}, {"Y", 50}}, {}, false, 300},
               {"line", {{"X", 50}, {"Y", 20}}, {}, false, 300},
               {"line", {{"X", 20}, {"Y", 20}}, {}, false, 300}});
}

TEST(MazakConformance, G02FullCircleAndThreeQuarterArc) {
  Lowered r = lower(Dialect::MazakM,
                "G17 G90 G00 X0 Y0\nG02 J50000 F500\nG91 G02 X50000 Y50000 J50000 F500\nM30\n",
                mazak("", "{ X = -20.0, Y = -20.0, Z = 0.0 }"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 0}, {"Y", 0}}},
               {"arc", {{"X", 0}, {"Y", 0}}, {{"X", 0}, {"Y", 50}}, true, 500},
               {"arc", {{"X", 50}, {"Y", 50}}, {{"X", 0}, {"Y", 50}}, true, 500}});
}

TEST(MazakConformance, G02G03RAddressRules) {
  Lowered r = lower(Dialect::MazakM,
                "G17 G90 G00 X0 Y0\nG02 X10. Y10. R10. F100\nG00 X0 Y0\nG02 X10. Y10. R-10. F100\n"
                "G00 X0 Y0\nG02 X20. Y0 J5. R10.\nG17 G02 I10. J0 R5.\nG02 R10.\nM30\n",
                mazak("", "{ X = -20.0, Y = -20.0, Z = 0.0 }"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 0}, {"Y", 0}}},
               {"arc", {{"X", 10}, {"Y", 10}}, {{"X", 10}, {"Y", 0}}, true, 100},
               {"rapid", {{"X", 0}, {"Y", 0}}},
               {"arc", {{"X", 10}, {"Y", 10}}, {{"X", 0}, {"Y", 10}}, true, 100},
               {"rapid", {{"X", 0}, {"Y", 0}}},
               {"arc", {{"X", 20}, {"Y", 0}}, {{"X", 10}, {"Y", 0}}, true, 100},
               {"arc", {{"X", 20}, {"Y", 0}}, {{"X", 30}, {"Y", 0}}, true, 100}});
}

TEST(MazakConformance, G04DwellSecondsXAndP) {
  Lowered r = lower(Dialect::MazakM, "G94\nG04 X5.\nG04 P5000\nG04 P12.345\nG04 X5000\nM30\n",
                mazak("", kOrigin));
  expectMoves(r, kXYZ,
              {{"dwell", {}, {}, false, -1, 5.0}, {"dwell", {}, {}, false, -1, 5.0},
               {"dwell", {}, {}, false, -1, 0.012}, {"dwell", {}, {}, false, -1, 5.0}});
}

TEST(MazakConformance, G10L10LengthOffsetSetAndAdd) {
  // N5 (#101=#2010) reads a system variable: Macro B is a later issue, so it is left out.
  Lowered r = lower(Dialect::MazakM,
                "N1 G01 G90 G43 Z-100000 H10 F1000\nN2 G28 Z0\nN3 G91 G10 L10 P10 R-500\n"
                "N4 G01 G90 G43 Z-100000 H10\nM30\n",
                mazak(kRef1, kOrigin, "H10 = -1.0\n"));
  // moves_subset: the G28 intermediate point (Z0 + H10 = -1) is an extra rapid.
  expectMoves(r, kXYZ,
              {{"line", {{"Z", -101.0}}, {}, false, 1000},
               {"rapid", {{"Z", -1.0}}},
               {"rapid", {{"Z", 0.0}}},
               {"line", {{"Z", -101.5}}, {}, false, 1000}});
}

TEST(MazakConformance, G10L20SetThenAddG541Offset) {
  Lowered r = lower(Dialect::MazakM,
                "G90 G10 L20 P30 X-255. Y-50.\nG91 G10 L20 P30 X-3. Y-5.\nG90 G54.1 P30\n"
                "G00 X0 Y0\nG54 X0 Y0\nM30\n",
                mazak("", "{ X = 10.0, Y = 10.0, Z = 0.0 }"));
  expectMoves(r, kXYZ, {{"rapid", {{"X", -258}, {"Y", -55}}}, {"rapid", {{"X", 0}, {"Y", 0}}}});
}

TEST(MazakConformance, G18G19PlaneArcs) {
  Lowered r = lower(Dialect::MazakM,
                "G90 G00 X0 Y0 Z0\nG18 G02 X10. Z10. I10. K0 F100\nG19 G03 Y10. Z20. J0 K10.\n"
                "G17 G01 X0 Y0 Z0\nM30\n",
                mazak("", "{ X = -20.0, Y = -20.0, Z = -20.0 }"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 0}, {"Y", 0}, {"Z", 0}}},
               {"arc", {{"X", 10}, {"Z", 10}}, {{"X", 10}, {"Z", 0}}, true, 100},
               {"arc", {{"Y", 10}, {"Z", 20}}, {{"Y", 0}, {"Z", 20}}, false, 100},
               {"line", {{"X", 0}, {"Y", 0}, {"Z", 0}}, {}, false, 100}});
}

TEST(MazakConformance, G20InchAppliesToLinearAxesOnly) {
  std::string machine =
      "[machine]\naxes = [\"X\", \"Y\", \"Z\", \"B\"]\n[machine.work]\nG54 = [0.0, 0.0, 0.0, 0.0]\n"
      "[machine.params]\ndecimal_point = \"standard\"\nreset_unit = \"G21\"\n"
      "[start]\nposition = { X = 0.0, Y = 0.0, Z = 0.0, B = 0.0 }\n";
  Lowered r = lower(Dialect::MazakM, "G91 G20 G00 X100 Y100 B100\nG21 X100\nM30\n", machine);
  expectMoves(r, {"X", "Y", "Z", "B"},
              {{"rapid", {{"X", 0.254}, {"Y", 0.254}, {"B", 0.1}}},
               {"rapid", {{"X", 0.354}, {"Y", 0.254}, {"B", 0.1}}}});
}

TEST(MazakConformance, G30SecondThirdReferencePoints) {
  Lowered r = lower(Dialect::MazakM,
                "N1 G90 G00 X10. Y10.\nN2 G30 P3 X20.\nN3 G30 Y0\nN4 G30 P7 X5.\nN5 M30\n",
                mazak(std::string(kRef1) +
                          "reference_point_2 = { X = -100.0, Y = -50.0, Z = 0.0 }\n"
                          "reference_point_3 = { X = -200.0, Y = -80.0, Z = 0.0 }\n",
                      kOrigin));
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 10}, {"Y", 10}}}, {"rapid", {{"X", 20}}}, {"rapid", {{"X", -200}}},
               {"rapid", {{"Y", 0}}}, {"rapid", {{"Y", -50}}}, {"rapid", {{"X", 5}}},
               {"rapid", {{"X", -100}, {"Y", -50}}}});
}

TEST(MazakConformance, G43LengthOffsetAbsolute) {
  Lowered r = lower(Dialect::MazakM,
                "N001 G90 G94 G00 G40 G80\nN002 G91 G28 Z0\nN003 T01 T00 M06\n"
                "N004 G90 G54 X-100. Y0\nN005 G43 Z5. H01\nN006 G01 Z-50. F100\nM30\n",
                mazak(kRef1, "{ X = 0.0, Y = 0.0, Z = -50.0 }", "H1 = 100.0\n"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", 0}}}, {"rapid", {{"X", -100}}}, {"rapid", {{"Z", 105}}},
               {"line", {{"X", -100}, {"Y", 0}, {"Z", 50}}, {}, false, 100}});
}

TEST(MazakConformance, G44G49H00AndReferenceReturnCancel) {
  Lowered r = lower(Dialect::MazakM,
                "N1 G90 G00 G44 Z10. H01\nN2 G49 Z10.\nN3 G43 Z10. H01\nN4 Z20. H00\n"
                "N5 G43 Z10. H01\nN6 G28 Z0\nN7 G00 Z10.\nN8 M30\n",
                mazak(kRef1, kOrigin, "H1 = 100.0\n"));
  // N6: the intermediate point Z0 includes the offset (machine 100), then the reference point.
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", -90}}}, {"rapid", {{"Z", 10}}}, {"rapid", {{"Z", 110}}},
               {"rapid", {{"Z", 20}}}, {"rapid", {{"Z", 110}}}, {"rapid", {{"Z", 100}}},
               {"rapid", {{"Z", 0}}}, {"rapid", {{"Z", 10}}}});
}

TEST(MazakConformance, G52LocalSystemAbsoluteAndIncremental) {
  Lowered r = lower(Dialect::MazakM,
                "G90 G54 G00 X0 Y0\nG91 G52 X10. Y10.\nG52 X5. Y5.\nG90 G00 X0 Y0\nG52 X20. Y20.\n"
                "G00 X0 Y0\nX5. Y5.\nG55 X0 Y0\nG54 X0 Y0\nG52 X0 Y0\nG00 X0 Y0\nM30\n",
                mazak("", "{ X = -20.0, Y = -20.0, Z = 0.0 }", "",
                      "G54 = [0.0, 0.0, 0.0]\nG55 = [-100.0, 0.0, 0.0]\n"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 0}, {"Y", 0}}}, {"rapid", {{"X", 15}, {"Y", 15}}},
               {"rapid", {{"X", 20}, {"Y", 20}}}, {"rapid", {{"X", 25}, {"Y", 25}}},
               {"rapid", {{"X", -100}, {"Y", 0}}}, {"rapid", {{"X", 20}, {"Y", 20}}},
               {"rapid", {{"X", 0}, {"Y", 0}}}});
}

TEST(MazakConformance, G53MachineCoordinatePositioning) {
  Lowered r = lower(Dialect::MazakM,
                "G90 G00 G54 X10. Y10.\nG53 X-100. Y-50.\nX10. Y10.\nG91 G53 X10.\nG90 G53 X0 Y0\nM30\n",
                mazak("", kOrigin, "", "G54 = [-100.0, -50.0, 0.0]\n"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", -90}, {"Y", -40}}}, {"rapid", {{"X", -100}, {"Y", -50}}},
               {"rapid", {{"X", -90}, {"Y", -40}}}, {"rapid", {{"X", -80}, {"Y", -40}}},
               {"rapid", {{"X", 0}, {"Y", 0}}}});
}

TEST(MazakConformance, G55G43FaceMillingPasses) {
  Lowered r = lower(Dialect::MazakM,
                "N001 (FR-SFR D100)\nG55 G90 G94 G40 G49\nG91 G28 Y0 Z0\nT01 T00 M06\n"
                "G90 G00 S480 M03\nX-110.Y30.\nG43 Z50.H01 M08\nG00 Z3.\nG01 X110.F290\nY-30.\n"
                "X-110.\nG00 Z50.\nX-110.Y30.\nZ0\nG01 X110.\nG00 Z50.\nX-110.Y-30.\nZ0\n"
                "G01 X110.\nG00 Z50.\nG91 G28 Y0 Z0\nM30\n",
                mazak(kRef1, kOrigin, "H1 = 150.0\n",
                      "G54 = [0.0, 0.0, 0.0]\nG55 = [-500.0, -250.0, -300.0]\n"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", -610}, {"Y", -220}}},
               {"rapid", {{"Z", -100}}},
               {"rapid", {{"Z", -147}}},
               {"line", {{"X", -390}}, {}, false, 290},
               {"line", {{"Y", -280}}, {}, false, 290},
               {"line", {{"X", -610}}, {}, false, 290},
               {"rapid", {{"Z", -100}}},
               {"rapid", {{"Y", -220}}},
               {"rapid", {{"Z", -150}}},
               {"line", {{"X", -390}}, {}, false, 290},
               {"rapid", {{"Z", -100}}},
               {"rapid", {{"X", -610}, {"Y", -280}}},
               {"rapid", {{"Z", -150}}},
               {"line", {{"X", -390}}, {}, false, 290},
               {"rapid", {{"Z", -100}}},
               {"rapid", {{"X", -390}, {"Y", 0}, {"Z", 0}}}});
}

TEST(MazakConformance, G90G91SwitchInsideABlock) {
  Lowered r = lower(Dialect::MazakM,
                "N1 G90 G00 X0 Y0\nN2 G91 G01 X200. Y50. F100\nN3 X-100. Y50.\nN4 G90X300. G91Y100.\n"
                "N5 Y-50.\nM30\n",
                mazak("", "{ X = -20.0, Y = -20.0, Z = 0.0 }"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 0}, {"Y", 0}}}, {"line", {{"X", 200}, {"Y", 50}}, {}, false, 100},
               {"line", {{"X", 100}, {"Y", 100}}, {}, false, 100},
               {"line", {{"X", 300}, {"Y", 200}}, {}, false, 100},
               {"line", {{"X", 300}, {"Y", 150}}, {}, false, 100}});
}

TEST(MazakConformance, Alarm816FirstCuttingBlockWithoutF) {
  Lowered r = lower(Dialect::MazakM, "G90 G00 X0 Y0\nG01 X10. Y10.\nM30\n",
                mazak("", "{ X = -10.0, Y = 0.0, Z = 0.0 }"));
  ASSERT_EQ(r.diags.size(), 1u) << r.diagText();
  EXPECT_EQ(r.diags[0].code, "816");
  EXPECT_EQ(r.diags[0].location.line, 2u);
}

TEST(MazakConformance, Alarm818RArcChordLongerThanDiameter) {
  Lowered r = lower(Dialect::MazakM, "G90 G00 X0 Y0\nG02 X100. Y0 R40. F100\nM30\n",
                mazak("", "{ X = -10.0, Y = 0.0, Z = 0.0 }"));
  ASSERT_EQ(r.diags.size(), 1u) << r.diagText();
  EXPECT_EQ(r.diags[0].code, "818");
  EXPECT_EQ(r.diags[0].location.line, 2u);
}

TEST(MazakConformance, Alarm839OffsetNumberOutOfRange) {
  Lowered r = lower(Dialect::MazakM, "G90 G00 X0 Y0 Z0\nG43 Z10. H200\nM30\n",
                mazak("offset_count = 128\n", "{ X = -10.0, Y = 0.0, Z = 0.0 }"));
  ASSERT_EQ(r.diags.size(), 1u) << r.diagText();
  EXPECT_EQ(r.diags[0].code, "839");
  EXPECT_EQ(r.diags[0].location.line, 2u);
}

TEST(SiemensConformance, ArcHelicalG17) {
  Lowered r = lower(Dialect::SiemensIsoM,
                "N10 G90 G00 X10. Y0 Z0;\nN20 G17 G03 X0 Y10. I-10. J0 Z-5. F200.;\n"
                "N30 G03 X-10. Y0 I0 J-10. Z-10.;\nN40 M30;\n",
                siemens(""));
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 10}}},
               {"arc", {{"X", 0}, {"Y", 10}, {"Z", -5}}, {{"X", 0}, {"Y", 0}}, false, 200},
               {"arc", {{"X", -10}, {"Y", 0}, {"Z", -10}}, {{"X", 0}, {"Y", 0}}, false, 200}});
}

TEST(SiemensConformance, ArcIjkAbsolute) {
  Lowered r = lower(Dialect::SiemensIsoM, "G17 G90 G03 X15. Y40. I-30. J-10. F150;\n",
                siemens("", "{ X = 55.0, Y = 20.0, Z = 0.0 }"));
  expectMoves(r, kXYZ, {{"arc", {{"X", 15}, {"Y", 40}}, {{"X", 25}, {"Y", 10}}, false, 150}});
}

TEST(SiemensConformance, ArcPlanesG18G19) {
  Lowered r = lower(Dialect::SiemensIsoM,
                "N10 G90 G00 Z10.;\nN20 G18 G02 Z0 X-10. K-10. I0 F100.;\nN30 G19 G03 Y10. Z-10. J10. K0;\n"
                "N40 G17;\nN50 M30;\n",
                siemens(""));
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", 10}}},
               {"arc", {{"X", -10}, {"Z", 0}}, {{"X", 0}, {"Z", 0}}, true, 100},
               {"arc", {{"Y", 10}, {"Z", -10}}, {{"Y", 10}, {"Z", 0}}, false, 100}});
}

TEST(SiemensConformance, ArcRSignedRadius) {
  Lowered r = lower(Dialect::SiemensIsoM,
                "N10 G17 G90 G02 X10. Y10. R10. F100.;\nN20 G02 X20. Y0 R-10.;\nN30 M30;\n", siemens(""));
  expectMoves(r, kXYZ,
              {{"arc", {{"X", 10}, {"Y", 10}}, {{"X", 10}, {"Y", 0}}, true, 100},
               {"arc", {{"X", 20}, {"Y", 0}}, {{"X", 20}, {"Y", 10}}, true, 100}});
}

TEST(SiemensConformance, G04DwellXAndP) {
  Lowered r = lower(Dialect::SiemensIsoM,
                "N10 G90 G01 X10. F100.;\nN20 G04 X1.5;\nN30 G04 P2500;\nN40 X20.;\nN50 M30;\n",
                siemens("dwell_in_revolutions_with_g95 = false\n"));
  expectMoves(r, kXYZ,
              {{"line", {{"X", 10}}, {}, false, 100}, {"dwell", {}, {}, false, -1, 1.5},
               {"dwell", {}, {}, false, -1, 2.5}, {"line", {{"X", 20}}, {}, false, 100}});
}

TEST(SiemensConformance, G10L2G54ReselectAndG92) {
  Lowered r = lower(Dialect::SiemensIsoM,
                "N10 G10 L2 P1 X10 Y10\nN20 G0 X100 Y100\nN30 G54 X100 Y100\nN40 G92 X50 Y50\n"
                "N50 G0 X100 Y100\nN60 G92.1 X0 Y0\n",
                siemens(""));
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 100}, {"Y", 100}}}, {"rapid", {{"X", 110}, {"Y", 110}}},
               {"rapid", {{"X", 160}, {"Y", 160}}}});
  // N60 removes the G92 shift only: the work position becomes 150 (machine 160 - G54 10).
  const ir::Block& last = r.blocks.back();
  EXPECT_DOUBLE_EQ(last.frame.shift[0], 0.0);
  EXPECT_DOUBLE_EQ(last.frame.work_offset[0], 10.0);
}

TEST(SiemensConformance, G20InchInput) {
  Lowered r = lower(Dialect::SiemensIsoM, "N10 G20;\nN20 G90 G01 X1. Y2. F10.;\nN30 M30;\n",
                siemens("machine_unit = \"mm\"\n"));
  expectMoves(r, kXYZ, {{"line", {{"X", 25.4}, {"Y", 50.8}}, {}, false, 254}});
}

TEST(SiemensConformance, G43G44G49ToolLength) {
  Lowered r = lower(Dialect::SiemensIsoM,
                "N10 G90 G00 G43 Z10. H1;\nN20 G43 Z10. H2;\nN30 G49 Z10.;\nN40 G44 Z10. H1;\n"
                "N50 G43 Z10. H3;\nN60 G49 Z100.;\nN70 M30;\n",
                siemens("tool_length_mode = \"A\"\n", "{ X = 0.0, Y = 0.0, Z = 0.0 }",
                        "H1 = 50.0\nH2 = 20.0\nH3 = -5.0\n"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"Z", 60}}}, {"rapid", {{"Z", 30}}}, {"rapid", {{"Z", 10}}},
               {"rapid", {{"Z", -40}}}, {"rapid", {{"Z", 5}}}, {"rapid", {{"Z", 100}}}});
}

TEST(SiemensConformance, G52LocalCoordinates) {
  Lowered r = lower(Dialect::SiemensIsoM,
                "N10 G90 G55 G00 X0 Y0;\nN20 G52 X10. Y20.;\nN30 X5. Y5.;\nN40 G52 X0 Y0 Z0;\n"
                "N50 X5. Y5.;\nN60 M30;\n",
                siemens("", "{ X = 0.0, Y = 0.0, Z = 0.0 }", "",
                        "G54 = [0.0, 0.0, 0.0]\nG55 = [100.0, 50.0, 0.0]\n"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 100}, {"Y", 50}}}, {"rapid", {{"X", 115}, {"Y", 75}}},
               {"rapid", {{"X", 105}, {"Y", 55}}}});
}

TEST(SiemensConformance, G53MachineCoordinates) {
  Lowered r = lower(Dialect::SiemensIsoM, "N10 G90 G00 X10. Y10.;\nN20 G53 X0 Y0;\nN30 X20.;\nN40 M30;\n",
                siemens("", "{ X = 0.0, Y = 0.0, Z = 0.0 }", "", "G54 = [100.0, 50.0, 0.0]\n"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 110}, {"Y", 60}}}, {"rapid", {{"X", 0}, {"Y", 0}}},
               {"rapid", {{"X", 120}, {"Y", 0}}}});
}

TEST(SiemensConformance, G90G91SameBlock) {
  Lowered r = lower(Dialect::SiemensIsoM, "N10 G90 G01 X10. F100.;\nN20 G90 G91 X5.;\nN30 G91 G90 X5.;\nN40 M30;\n",
                siemens(""));
  expectMoves(r, kXYZ,
              {{"line", {{"X", 10}}, {}, false, 100}, {"line", {{"X", 15}}, {}, false, 100},
               {"line", {{"X", 5}}, {}, false, 100}});
}

TEST(SiemensConformance, G92ShiftAndG921Reset) {
  Lowered r = lower(Dialect::SiemensIsoM, "N10 G0 X100 Y100\nN20 G92 X10 Y10\nN30 G0 X50 Y50\nN40 G92.1 X0 Y0\n",
                siemens(""));
  expectMoves(r, kXYZ, {{"rapid", {{"X", 100}, {"Y", 100}}}, {"rapid", {{"X", 140}, {"Y", 140}}}});
}

TEST(SiemensConformance, F1DigitFeed) {
  Lowered r = lower(Dialect::SiemensIsoM,
                "N10 X10 Y10 Z10 F0 G94 ;\nN20 G01 X150 Y30 F1 ;\nN30 Z0 F2 ;\nN40 Z10 F0 ;\n",
                siemens("f1_digit_feed = true\n"
                        "f1_f9_feedrates = [1500.0, 550.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]\n"));
  expectMoves(r, kXYZ,
              {{"rapid", {{"X", 10}, {"Y", 10}, {"Z", 10}}},
               {"line", {{"X", 150}, {"Y", 30}}, {}, false, 1500},
               {"line", {{"Z", 0}}, {}, false, 550},
               {"rapid", {{"Z", 10}}}});
}

}  // namespace
}  // namespace ncc::passes::test
