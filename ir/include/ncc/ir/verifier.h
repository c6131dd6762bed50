#pragma once
// Checks IR invariants; a violation is a compiler bug, reported as an internal error (NCC9xxx)
// with the block's location rather than crashing or emitting bad bytecode.
#include <string>
#include <vector>

#include "ncc/ir/ir.h"
#include "ncc/support/diagnostics.h"

namespace ncc::ir {

struct VerifyOptions {
  int axis_count = 3;
  bool require_machine_space = false;  // true before the backend
};

// Returns the list of problems (empty = valid).
std::vector<std::string> verify(const Block& block, const VerifyOptions& options);

// A pass-through sink that verifies every block and reports problems to `diags`.
class VerifyingSink : public BlockSink {
 public:
  VerifyingSink(BlockSink& next, VerifyOptions options, DiagnosticEngine& diags)
      : next_(next), options_(options), diags_(diags) {}
  void accept(Block&& block) override;
  void finish() override { next_.finish(); }

 private:
  BlockSink& next_;
  VerifyOptions options_;
  DiagnosticEngine& diags_;
};

}  // namespace ncc::ir
