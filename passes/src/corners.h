#pragma once
// Corner chamfer and rounding (`,C` / `,R`, docs/semantics.md "Corner chamfer and rounding"):
// a look-ahead pass in work space. A block whose move carries a corner request (lowering puts
// it on ir::Block::corner) is held until the next block arrives; then the chamfer line or the
// rounding arc is inserted after its move, the move is shortened to where the insert starts,
// and the next move starts where it ends (its programmed end point is kept). At most one block
// is held; a block without a request passes straight through when nothing is held.
//
// Blocks made only of variable writes (`#100 = 1`) between the two moves are held with it, in
// order. A PREPARE block (the rest is prepared while the program runs) drops what is held: the
// VM's block preparation replays the same blocks through the same pass and emits them.
#include <optional>
#include <vector>

#include "ncc/ir/ir.h"
#include "ncc/machine/dialect.h"
#include "ncc/passes/dialect_table.h"
#include "ncc/support/diagnostics.h"

namespace ncc::passes {

class CornersPass : public ir::BlockSink {
 public:
  CornersPass(ir::BlockSink& next, Dialect dialect, DiagnosticEngine& diags);
  void accept(ir::Block&& block) override;
  void finish() override;

 private:
  // Takes a block that may carry a request: holds it, or passes it on.
  void take(ir::Block&& block);
  // Inserts the held block's corner before `next` (whose move then starts at `next_start`);
  // false after reporting an alarm.
  bool insertCorner(ir::Block& held, ir::Block& next, AxisValues& next_start);
  void fail(Alarm a, SourceLocation loc, std::string message);
  void release();

  ir::BlockSink& next_;
  const DialectTable* table_;  // null: a dialect lowering does not handle (nothing to do)
  DiagnosticEngine& diags_;
  std::optional<ir::Block> held_;
  std::vector<ir::Block> writes_;  // variable-write blocks after the held one
};

}  // namespace ncc::passes
