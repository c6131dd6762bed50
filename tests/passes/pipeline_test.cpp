#include "ncc/passes/pass_manager.h"

#include "gtest/gtest.h"
#include "ncc/frontend/block_reader.h"
#include "ncc/passes/coordinate_transform.h"
#include "ncc/passes/lowering.h"

namespace ncc::passes {
namespace {

class Keep : public ir::BlockSink {
 public:
  void accept(ir::Block&& b) override { blocks.push_back(std::move(b)); }
  void finish() override { finished = true; }
  std::vector<ir::Block> blocks;
  bool finished = false;
};

TEST(WorkToMachine, AddsTheFrameToTargetsAndCentres) {
  Keep keep;
  WorkToMachinePass pass(keep, 3);
  ir::Block b;
  b.frame.work_offset = {100, 50, 0};
  b.frame.shift = {1, 2, 3};
  b.frame.tool_length = {0, 0, 10};
  b.ops.push_back(ir::Arc{{10, 0, -5}, {0, 0, -5}, ir::Space::Work, ir::Plane::XY, true, 0, 100, false});
  b.ops.push_back(ir::Rapid{{7, 7, 7}, ir::Space::Machine, ir::RapidType::Linear});
  pass.accept(ir::Block(b));
  pass.finish();
  ASSERT_EQ(keep.blocks.size(), 1u);
  const auto& arc = std::get<ir::Arc>(keep.blocks[0].ops[0]);
  EXPECT_EQ(arc.space, ir::Space::Machine);
  EXPECT_EQ(arc.to, (AxisValues{111, 52, 8}));
  EXPECT_EQ(arc.center, (AxisValues{101, 52, 8}));
  const auto& rapid = std::get<ir::Rapid>(keep.blocks[0].ops[1]);
  EXPECT_EQ(rapid.to, (AxisValues{7, 7, 7}));  // machine-space ops are left alone
  EXPECT_TRUE(keep.finished);
}

TEST(PassManager, WorkSpaceWhenAskedAndMachineSpaceByDefault) {
  DiagnosticEngine diags;
  Keep work, machine;
  PipelineOptions o;
  o.to_machine_space = false;
  PassManager debug(o, diags, work);
  PassManager full(PipelineOptions{}, diags, machine);
  ir::Block b;
  b.frame.work_offset = {5, 0, 0};
  b.ops.push_back(ir::Rapid{{1, 0, 0}, ir::Space::Work, ir::RapidType::Linear});
  debug.entry().accept(ir::Block(b));
  full.entry().accept(ir::Block(b));
  EXPECT_EQ(std::get<ir::Rapid>(work.blocks[0].ops[0]).to[0], 1.0);
  EXPECT_EQ(std::get<ir::Rapid>(machine.blocks[0].ops[0]).to[0], 6.0);
  EXPECT_FALSE(diags.hasErrors());
}

TEST(Lowering, ADinBlockInADialectWithoutDinIsRefused) {
  // The reader never reads DIN for fanuc-m; a block store could still carry such a block.
  DiagnosticEngine diags;
  Keep keep;
  MachineConfig m = defaultMachine();
  Lowering lowering({Dialect::FanucM, &m, {}}, diags, keep);
  ast::Block b = *frontend::parseIsoBlock("G1 X1 F100", 1, 7, diags);
  b.language = frontend::Language::Din;
  lowering.lower(b);
  ASSERT_EQ(diags.diagnostics().size(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].code, "NCC2002");
  EXPECT_EQ(diags.diagnostics()[0].location.line, 7u);
  EXPECT_EQ(diags.diagnostics()[0].message, "fanuc-m has no DIN language: the block cannot be lowered");
  EXPECT_TRUE(keep.blocks.empty());
}

TEST(Lowering, AcceptsLanguageSwitchesAndReportsProgramEnd) {
  DiagnosticEngine diags;
  Keep keep;
  MachineConfig m = defaultMachine();
  Lowering lowering({Dialect::SiemensIsoM, &m, {}}, diags, keep);
  // The reader switches its language on G290/G291 (reader_test.cpp); lowering takes the
  // blocks as modal codes of their own group and ends nothing.
  auto din = lowering.lower(*frontend::parseIsoBlock("G290", 1, 1, diags));
  EXPECT_FALSE(din.program_end);
  auto iso = lowering.lower(*frontend::parseIsoBlock("G291", 1, 2, diags));
  EXPECT_FALSE(iso.program_end);
  EXPECT_FALSE(diags.hasErrors());
  auto end = lowering.lower(*frontend::parseIsoBlock("M30", 1, 3, diags));
  EXPECT_TRUE(end.program_end);
  lowering.finish();
  EXPECT_TRUE(keep.finished);
  EXPECT_FALSE(diags.hasErrors());
}

TEST(Lowering, UnsupportedDialectIsReportedOnce) {
  DiagnosticEngine diags;
  Keep keep;
  MachineConfig m = defaultMachine();
  Lowering lowering({Dialect::FanucT, &m, {}}, diags, keep);
  lowering.lower(*frontend::parseIsoBlock("G00 X1.", 1, 1, diags));
  lowering.lower(*frontend::parseIsoBlock("G00 X2.", 1, 2, diags));
  ASSERT_EQ(diags.diagnostics().size(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].code, "NCC2002");
  EXPECT_TRUE(keep.blocks.empty());
}

}  // namespace
}  // namespace ncc::passes
