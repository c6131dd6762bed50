// The pass names of each command's pipeline, the checks of --print-after / --stop-after, and
// the hook for stages before lowering (AstStageTap).
#include <sstream>

#include "ast_stages.h"
#include "gtest/gtest.h"
#include "ncc/driver/compile.h"
#include "ncc/frontend/block_reader.h"

namespace ncc::driver {
namespace {

TEST(PipelineStages, EachCommandsPassesInOrder) {
  EXPECT_EQ(pipelineStages(Pipeline::Compile),
            (std::vector<std::string>{"evaluate", "lower", "cycles", "corners", "transform", "compensation", "work-to-machine"}));
  EXPECT_EQ(pipelineStages(Pipeline::Check),
            (std::vector<std::string>{"evaluate", "lower", "cycles", "corners", "transform", "compensation", "work-to-machine", "travel-check"}));
}

TEST(CheckPassControl, AcceptsThePipelinesNamesOnly) {
  PassControl ok;
  ok.print_after = {"lower", "work-to-machine"};
  ok.stop_after = "work-to-machine";
  EXPECT_EQ(checkPassControl(ok, Pipeline::Compile), std::nullopt);
  PassControl travel;
  travel.stop_after = "travel-check";
  EXPECT_EQ(checkPassControl(travel, Pipeline::Check), std::nullopt);
  EXPECT_EQ(checkPassControl(travel, Pipeline::Compile),
            "--stop-after: pass 'travel-check' does not run in ncc compile (only in ncc check); "
            "the passes of ncc compile: evaluate, lower, cycles, corners, transform, compensation, work-to-machine");
  PassControl late;
  late.stop_after = "lower";
  late.print_after = {"lower", "travel-check"};
  EXPECT_EQ(checkPassControl(late, Pipeline::Check),
            "--print-after: pass 'travel-check' does not run: the pipeline stops after 'lower' "
            "(--stop-after)");
}

TEST(AstStages, EvaluateComesBeforeLowering) {
  const AstStage* evaluate = findAstStage("evaluate");
  ASSERT_NE(evaluate, nullptr);
  EXPECT_TRUE(evaluate->built);
  PassControl control;
  control.print_after = {"evaluate", "lower"};
  control.stop_after = "lower";
  EXPECT_EQ(checkPassControl(control, Pipeline::Compile), std::nullopt);
  PassControl late;
  late.stop_after = "evaluate";
  late.print_after = {"lower"};
  std::optional<std::string> why = checkPassControl(late, Pipeline::Compile);
  ASSERT_TRUE(why);
  EXPECT_NE(why->find("the pipeline stops after 'evaluate'"), std::string::npos) << *why;
}

// What the driver's block loop sees through the hook, for a stage before lowering.
TEST(AstStageTap, PrintsAndStopsAfterAnAstStage) {
  DiagnosticEngine diags;
  std::optional<ast::Block> block = frontend::parseIsoBlock("N10 G01 X1. F100.", 1, 1, diags);
  ASSERT_TRUE(block);
  std::string text = frontend::printBlock(*block);

  PassControl print;
  print.print_after = {"evaluate"};
  std::ostringstream printed, stopped;
  passes::PassPrinter printer(printed, {"X", "Y", "Z"});
  AstStageTap tap(print, &printer, &stopped);
  EXPECT_TRUE(tap.lowers());
  EXPECT_TRUE(tap.after("evaluate", *block));   // printed, and lowered next
  EXPECT_TRUE(tap.after("resolve", *block));    // a stage nobody asked about: nothing
  tap.finish();
  EXPECT_EQ(printed.str(), "; after evaluate\n" + text + "\n");
  EXPECT_EQ(stopped.str(), "");

  std::ostringstream empty;  // a program without blocks
  passes::PassPrinter empty_printer(empty, {"X", "Y", "Z"});
  AstStageTap no_blocks(print, &empty_printer, nullptr);
  no_blocks.finish();
  EXPECT_EQ(empty.str(), "; after evaluate\n");

  PassControl stop;
  stop.stop_after = "evaluate";
  std::ostringstream out;
  AstStageTap stopping(stop, nullptr, &out);
  EXPECT_FALSE(stopping.lowers());
  EXPECT_FALSE(stopping.after("evaluate", *block));  // the block goes no further
  EXPECT_EQ(out.str(), text + "\n");                   // the output, as --emit=ir's, no header
}

}  // namespace
}  // namespace ncc::driver
