#pragma once
// Builds the chain of streaming passes between lowering and the final sink (the backend, an
// IR printer, ...). Each stage is a BlockSink that forwards to the next; the manager owns
// them and wires them in the documented order (DESIGN.md, Passes).
#include <memory>
#include <vector>

#include "ncc/ir/ir.h"
#include "ncc/ir/verifier.h"
#include "ncc/machine/dialect.h"
#include "ncc/machine/machine_config.h"
#include "ncc/support/diagnostics.h"

namespace ncc::passes {

struct PipelineOptions {
  int axis_count = 3;
  bool to_machine_space = true;  // false: stop in work space (debug printing)
  bool verify = true;            // run the IR verifier before the final sink
  // Check motion targets against this machine's travel limits (`ncc check`; needs
  // to_machine_space), reporting with the dialect's alarm numbers.
  const MachineConfig* travel_limits = nullptr;
  Dialect dialect = Dialect::FanucM;
};

class PassManager {
 public:
  PassManager(PipelineOptions options, DiagnosticEngine& diags, ir::BlockSink& final_sink);
  // The entry of the chain: lowering writes here.
  ir::BlockSink& entry() { return *entry_; }

 private:
  std::vector<std::unique_ptr<ir::BlockSink>> stages_;
  ir::BlockSink* entry_ = nullptr;
};

}  // namespace ncc::passes
