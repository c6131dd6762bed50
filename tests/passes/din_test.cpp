// Siemens DIN blocks after G290 (docs/din.md): read by the block reader in DIN, lowered with the
// DIN table over the one controller state that ISO blocks use.
#include "gtest/gtest.h"
#include "lowering_harness.h"

namespace ncc::passes::test {
namespace {

// decimal_point = "standard": in ISO `X20` is 20 least input increments (0.020 mm); DIN always
// reads `X20` as 20 mm.
const std::string kMachine = xyzMachine("decimal_point = \"standard\"");

TEST(Din, PlainWordBlocksMoveFromTheSameStateInCalculatorNotation) {
  const Lowered r = lowerRead(Dialect::SiemensIsoM,
                              "G90 G01 X20 F100\n"   // ISO: 0.020 mm
                              "G290\n"
                              "G1 X20 Y5 F200\n"     // DIN: 20 mm, 5 mm
                              "G91 X-1\n"            // G91 in DIN, carried to ISO after
                              "G291\n"
                              "X1.\n",               // ISO, incremental: 19 + 1
                              kMachine);
  // Only the ISO X20 is a word without a point read as increments (the audit of the ISO
  // decimal-point rule counts no DIN word).
  EXPECT_EQ(r.diagText().find("error"), std::string::npos) << r.diagText();
  EXPECT_NE(r.diagText().find("1 coordinate word without a decimal point"), std::string::npos)
      << r.diagText();
  ASSERT_EQ(r.moves.size(), 4u);
  EXPECT_NEAR(r.moves[0].to[0], 0.020, 1e-9);
  EXPECT_NEAR(r.moves[1].to[0], 20.0, 1e-9);
  EXPECT_NEAR(r.moves[1].to[1], 5.0, 1e-9);
  EXPECT_NEAR(r.moves[1].feed, 200.0, 1e-9);
  EXPECT_NEAR(r.moves[2].to[0], 19.0, 1e-9);
  EXPECT_NEAR(r.moves[3].to[0], 20.0, 1e-9);
}

TEST(Din, WhatDinReadsOtherwiseIsRefusedAtItsPosition) {
  struct Case {
    const char* block;
    const char* expected;  // in the diagnostics
  };
  const Case cases[] = {
      {"G451", "NCC2010"},                // intersection at outer corners: not built
      {"G96 S100", "NCC2010"},            // constant cutting speed
      {"G70 X1 F100", "NCC2010"},         // geometry-only inch
      {"G500", "NCC2010"},                // no settable frame
      {"R10 X1 F100", "address R is not supported yet"},  // R parameter in DIN
      {"H1", "address H is not supported yet"},  // an auxiliary function in DIN
      {"X=ACP(10)", "NCC1090"},           // rotary positioning: not read yet
      {"PROC A SAVE", "NCC1090"},         // SAVE: not built yet
      {"N10 (comment) X1", "NCC1006"},    // no ( ) comments in DIN: unexpected '('
  };
  for (const Case& c : cases) {
    const Lowered r = lowerRead(Dialect::SiemensIsoM, std::string("G290\n") + c.block + "\n",
                                kMachine);
    EXPECT_NE(r.diagText().find(c.expected), std::string::npos) << c.block << "\n" << r.diagText();
    EXPECT_NE(r.diagText().find("2:"), std::string::npos) << c.block << ": at the DIN block";
  }
}

TEST(Din, G700IsInchForLengthsAndFeeds) {
  const Lowered r = lowerRead(Dialect::SiemensIsoM, "G290\nG700 G1 X1 F10\n", kMachine);
  EXPECT_EQ(r.diagText(), "");
  ASSERT_EQ(r.moves.size(), 1u);
  EXPECT_NEAR(r.moves[0].to[0], 25.4, 1e-9);
  EXPECT_NEAR(r.moves[0].feed, 254.0, 1e-9);
}

TEST(Din, MacroCallWordsAreIsoModeWords) {
  // M98 in DIN text calls nothing: it reaches lowering as an M code with a P it refuses.
  const Lowered r = lowerRead(Dialect::SiemensIsoM, "G290\nM98 P1234\n", kMachine);
  EXPECT_NE(r.diagText().find("address P is not supported yet"), std::string::npos)
      << r.diagText();
}

}  // namespace
}  // namespace ncc::passes::test
