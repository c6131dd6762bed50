// Cutter radius compensation as lowering records it (passes/src/lowering_cutter_comp.cpp,
// docs/semantics.md "Cutter compensation: what lowering records"): the ir::CutterComp of each
// block at the `lower` stage, per dialect, and every alarm lowering raises for it. The
// compensation pass (the tool centre's path) is not run here: the blocks are taken as
// lowering emits them.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "ncc/frontend/block_reader.h"
#include "ncc/ir/printer.h"
#include "ncc/machine/machine_file.h"
#include "ncc/passes/dialect_table.h"
#include "ncc/passes/lowering.h"

namespace ncc::passes::test {
namespace {

class Collect : public ir::BlockSink {
 public:
  explicit Collect(std::vector<ir::Block>& out) : out_(out) {}
  void accept(ir::Block&& block) override { out_.push_back(std::move(block)); }
  void finish() override {}

 private:
  std::vector<ir::Block>& out_;
};

struct Lowered {
  std::vector<ir::Block> blocks;
  std::string diags;  // "line:col: error[CODE]: message\n" each
  // "line: comp(...)" for each block with a record, as --print-after=lower prints it.
  std::string comps() const {
    std::string out;
    for (const ir::Block& b : blocks) {
      if (!b.comp) continue;
      const std::string text = ir::printBlock(b, {"X", "Y", "Z"});
      const size_t at = text.find(" comp(");
      absl::StrAppend(&out, b.loc.line, ":", text.substr(at, text.find('\n') - at), "\n");
    }
    return out;
  }
  const ir::Block& line(uint32_t n) const {
    for (const ir::Block& b : blocks)
      if (b.loc.line == n) return b;
    static const ir::Block none;
    ADD_FAILURE() << "no block at line " << n;
    return none;
  }
};

// D1 = 5, D2 = -4 (a negative radius swaps the side in the pass), D3 = 2.
std::string machine(const std::string& params = "") {
  return absl::StrCat(
      "[machine]\naxes = [\"X\", \"Y\", \"Z\"]\n[machine.offsets]\nD1 = 5.0\nD2 = -4.0\n"
      "D3 = 2.0\n[machine.work]\nG54 = [0.0, 0.0, 0.0]\n[machine.params]\n",
      params, "\n[start]\nposition = { X = 0.0, Y = 0.0, Z = 0.0 }\n");
}

// Lowers `program` (one block a line) and keeps the IR as lowering emits it.
Lowered lowerOnly(Dialect dialect, const std::string& program, const std::string& params = "") {
  Lowered run;
  SourceManager sources;
  DiagnosticEngine diags(&sources);
  auto parsed = parseMachineFile(machine(params), "machine.toml", sources, diags);
  EXPECT_TRUE(parsed.has_value());
  if (!parsed) return run;
  MachineConfig config = *parsed;
  const uint32_t file = sources.addBuffer("test.nc", program);
  Collect collect(run.blocks);
  LoweringOptions options;
  options.dialect = dialect;
  options.machine = &config;
  Lowering lowering(options, diags, collect);
  uint32_t n = 0;
  std::string_view rest = program;
  while (!rest.empty()) {
    const size_t eol = rest.find('\n');
    std::string_view text = rest.substr(0, eol);
    rest = eol == std::string_view::npos ? std::string_view() : rest.substr(eol + 1);
    auto block = frontend::parseIsoBlock(text, file, ++n, diags);
    if (!block) continue;
    if (lowering.lower(*block).program_end) break;
  }
  lowering.finish();
  for (const Diagnostic& d : diags.diagnostics())
    absl::StrAppend(&run.diags, d.location.line, ":", d.location.column, ": ",
                    d.severity == Severity::Error ? "error" : "warning", "[", d.code, "]: ",
                    d.message, "\n");
  return run;
}

constexpr Dialect kAll[] = {Dialect::FanucM, Dialect::MazakM, Dialect::SiemensIsoM};

// ---- the tables --------------------------------------------------------------------------

TEST(CutterCompLowering, TablesMakeG40G41G42RealAndG38G39WhereTheManualHasThem) {
  for (Dialect d : kAll) {
    const DialectTable* t = dialectTable(d);
    ASSERT_NE(t->comp, nullptr);
    EXPECT_EQ(t->findG(400)->action, GAction::CompCancel);
    EXPECT_TRUE(t->findG(400)->power_on_default);
    EXPECT_EQ(t->findG(410)->action, GAction::CompLeft);
    EXPECT_EQ(t->findG(420)->action, GAction::CompRight);
  }
  for (Dialect d : {Dialect::FanucM, Dialect::MazakM}) {
    EXPECT_EQ(dialectTable(d)->findG(380)->action, GAction::CompVectorHold);
    EXPECT_EQ(dialectTable(d)->findG(390)->action, GAction::CompCornerArc);
  }
  EXPECT_EQ(dialectTable(Dialect::SiemensIsoM)->findG(380), nullptr);
  EXPECT_EQ(dialectTable(Dialect::SiemensIsoM)->findG(390), nullptr);
  EXPECT_EQ(dialectTable(Dialect::FanucM)->findG(412)->action, GAction::NotSupported);
  const CompRules& f = *dialectTable(Dialect::FanucM)->comp;
  const CompRules& m = *dialectTable(Dialect::MazakM)->comp;
  const CompRules& s = *dialectTable(Dialect::SiemensIsoM)->comp;
  EXPECT_EQ(std::vector<int>({f.lookahead, m.lookahead, s.lookahead}), std::vector<int>({3, 5, 2}));
  EXPECT_TRUE(f.side_change_early_is_error && m.side_change_early_is_error);
  EXPECT_FALSE(s.side_change_early_is_error);
  EXPECT_TRUE(s.reference_return_is_error);
  EXPECT_FALSE(f.reference_return_is_error || m.reference_return_is_error);
  EXPECT_TRUE(m.d_zero_cancels && m.has_3d && m.cycle_in_3d_is_error);
  EXPECT_FALSE(f.d_zero_cancels || s.d_zero_cancels || f.has_3d || s.has_3d);
  EXPECT_TRUE(s.arc_corners);
  EXPECT_FALSE(f.arc_corners || m.arc_corners);
}

// ---- what is recorded ----------------------------------------------------------------------

TEST(CutterCompLowering, FanucRecordsEveryBlockFromStartUpToCancel) {
  Lowered r = lowerOnly(Dialect::FanucM,
                        "G17 G90 G00 X0 Y0\n"
                        "G41 G01 X10. Y10. D1 F100.\n"  // 2: start-up
                        "X50. I1. J0\n"                 // 3: IJ-type vector
                        "G39 I0 J1.\n"                  // 4: corner arc, its end vector
                        "G38 X60.\n"                    // 5: vector hold
                        "M08\n"                         // 6: no motion, still compensated
                        "G02 X70. Y20. R10.\n"          // 7: I J R of an arc are the arc's
                        "G01 G40 X0 Y0 I-1. J0\n"       // 8: cancel with a virtual next move
                        "X5.\n"                         // 9: nothing recorded
                        "M30\n");
  EXPECT_EQ(r.diags, "");
  EXPECT_EQ(r.comps(),
            "2: comp(left D1=5.000 commanded)\n"
            "3: comp(left D1=5.000 vector 1.000 0.000 0.000)\n"
            "4: comp(left D1=5.000 corner-arc vector 0.000 1.000 0.000)\n"
            "5: comp(left D1=5.000 hold)\n"
            "6: comp(left D1=5.000)\n"
            "7: comp(left D1=5.000)\n"
            "8: comp(off D1=5.000 vector -1.000 0.000 0.000)\n");
  EXPECT_TRUE(r.line(4).ops.empty());  // G39 moves nothing itself
  const ir::CutterComp& c = *r.line(2).comp;
  EXPECT_EQ(c.loc.line, 2u);
  EXPECT_EQ(c.loc.column, 1u);  // the G41 word
  EXPECT_EQ(c.startup, ir::CutterComp::Startup::A);
  EXPECT_FALSE(c.arc_corners);
  EXPECT_EQ(c.lookahead, 3);
  EXPECT_EQ(c.max_without_motion, 1);  // No.19625 - 2
  EXPECT_TRUE(c.interference_check);
  EXPECT_EQ(r.line(8).comp->loc.column, 5u);  // the G40 word
}

TEST(CutterCompLowering, TheSideIsTheOneAfterTheBlockAndSameSideAgainCountsOnFanucOnly) {
  const std::string program =
      "G17 G90 G01 F100.\nG42 X10. D2\nX20.\nX30.\nG41 X40.\nG41 Y10.\nG40 X0 Y0\nM30\n";
  EXPECT_EQ(lowerOnly(Dialect::FanucM, program).comps(),
            "2: comp(right D2=-4.000 commanded)\n3: comp(right D2=-4.000)\n"
            "4: comp(right D2=-4.000)\n5: comp(left D2=-4.000 commanded)\n"
            "6: comp(left D2=-4.000 commanded)\n7: comp(off D2=-4.000)\n");
  // Mazak §12-4-2 4.: "G41 or G42 given in compensation mode is ignored".
  EXPECT_EQ(lowerOnly(Dialect::MazakM, program).comps(),
            "2: comp(right D2=-4.000 commanded)\n3: comp(right D2=-4.000)\n"
            "4: comp(right D2=-4.000)\n5: comp(left D2=-4.000 commanded)\n"
            "6: comp(left D2=-4.000)\n7: comp(off D2=-4.000)\n");
}

TEST(CutterCompLowering, DialectDefaultsAndParametersAreRecorded) {
  const std::string program = "G17 G01 G41 X10. D1 F100.\nG40 X0\nM30\n";
  const ir::CutterComp mazak = *lowerOnly(Dialect::MazakM, program).line(1).comp;
  EXPECT_EQ(mazak.lookahead, 5);
  EXPECT_EQ(mazak.max_without_motion, 4);
  EXPECT_FALSE(mazak.arc_corners);
  const ir::CutterComp siemens = *lowerOnly(Dialect::SiemensIsoM, program).line(1).comp;
  EXPECT_EQ(siemens.lookahead, 2);
  EXPECT_EQ(siemens.max_without_motion, 2);
  EXPECT_TRUE(siemens.arc_corners);  // G450
  const ir::CutterComp set = *lowerOnly(Dialect::FanucM, program,
                                        "startup_type = \"B\"\nouter_corner_connection = \"arc\"\n"
                                        "tnrc_lookahead_blocks = 6\ninterference_check = false\n"
                                        "corner_move_limit = 0.02\n")
                                  .line(1)
                                  .comp;
  EXPECT_EQ(set.startup, ir::CutterComp::Startup::B);
  EXPECT_TRUE(set.arc_corners);
  EXPECT_EQ(set.lookahead, 6);
  EXPECT_EQ(set.max_without_motion, 4);  // 6 - 2
  EXPECT_FALSE(set.interference_check);
  EXPECT_DOUBLE_EQ(set.corner_move_limit, 0.02);
  // Mazak's fixed 4 does not follow the look-ahead.
  EXPECT_EQ(lowerOnly(Dialect::MazakM, program, "tnrc_lookahead_blocks = 8\n").line(1)
                .comp->max_without_motion,
            4);
  const ir::CutterComp siemens_linear =
      *lowerOnly(Dialect::SiemensIsoM, program, "outer_corner_connection = \"linear\"\n")
           .line(1)
           .comp;
  EXPECT_FALSE(siemens_linear.arc_corners);
}

TEST(CutterCompLowering, AG10RadiusWriteIsSeenFromItsOwnBlockOn) {
  Lowered r = lowerOnly(Dialect::FanucM,
                        "G17 G01 G41 X10. D1 F100.\nG10 L12 P1 R6.\nX20.\nG10 L13 P1 R-0.5\n"
                        "X30.\nD3 X40.\nG40 X0\nM30\n");
  EXPECT_EQ(r.diags, "");
  EXPECT_EQ(r.comps(),
            "1: comp(left D1=5.000 commanded)\n2: comp(left D1=6.000)\n3: comp(left D1=6.000)\n"
            "4: comp(left D1=5.500)\n5: comp(left D1=5.500)\n6: comp(left D3=2.000)\n"
            "7: comp(off D3=2.000)\n");
}

TEST(CutterCompLowering, MazakD00CancelsSiemensD00IsRadiusZero) {
  const std::string program = "G17 G01 G41 X10. D1 F100.\nX20.\nD0 X30.\nX40.\nM30\n";
  Lowered mazak = lowerOnly(Dialect::MazakM, program);
  EXPECT_EQ(mazak.diags, "");
  EXPECT_EQ(mazak.comps(),
            "1: comp(left D1=5.000 commanded)\n2: comp(left D1=5.000)\n3: comp(off D0=0.000)\n");
  EXPECT_EQ(mazak.line(3).comp->loc.column, 1u);  // the D word cancels
  Lowered siemens = lowerOnly(Dialect::SiemensIsoM, program);
  EXPECT_EQ(siemens.diags, "");
  EXPECT_EQ(siemens.comps(),
            "1: comp(left D1=5.000 commanded)\n2: comp(left D1=5.000)\n3: comp(left D0=0.000)\n"
            "4: comp(left D0=0.000)\n5: comp(left D0=0.000)\n");
  // Mazak: G41 with D0 in force is no start-up ("0 < D <= max").
  EXPECT_EQ(lowerOnly(Dialect::MazakM, "G17 G01 G41 X10. F100.\nX20.\nM30\n").comps(), "");
}

TEST(CutterCompLowering, MazakG38WithIJSetsANewVectorFanucHasOnlyTheHold) {
  Lowered mazak =
      lowerOnly(Dialect::MazakM, "G17 G01 G42 X10. D1 F100.\nG38 X20. I0 J-1. D3\nG40 X0\nM30\n");
  EXPECT_EQ(mazak.diags, "");
  EXPECT_EQ(mazak.comps(),
            "1: comp(right D1=5.000 commanded)\n2: comp(right D3=2.000 hold vector 0.000 -1.000 0.000)\n"
            "3: comp(off D3=2.000)\n");
  // In G02/G03 mode I J are the arc's centre, G38 only holds the vector.
  Lowered arc = lowerOnly(Dialect::MazakM,
                          "G17 G01 G42 X10. D1 F100.\nG02 G38 X20. Y0 I5. J0\nG01 G40 X0\nM30\n");
  EXPECT_EQ(arc.diags, "");
  EXPECT_EQ(arc.line(2).comp->special, ir::CutterComp::Special::VectorHold);
  EXPECT_FALSE(arc.line(2).comp->vector.has_value());
  ASSERT_EQ(arc.line(2).ops.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<ir::Arc>(arc.line(2).ops[0]));
  Lowered fanuc = lowerOnly(Dialect::FanucM, "G17 G01 G42 X10. D1 F100.\nG38 X20. I0 J-1.\nM30\n");
  EXPECT_EQ(fanuc.diags, "2:10: error[NCC2014]: address I has no meaning in this block\n");
}

TEST(CutterCompLowering, MazakThreeDimensionalOffset) {
  // §12-4: offset = r (I,J,K) / |I,J,K| for G41, the negative for G42; F11 replaces |I,J,K|.
  Lowered r = lowerOnly(Dialect::MazakM,
                        "G17 G01 G41 X10. Y1. Z1. I0 J3. K4. D1 F100.\nX20.\nD3 X30.\nG40 X0\nM30\n");
  EXPECT_EQ(r.diags, "");
  EXPECT_EQ(r.comps(),
            "1: comp(left D1=5.000 commanded 3d 0.000 3.000 4.000)\n"
            "2: comp(left D1=5.000 3d 0.000 3.000 4.000)\n"
            "3: comp(left D3=2.000 3d 0.000 1.200 1.600)\n"
            "4: comp(off D3=2.000)\n");
  Lowered right = lowerOnly(Dialect::MazakM, "G17 G01 G42 X10. I1. J0 K0 D1 F100.\nM30\n",
                            "comp3d_normal_length = 2.5\n");
  EXPECT_EQ(right.comps(),
            "1: comp(right D1=5.000 commanded 3d -2.000 0.000 0.000)\n"
            "2: comp(right D1=5.000 3d -2.000 0.000 0.000)\n");
  // Two of I J K with G41: 2-D compensation, and they have no meaning (Mazak has no IJ vector).
  EXPECT_EQ(lowerOnly(Dialect::MazakM, "G17 G01 G41 X10. I1. J1. D1 F100.\nM30\n").diags,
            "1:18: error[NCC2014]: address I has no meaning in this block\n");
}

TEST(CutterCompLowering, AHoleCycleIsSuspendedAndMazak901In3D) {
  const std::string cycle = "G17 G90 G00 G41 X10. Y10. D1 M03\nG81 X20. Y10. Z-5. R1. F100.\nG80\nG40 X0 Y0\nM30\n";
  for (Dialect d : kAll) {
    Lowered r = lowerOnly(d, cycle);
    EXPECT_EQ(r.diags, "");
    EXPECT_FALSE(r.line(1).comp->suspended);
    ASSERT_TRUE(r.line(2).comp.has_value());
    EXPECT_TRUE(r.line(2).comp->suspended);
    EXPECT_FALSE(r.line(3).comp->suspended);
  }
  Lowered r = lowerOnly(Dialect::MazakM,
                        "G17 G90 G00 G41 X10. Y10. Z1. I0 J0 K1. D1\nG81 X20. Y10. Z-5. R1. F100.\nM30\n");
  EXPECT_EQ(r.diags,
            "2:1: error[901]: a hole cycle is not allowed in 3-D cutter compensation; cancel it "
            "with G40\n");
}

TEST(CutterCompLowering, IJKOutsideTheirContextsStillHaveNoMeaning) {
  // G40 in cancel mode: I J ignored (FANUC §5.2), nothing recorded.
  Lowered fanuc = lowerOnly(Dialect::FanucM, "G17 G01 G40 X1. I1. J0 F100.\nM30\n");
  EXPECT_EQ(fanuc.diags, "");
  EXPECT_EQ(fanuc.comps(), "");
  // A G01 block without compensation; K outside the G17 plane's I J; Siemens G40 I J.
  EXPECT_EQ(lowerOnly(Dialect::FanucM, "G17 G01 X1. I1. J0 F100.\nM30\n").diags,
            "1:13: error[NCC2014]: address I has no meaning in this block\n");
  EXPECT_EQ(lowerOnly(Dialect::FanucM, "G17 G01 G41 X1. I1. K1. D1 F100.\nM30\n").diags,
            "1:21: error[NCC2014]: address K has no meaning in G17: the vector of G41 is I J\n");
  EXPECT_EQ(lowerOnly(Dialect::SiemensIsoM, "G17 G01 G41 X1. D1 F100.\nX2.\nG40 X3. I1. J0\nM30\n")
                .diags,
            "3:9: error[NCC2014]: address I has no meaning in this block\n");
  EXPECT_EQ(lowerOnly(Dialect::FanucM, "G17 G01 G41 X1. I0 J0 D1 F100.\nM30\n").diags,
            "1:17: error[NCC2031]: the I J K vector of G41 is zero: it gives no direction\n");
}

TEST(CutterCompLowering, ProgramEndPutsG40Back) {
  // M30 resets the control: the block after it would start from G40 (the lowering's state).
  Lowered r = lowerOnly(Dialect::FanucM, "G17 G01 G41 X10. D1 F100.\nM30\n");
  EXPECT_EQ(r.comps(), "1: comp(left D1=5.000 commanded)\n2: comp(left D1=5.000)\n");
}

TEST(CutterCompLowering, G38G39OutsideCompensationWarnAndDoNothing) {
  Lowered r = lowerOnly(Dialect::FanucM, "G17 G01 X1. F100.\nG39\nM30\n");
  EXPECT_EQ(r.diags, "2:1: warning[NCC2014]: G39 has no effect outside cutter compensation (G41/G42)\n");
  EXPECT_EQ(r.comps(), "");
}

// ---- alarms ----------------------------------------------------------------------------

struct AlarmCase {
  const char* name;
  Dialect dialect;
  const char* program;
  const char* expected;
};

class CutterCompAlarm : public testing::TestWithParam<AlarmCase> {};

TEST_P(CutterCompAlarm, ReportsCodeLocationAndMessage) {
  const AlarmCase& c = GetParam();
  Lowered r = lowerOnly(c.dialect, c.program);
  EXPECT_EQ(r.diags, std::string(c.expected) + "\n");
  // Nothing is written for the rejected block.
  const uint32_t rejected = static_cast<uint32_t>(std::stoi(c.expected));
  for (const ir::Block& b : r.blocks) EXPECT_NE(b.loc.line, rejected);
}

const AlarmCase kAlarms[] = {
    {"StartInArcFanuc", Dialect::FanucM, "G17 G02 G41 X10. Y0 R5. D1 F100.",
     "1:9: error[PS0034]: G41 starts cutter compensation in G02 mode: the start-up and the "
     "cancel must be G00 or G01 blocks"},
    {"StartInArcMazak", Dialect::MazakM, "G17 G03 G42 X10. Y0 R5. D1 F100.",
     "1:9: error[835]: G42 starts cutter compensation in G03 mode: the start-up and the cancel "
     "must be G00 or G01 blocks"},
    {"StartInArcSiemens", Dialect::SiemensIsoM, "G17 G02 G41 X10. Y0 R5. D1 F100.",
     "1:9: error[NCC2120]: G41 starts cutter compensation in G02 mode: the start-up and the "
     "cancel must be G00 or G01 blocks"},
    {"CancelInArcFanuc", Dialect::FanucM, "G17 G01 G41 X10. D1 F100.\nG02 X20. Y10. R10.\nG40",
     "3:1: error[PS0034]: G40 cancels cutter compensation in G02 mode: the start-up and the "
     "cancel must be G00 or G01 blocks"},
    {"CancelByD00InArcMazak", Dialect::MazakM,
     "G17 G01 G41 X10. D1 F100.\nG02 X20. Y10. R10.\nD00",
     "3:1: error[835]: D0 cancels cutter compensation in G02 mode: the start-up and the cancel "
     "must be G00 or G01 blocks"},
    {"ThreeDChangeInArcMazak", Dialect::MazakM,
     "G17 G01 G41 X10. D1 F100.\nX20.\nG02 G42 X30. Y10. I0 J10. K1.",
     "3:5: error[835]: G42 with I J K (3-D compensation) in G02 mode: 3-D compensation starts "
     "and changes in G00 or G01 blocks"},
    {"PlaneChangeFanuc", Dialect::FanucM, "G17 G01 G41 X10. D1 F100.\nX20.\nG18 X30.",
     "3:1: error[PS0037]: G18 changes the plane from G17 while cutter compensation (G41) is in "
     "force; cancel it with G40 first"},
    {"PlaneChangeSiemens", Dialect::SiemensIsoM, "G17 G01 G42 X10. D1 F100.\nG19 G40 X30.",
     "2:1: error[NCC2121]: G19 changes the plane from G17 while cutter compensation (G42) is in "
     "force; cancel it with G40 first"},
    {"SkipFanuc", Dialect::FanucM, "G17 G01 G41 X10. D1 F100.\nG31 X20.",
     "2:1: error[PS0035]: G31 (skip) is not allowed while G41 cutter compensation is in force"},
    {"SkipMazak", Dialect::MazakM, "G17 G01 G41 X10. D1 F100.\nG31 X20. F50.",
     "2:1: error[NCC2122]: G31 (skip) is not allowed while G41 cutter compensation is in force"},
    {"ReferenceReturnSiemens", Dialect::SiemensIsoM, "G17 G01 G41 X10. D1 F100.\nG91 G28 Z0",
     "2:5: error[NCC2123]: G28 (reference return) is not allowed while G41 cutter compensation "
     "is in force; cancel it with G40"},
    {"SecondReferenceReturnSiemens", Dialect::SiemensIsoM, "G17 G01 G42 X10. D1 F100.\nG30 P2 Z0",
     "2:1: error[NCC2123]: G30 (reference return) is not allowed while G42 cutter compensation "
     "is in force; cancel it with G40"},
    {"SideChangeEarlyFanuc", Dialect::FanucM, "G17 G01 G41 X10. D1 F100.\nG42 X20.",
     "2:1: error[NCC2124]: G42 changes the compensation side in the block after the G41 "
     "start-up: the side may change from the third compensated block on"},
    {"SideChangeEarlyMazak", Dialect::MazakM, "G17 G01 G42 X10. D1 F100.\nG41 X20.",
     "2:1: error[NCC2124]: G41 changes the compensation side in the block after the G42 "
     "start-up: the side may change from the third compensated block on"},
    {"CornerArcMoveFanuc", Dialect::FanucM, "G17 G01 G41 X10. D1 F100.\nX20.\nG39 Y5.",
     "3:5: error[NCC2125]: G39 (corner arc) cannot move: address Y is not allowed in its block"},
    {"CornerArcMoveMazak", Dialect::MazakM, "G17 G01 G41 X10. D1 F100.\nX20.\nG39 X30. I1. J0",
     "3:5: error[NCC2125]: G39 (corner arc) cannot move: address X is not allowed in its block"},
    {"OffsetNumberFanuc", Dialect::FanucM, "G17 G01 G41 X10. D401 F100.",
     "1:18: error[PS0030]: D401 is out of range: offset numbers are 1-400 (offset_count)"},
    {"OffsetNumberMazak", Dialect::MazakM, "G17 G01 G41 X10. D129 F100.",
     "1:18: error[839]: D129 is out of range: offset numbers are 1-128 (offset_count)"},
    {"G38WithG04", Dialect::FanucM, "G17 G01 G41 X10. D1 F100.\nG38 G04 X1.",
     "2:5: error[NCC2021]: G04 and G38 cannot be given in one block"},
};

INSTANTIATE_TEST_SUITE_P(CutterCompLowering, CutterCompAlarm, testing::ValuesIn(kAlarms),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(CutterCompLowering, ARejectedBlockLeavesTheSideUnknownUntilGivenAgain) {
  // The side change is refused: the block emits no IR, and as for any modal group the side it
  // would have set is unknown (lowering_recovery.cpp): X30. is not emitted; G41 determines it.
  Lowered r =
      lowerOnly(Dialect::FanucM, "G17 G01 G41 X10. D1 F100.\nG42 X20.\nX30.\nG41 X40.\nM30\n");
  EXPECT_EQ(r.diags.substr(0, 19), "2:1: error[NCC2124]");
  for (const ir::Block& b : r.blocks) EXPECT_TRUE(b.loc.line != 2u && b.loc.line != 3u);
  EXPECT_EQ(r.line(4).comp->side, ir::CutterComp::Side::Left);
}

TEST(CutterCompLowering, TheStartUpBlockMayChooseThePlane) {
  Lowered r = lowerOnly(Dialect::SiemensIsoM, "G17 G01 F100.\nG18 G41 X10. Z5. D1\nG40 X0\nM30\n");
  EXPECT_EQ(r.diags, "");
  EXPECT_EQ(r.line(2).modal.plane, ir::Plane::ZX);
  EXPECT_EQ(r.line(2).comp->side, ir::CutterComp::Side::Left);
}

TEST(CutterCompLowering, TheDialectsRulesAndThePlanesAxesAreRecorded) {
  const std::string program = "G18 G01 G41 X10. Z5. D1 F100.\nM08\nG40 X0\nM30\n";
  for (Dialect d : kAll) {
    Lowered r = lowerOnly(d, program);
    EXPECT_EQ(r.diags, "");
    for (uint32_t line : {1u, 2u, 3u}) {
      const ir::CutterComp& c = *r.line(line).comp;
      EXPECT_EQ(std::vector<int>({c.plane_a, c.plane_b, c.plane_normal}),
                std::vector<int>({2, 0, 1}));  // G18: Z X, normal Y
      EXPECT_EQ(c.recommand_perpendicular, d == Dialect::FanucM);
      EXPECT_EQ(c.side_change_perpendicular, d == Dialect::SiemensIsoM);
    }
  }
}

TEST(CutterCompLowering, SiemensChangesTheSideAnywhere) {
  Lowered r = lowerOnly(Dialect::SiemensIsoM, "G17 G01 G41 X10. D1 F100.\nG42 X20.\nM30\n");
  EXPECT_EQ(r.diags, "");
  EXPECT_EQ(r.line(2).comp->side, ir::CutterComp::Side::Right);
  EXPECT_TRUE(r.line(2).comp->side_commanded);
}

}  // namespace
}  // namespace ncc::passes::test
