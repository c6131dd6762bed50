#include "ncc/passes/pass_manager.h"

#include <algorithm>
#include <string>

#include "ncc/ir/verifier.h"

namespace ncc::passes {

namespace {

// Prints each block as it leaves `pass` (--print-after) and forwards it unchanged. It sits
// before the pass's verifier, so a block the verifier rejects is still shown.
class PrintTap : public ir::BlockSink {
 public:
  PrintTap(ir::BlockSink& next, std::string_view pass, PassPrinter& printer)
      : next_(next), pass_(pass), printer_(printer) {}
  void accept(ir::Block&& block) override {
    printer_.print(pass_, block);
    next_.accept(std::move(block));
  }
  void finish() override {
    printer_.finish(pass_);
    next_.finish();
  }

 private:
  ir::BlockSink& next_;
  std::string_view pass_;
  PassPrinter& printer_;
};

// The IR verifier after `pass`: a violation is a compiler bug, reported as NCC9001 naming the
// pass that produced the block; the block goes no further.
class VerifyAfter : public ir::BlockSink {
 public:
  VerifyAfter(ir::BlockSink& next, std::string_view pass, ir::VerifyOptions options,
              DiagnosticEngine& diags)
      : next_(next), pass_(pass), options_(options), diags_(diags) {}
  void accept(ir::Block&& block) override {
    std::vector<std::string> problems = ir::verify(block, options_);
    if (problems.empty()) {
      next_.accept(std::move(block));
      return;
    }
    for (const std::string& p : problems)
      diags_.error("NCC9001", block.loc,
                   "internal error: invalid IR after pass " + std::string(pass_) + ": " + p);
  }
  void finish() override { next_.finish(); }

 private:
  ir::BlockSink& next_;
  std::string_view pass_;
  ir::VerifyOptions options_;
  DiagnosticEngine& diags_;
};

}  // namespace

std::vector<std::string_view> PassManager::passNames(const PipelineOptions& options) {
  std::vector<std::string_view> names;
  for (const PassInfo& pass : passRegistry())
    if (pass.runs(options)) names.push_back(pass.name);
  return names;
}

// Built from the final sink backwards so that each stage knows its successor.
PassManager::PassManager(PipelineOptions options, DiagnosticEngine& diags,
                         ir::BlockSink& final_sink) {
  std::vector<const PassInfo*> passes;
  for (const PassInfo& pass : passRegistry()) {
    if (!pass.runs(options)) continue;
    passes.push_back(&pass);
    if (pass.name == options.stop_after) break;
  }
  // Whether the IR leaving passes[i] is in machine space.
  std::vector<bool> machine_space(passes.size());
  for (size_t i = 0; i < passes.size(); ++i)
    machine_space[i] = passes[i]->machine_space_after || (i > 0 && machine_space[i - 1]);
  auto verifier = [&](ir::BlockSink& next, size_t i) -> ir::BlockSink* {
    ir::VerifyOptions verify;
    verify.axis_count = options.axis_count;
    verify.require_machine_space = machine_space[i];
    stages_.push_back(std::make_unique<VerifyAfter>(next, passes[i]->name, verify, diags));
    return stages_.back().get();
  };
  auto printed = [&](std::string_view name) {
    return std::find(options.print_after.begin(), options.print_after.end(), name) !=
           options.print_after.end();
  };

  ir::BlockSink* next = &final_sink;
  if (options.verify && !options.verify_each && !passes.empty())
    next = verifier(*next, passes.size() - 1);
  for (size_t i = passes.size(); i-- > 0;) {
    if (options.verify_each) next = verifier(*next, i);
    if (options.printer && printed(passes[i]->name)) {
      stages_.push_back(std::make_unique<PrintTap>(*next, passes[i]->name, *options.printer));
      next = stages_.back().get();
    }
    if (passes[i]->create) {
      stages_.push_back(passes[i]->create(*next, options, diags));
      next = stages_.back().get();
    }
  }
  entry_ = next;
}

}  // namespace ncc::passes
