#include "ncc/passes/pass_manager.h"

#include "ncc/passes/coordinate_transform.h"
#include "ncc/passes/travel_check.h"

namespace ncc::passes {

// Built from the final sink backwards so that each stage knows its successor:
// entry -> WorkToMachine -> TravelCheck (check only) -> VerifyingSink -> final sink.
PassManager::PassManager(PipelineOptions options, DiagnosticEngine& diags,
                         ir::BlockSink& final_sink) {
  ir::BlockSink* next = &final_sink;
  if (options.verify) {
    ir::VerifyOptions verify;
    verify.axis_count = options.axis_count;
    verify.require_machine_space = options.to_machine_space;
    stages_.push_back(std::make_unique<ir::VerifyingSink>(*next, verify, diags));
    next = stages_.back().get();
  }
  if (options.to_machine_space && options.travel_limits) {
    stages_.push_back(std::make_unique<TravelCheckPass>(*next, *options.travel_limits,
                                                        options.dialect, diags));
    next = stages_.back().get();
  }
  if (options.to_machine_space) {
    stages_.push_back(std::make_unique<WorkToMachinePass>(*next, options.axis_count));
    next = stages_.back().get();
  }
  entry_ = next;
}

}  // namespace ncc::passes
