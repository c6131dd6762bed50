#pragma once
// Builds the named pipeline of streaming passes between lowering and the final sink (the
// backend, an IR printer, ...): the passes of pass_registry.h that the options run, in their
// order, up to `stop_after`. Each stage is a BlockSink that forwards to the next; the manager
// owns them. Around each pass it adds what the options ask for, in this order:
//   pass -> print tap (--print-after) -> verifier (--verify-each) -> next pass
// and without verify_each one verifier before the final sink.
#include <memory>
#include <string_view>
#include <vector>

#include "ncc/ir/ir.h"
#include "ncc/passes/pass_printer.h"
#include "ncc/passes/pass_registry.h"
#include "ncc/passes/pipeline_options.h"
#include "ncc/support/diagnostics.h"

namespace ncc::passes {

class PassManager {
 public:
  PassManager(PipelineOptions options, DiagnosticEngine& diags, ir::BlockSink& final_sink);
  // The entry of the chain: lowering writes here.
  ir::BlockSink& entry() { return *entry_; }

  // The passes a pipeline built with `options` runs, in order, ignoring stop_after
  // (`lower` first).
  static std::vector<std::string_view> passNames(const PipelineOptions& options);

 private:
  std::vector<std::unique_ptr<ir::BlockSink>> stages_;
  ir::BlockSink* entry_ = nullptr;
};

}  // namespace ncc::passes
