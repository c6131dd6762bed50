#pragma once
// The `transform` pass (docs/transforms.md): applies the map of programmed points the lowering
// put on each block (ir::Block::transform: G68 rotation, G51 scaling, G51.1 mirror, Mazak
// figure rotation and G92.5) to its work-space targets and arc centres, then clears it. It runs
// after `cycles` and `corners` (a cycle's or a corner's moves are turned and scaled with the
// rest, as the manuals state) and before `work-to-machine`. Exact for lines and arcs: an arc
// keeps its circle, moves to the plane its image lies in and reverses under a mirror; an arc
// whose image is no circle in a principal plane (unequal scaling in its plane, a 3-D rotation
// that tilts it) is refused with a diagnostic, never approximated.
#include <optional>

#include "ncc/ir/ir.h"
#include "ncc/machine/dialect.h"
#include "ncc/passes/dialect_table.h"
#include "ncc/support/diagnostics.h"

namespace ncc::passes {

class TransformPass : public ir::BlockSink {
 public:
  TransformPass(ir::BlockSink& next, Dialect dialect, DiagnosticEngine& diags);
  void accept(ir::Block&& block) override;
  void finish() override { next_.finish(); }

 private:
  bool mapArc(const ir::Block& block, const ir::Affine& map, ir::Arc& arc);

  ir::BlockSink& next_;
  const DialectTable* table_;
  DiagnosticEngine& diags_;
  std::optional<AxisValues> last_;  // where the tool ends, machine coordinates (unknown at first)
};

}  // namespace ncc::passes
