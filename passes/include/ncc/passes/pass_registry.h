#pragma once
// The named passes, in pipeline order (docs/semantics.md "Passes"). A new pass (canned
// cycles, cutter compensation, ...) is one entry in the table of pass_registry.cpp, at its
// place in the order, plus its own file; the pass manager, --print-after, --stop-after and
// --verify-each then know it by its name.
#include <memory>
#include <span>
#include <string_view>

#include "ncc/ir/ir.h"
#include "ncc/passes/pipeline_options.h"
#include "ncc/support/diagnostics.h"

namespace ncc::passes {

struct PassInfo {
  std::string_view name;     // as on the command line: lower-case words joined by '-'
  std::string_view summary;  // one line, for docs and messages
  // True when a pipeline built with `options` runs the pass.
  bool (*runs)(const PipelineOptions& options);
  // The stage in front of `next`. nullptr for `lower`, the producer: the driver feeds the
  // pipeline's entry with the IR it makes from AST blocks.
  std::unique_ptr<ir::BlockSink> (*create)(ir::BlockSink& next, const PipelineOptions& options,
                                           DiagnosticEngine& diags);
  // The IR leaving this pass is in machine space (so is the IR after every later pass): the
  // verifier requires it from here on.
  bool machine_space_after;
};

// Every pass, in pipeline order.
std::span<const PassInfo> passRegistry();
// nullptr for an unknown name.
const PassInfo* findPass(std::string_view name);

}  // namespace ncc::passes
