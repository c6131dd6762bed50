#pragma once
// Travel check (`ncc check`): every motion target, in machine coordinates, against the
// machine's axis travel limits (AxisConfig::min_travel / max_travel). A target outside them
// is what the control alarms on when the block is about to move (FANUC OT0500/OT0501 stored
// stroke limit 1, Sinumerik 10720 software limit switch); reporting it at compile time
// spares the run. It sits after the work-to-machine transform; targets only (an arc's bulge
// between its ends is not checked).
#include <string_view>

#include "ncc/ir/ir.h"
#include "ncc/machine/dialect.h"
#include "ncc/machine/machine_config.h"
#include "ncc/support/diagnostics.h"

namespace ncc::passes {

// The alarm numbers of a dialect for a target beyond the positive or the negative limit
// (data: kTravelAlarms in travel_check.cpp).
struct TravelAlarms {
  std::string_view positive;
  std::string_view negative;
};
TravelAlarms travelAlarms(Dialect dialect);

class TravelCheckPass : public ir::BlockSink {
 public:
  TravelCheckPass(ir::BlockSink& next, const MachineConfig& machine, Dialect dialect,
                  DiagnosticEngine& diags)
      : next_(next), machine_(machine), alarms_(travelAlarms(dialect)), diags_(diags) {}
  void accept(ir::Block block) override;
  void finish() override { next_.finish(); }

 private:
  // Reports the first axis of `to` beyond its limits (one diagnostic per block).
  void check(const AxisValues& to, SourceLocation where);

  ir::BlockSink& next_;
  const MachineConfig& machine_;
  TravelAlarms alarms_;
  DiagnosticEngine& diags_;
};

}  // namespace ncc::passes
