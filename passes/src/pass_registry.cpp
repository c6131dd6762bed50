#include "ncc/passes/pass_registry.h"

#include "compensation/compensation_pass.h"
#include "cycle_expansion.h"
#include "ncc/passes/coordinate_transform.h"
#include "ncc/passes/travel_check.h"
#include "corners.h"
#include "transform_pass.h"

namespace ncc::passes {

namespace {

bool always(const PipelineOptions&) { return true; }
bool inMachineSpace(const PipelineOptions& o) { return o.to_machine_space; }
bool checksTravel(const PipelineOptions& o) { return o.to_machine_space && o.travel_limits; }

std::unique_ptr<ir::BlockSink> cycles(ir::BlockSink& next, const PipelineOptions& o,
                                      DiagnosticEngine&) {
  return std::make_unique<CycleExpansionPass>(next, o.axis_count);
}

std::unique_ptr<ir::BlockSink> workToMachine(ir::BlockSink& next, const PipelineOptions& o,
                                             DiagnosticEngine&) {
  return std::make_unique<WorkToMachinePass>(next, o.axis_count);
}

std::unique_ptr<ir::BlockSink> corners(ir::BlockSink& next, const PipelineOptions& o,
                                       DiagnosticEngine& diags) {
  return std::make_unique<CornersPass>(next, o.dialect, diags);
}

std::unique_ptr<ir::BlockSink> transform(ir::BlockSink& next, const PipelineOptions& o,
                                          DiagnosticEngine& diags) {
  return std::make_unique<TransformPass>(next, o.dialect, diags);
}

std::unique_ptr<ir::BlockSink> compensation(ir::BlockSink& next, const PipelineOptions& o,
                                            DiagnosticEngine& diags) {
  return std::make_unique<CompensationPass>(next, o.dialect, diags, o.compensate);
}

std::unique_ptr<ir::BlockSink> travelCheck(ir::BlockSink& next, const PipelineOptions& o,
                                           DiagnosticEngine& diags) {
  return std::make_unique<TravelCheckPass>(next, *o.travel_limits, o.dialect, diags);
}

// The order is the pipeline's (DESIGN.md, Passes): transforms in work space come before
// work-to-machine, checks on machine coordinates after it.
constexpr PassInfo kPasses[] = {
    {"lower", "AST blocks to canonical IR blocks (modal state, units, work-space targets)",
     always, nullptr, false},
    {"cycles", "canned hole cycles (G73-G89) to their rapid, feed, dwell and spindle operations",
     always, cycles, false},
    {"corners", ",C / ,R: inserts the chamfer line or rounding arc between two moves", always,
     corners, false},
    {"transform", "G68 rotation, G51 scaling, G51.1 mirror, G92.5: maps targets and arc centres",
     always, transform, false},
    {"compensation", "G41/G42 cutter radius compensation: the tool centre's path around each corner",
     always, compensation, false},
    {"work-to-machine", "adds each block's frame: work offset, shifts, tool length", inMachineSpace,
     workToMachine, true},
    {"travel-check", "motion targets against the travel limits (ncc check only)", checksTravel,
     travelCheck, true},
};

}  // namespace

std::span<const PassInfo> passRegistry() { return kPasses; }

const PassInfo* findPass(std::string_view name) {
  for (const PassInfo& pass : kPasses)
    if (pass.name == name) return &pass;
  return nullptr;
}

}  // namespace ncc::passes
