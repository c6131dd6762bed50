#include "ncc/ir/verifier.h"

#include <limits>

#include "gtest/gtest.h"

namespace ncc::ir {
namespace {

struct CollectingSink : BlockSink {
  std::vector<Block> blocks;
  bool finished = false;
  void accept(Block&& block) override { blocks.push_back(std::move(block)); }
  void finish() override { finished = true; }
};

Block validBlock() {
  Block b;
  b.loc = SourceLocation{1, 3, 1};
  b.ops = {Rapid{{1.0, 2.0, 3.0}, Space::Machine, RapidType::Linear},
           Linear{{1.0, 2.0, 0.0}, Space::Machine, 100.0, false}};
  return b;
}

TEST(IrVerifier, AcceptsAValidBlock) {
  EXPECT_TRUE(verify(validBlock(), VerifyOptions{3, true}).empty());
}

TEST(IrVerifier, WorkSpaceIsRejectedOnlyBeforeTheBackend) {
  Block b = validBlock();
  std::get<Rapid>(b.ops[0]).space = Space::Work;
  EXPECT_TRUE(verify(b, VerifyOptions{3, false}).empty());
  std::vector<std::string> problems = verify(b, VerifyOptions{3, true});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0],
            "operation 1: work-space target reached the backend (the coordinate transform did "
            "not run)");
}

TEST(IrVerifier, FindsNonFiniteValuesAndBadOperands) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Block b = validBlock();
  std::get<Rapid>(b.ops[0]).to[1] = nan;
  std::get<Linear>(b.ops[1]).feed = 0.0;
  b.ops.push_back(Dwell{-1.0, false});
  b.ops.push_back(MachineFunction{MachineFunction::Kind::OtherM, -5, 0.0});
  ReferenceCheck check;
  check.axes = 0b1000;  // axis 4 of 3
  b.ops.push_back(check);
  b.frame.shift[0] = std::numeric_limits<double>::infinity();
  std::vector<std::string> problems = verify(b, VerifyOptions{3, true});
  ASSERT_EQ(problems.size(), 6u);
  EXPECT_EQ(problems[0], "block: shift of axis 1 is not finite");
  EXPECT_EQ(problems[1], "operation 1: target of axis 2 is not finite");
  EXPECT_EQ(problems[2], "operation 2: feed 0 is not positive");
  EXPECT_NE(problems[3].find("operation 3: dwell"), std::string::npos);
  EXPECT_EQ(problems[4], "operation 4: negative M/T code -5");
  EXPECT_NE(problems[5].find("operation 5: reference check axis mask"), std::string::npos);
}

TEST(IrVerifier, UnusedAxisSlotsAreNotChecked) {
  Block b = validBlock();
  std::get<Rapid>(b.ops[0]).to[5] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(verify(b, VerifyOptions{3, true}).empty());
}

TEST(VerifyingSink, ForwardsValidBlocksAndReportsInvalidOnes) {
  CollectingSink next;
  DiagnosticEngine diags;
  VerifyingSink sink(next, VerifyOptions{3, true}, diags);
  sink.accept(validBlock());
  Block bad = validBlock();
  bad.loc = SourceLocation{1, 9, 2};
  std::get<Linear>(bad.ops[1]).feed = -1.0;
  sink.accept(ir::Block(bad));
  sink.finish();
  EXPECT_EQ(next.blocks.size(), 1u);
  EXPECT_TRUE(next.finished);
  ASSERT_EQ(diags.diagnostics().size(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].code, "NCC9001");
  EXPECT_EQ(diags.diagnostics()[0].location, (SourceLocation{1, 9, 2}));
}

}  // namespace
}  // namespace ncc::ir
