// The named pipeline: which passes run, --stop-after, --print-after's taps, --verify-each.
#include "ncc/passes/pass_manager.h"

#include <sstream>

#include "gtest/gtest.h"
#include "ncc/ir/printer.h"

namespace ncc::passes {
namespace {

class Keep : public ir::BlockSink {
 public:
  void accept(ir::Block&& b) override { blocks.push_back(std::move(b)); }
  void finish() override { finished = true; }
  std::vector<ir::Block> blocks;
  bool finished = false;
};

// A block with one work-space rapid to X1 under a work offset of X5.
ir::Block offsetRapid(int line) {
  ir::Block b;
  b.loc.line = line;
  b.frame.work_offset = {5, 0, 0};
  b.ops.push_back(ir::Rapid{{1, 0, 0}, ir::Space::Work, ir::RapidType::Linear});
  return b;
}

TEST(PassRegistry, NamesInPipelineOrder) {
  std::vector<std::string_view> names;
  for (const PassInfo& pass : passRegistry()) names.push_back(pass.name);
  EXPECT_EQ(names,
            (std::vector<std::string_view>{"lower", "cycles", "corners", "transform", "compensation", "work-to-machine", "travel-check"}));
  ASSERT_NE(findPass("work-to-machine"), nullptr);
  EXPECT_TRUE(findPass("work-to-machine")->machine_space_after);
  EXPECT_EQ(findPass("lower")->create, nullptr);  // the producer: the driver runs it
  ASSERT_NE(findPass("cycles"), nullptr);  // canned hole cycles, expanded in work space
  EXPECT_FALSE(findPass("cycles")->machine_space_after);
}

TEST(PassManager, PassNamesDependOnTheOptions) {
  PipelineOptions compile;
  EXPECT_EQ(PassManager::passNames(compile),
            (std::vector<std::string_view>{"lower", "cycles", "corners", "transform", "compensation", "work-to-machine"}));
  MachineConfig machine = defaultMachine();
  PipelineOptions check;
  check.travel_limits = &machine;
  EXPECT_EQ(PassManager::passNames(check),
            (std::vector<std::string_view>{"lower", "cycles", "corners", "transform", "compensation", "work-to-machine", "travel-check"}));
  PipelineOptions work;
  work.to_machine_space = false;
  EXPECT_EQ(PassManager::passNames(work), (std::vector<std::string_view>{"lower", "cycles", "corners", "transform", "compensation"}));
}

TEST(PassManager, StopAfterLowerKeepsWorkSpaceAndItsVerifierAcceptsIt) {
  DiagnosticEngine diags;
  Keep keep;
  PipelineOptions o;
  o.stop_after = "lower";
  PassManager pipeline(o, diags, keep);
  pipeline.entry().accept(offsetRapid(1));
  pipeline.entry().finish();
  ASSERT_EQ(keep.blocks.size(), 1u);
  const auto& rapid = std::get<ir::Rapid>(keep.blocks[0].ops[0]);
  EXPECT_EQ(rapid.space, ir::Space::Work);
  EXPECT_EQ(rapid.to[0], 1.0);
  EXPECT_TRUE(keep.finished);
  EXPECT_FALSE(diags.hasErrors());  // the verifier before the sink does not ask for machine space
}

TEST(PassManager, StopAfterWorkToMachineSkipsTheTravelCheck) {
  MachineConfig machine = defaultMachine();
  machine.axes[0].max_travel = 2.0;  // the rapid reaches X6
  for (bool stop : {false, true}) {
    DiagnosticEngine diags;
    Keep keep;
    PipelineOptions o;
    o.travel_limits = &machine;
    if (stop) o.stop_after = "work-to-machine";
    PassManager pipeline(o, diags, keep);
    pipeline.entry().accept(offsetRapid(1));
    pipeline.entry().finish();
    EXPECT_EQ(diags.hasErrors(), !stop) << "stop " << stop;
  }
}

TEST(PassManager, PrintAfterTapsEachNamedPassUnderItsHeader) {
  DiagnosticEngine diags;
  Keep keep;
  std::ostringstream out;
  ir::AxisNames axes{"X", "Y", "Z"};
  PassPrinter printer(out, axes);
  PipelineOptions o;
  o.print_after = {"lower", "work-to-machine"};
  o.printer = &printer;
  PassManager pipeline(o, diags, keep);
  pipeline.entry().accept(offsetRapid(1));
  pipeline.entry().accept(offsetRapid(2));
  pipeline.entry().finish();
  ASSERT_EQ(keep.blocks.size(), 2u);  // the taps forward every block
  // Blocks stream: each leaves lower, then work-to-machine, before the next one is lowered.
  std::string work1 = ir::printBlock(offsetRapid(1), axes);
  std::string work2 = ir::printBlock(offsetRapid(2), axes);
  std::string machine1 = ir::printBlock(keep.blocks[0], axes);
  std::string machine2 = ir::printBlock(keep.blocks[1], axes);
  EXPECT_NE(work1, machine1);
  EXPECT_NE(machine1.find("rapid machine X6.000"), std::string::npos) << machine1;
  EXPECT_EQ(out.str(), "; after lower\n" + work1 + "; after work-to-machine\n" + machine1 +
                           "; after lower\n" + work2 + "; after work-to-machine\n" + machine2);
}

TEST(PassManager, PrintAfterOnePassHasOneHeaderAndAnEmptyProgramShowsIt) {
  ir::AxisNames axes{"X", "Y", "Z"};
  for (int blocks : {2, 0}) {
    DiagnosticEngine diags;
    Keep keep;
    std::ostringstream out;
    PassPrinter printer(out, axes);
    PipelineOptions o;
    o.print_after = {"work-to-machine"};
    o.printer = &printer;
    PassManager pipeline(o, diags, keep);
    for (int i = 1; i <= blocks; ++i) pipeline.entry().accept(offsetRapid(i));
    pipeline.entry().finish();
    std::string expected = "; after work-to-machine\n";
    for (const ir::Block& b : keep.blocks) expected += ir::printBlock(b, axes);
    EXPECT_EQ(out.str(), expected);
  }
}

TEST(PassManager, VerifyEachNamesThePassThatLeftInvalidIr) {
  for (bool each : {false, true}) {
    DiagnosticEngine diags;
    Keep keep;
    PipelineOptions o;
    o.verify = true;  // the final verifier (the default only outside Release builds)
    o.verify_each = each;
    PassManager pipeline(o, diags, keep);
    ir::Block bad = offsetRapid(7);
    bad.ops.push_back(ir::Dwell{-1.0, false});  // lowering never makes a negative dwell
    pipeline.entry().accept(ir::Block(bad));
    pipeline.entry().accept(offsetRapid(8));
    pipeline.entry().finish();
    ASSERT_EQ(diags.diagnostics().size(), 1u) << "each " << each;
    const Diagnostic& d = diags.diagnostics()[0];
    EXPECT_EQ(d.code, "NCC9001");
    EXPECT_EQ(d.location.line, 7u);
    // With verify_each the first verifier, right after lower, catches it.
    std::string after = each ? "after pass lower: " : "after pass work-to-machine: ";
    EXPECT_NE(d.message.find("internal error: invalid IR " + after), std::string::npos) << d.message;
    ASSERT_EQ(keep.blocks.size(), 1u);  // the invalid block goes no further
    EXPECT_EQ(keep.blocks[0].loc.line, 8u);
  }
}

}  // namespace
}  // namespace ncc::passes
