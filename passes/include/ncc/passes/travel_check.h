#pragma once
// Travel check (`ncc check`): every motion, in machine coordinates, against the machine's
// axis travel limits (AxisConfig::min_travel / max_travel): the end point of a rapid or line,
// the whole extent of an arc or helix. What the control alarms on when the block is about to
// move (FANUC OT0500/OT0501 stored stroke limit 1, Sinumerik 10720 software limit switch),
// reported at compile time to spare the run. The rule, the alarm numbers and the text are the
// VM's (ncc/machine/travel.h): one implementation. It sits after the work-to-machine transform.
#include "ncc/ir/ir.h"
#include "ncc/machine/dialect.h"
#include "ncc/machine/machine_config.h"
#include "ncc/machine/travel.h"
#include "ncc/support/diagnostics.h"

namespace ncc::passes {

class TravelCheckPass : public ir::BlockSink {
 public:
  TravelCheckPass(ir::BlockSink& next, const MachineConfig& machine, Dialect dialect,
                  DiagnosticEngine& diags)
      : next_(next), machine_(machine), alarms_(travelAlarmCodes(dialect)), diags_(diags),
        position_(machine.start_position) {}
  void accept(ir::Block&& block) override;
  void finish() override { next_.finish(); }

 private:
  ir::BlockSink& next_;
  const MachineConfig& machine_;
  TravelAlarmCodes alarms_;
  DiagnosticEngine& diags_;
  AxisValues position_;  // where the previous motion ended (an arc's start)
};

}  // namespace ncc::passes
