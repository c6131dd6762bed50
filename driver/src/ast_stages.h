#pragma once
// The stages the driver runs on AST blocks before lowering, by name, in order, and what
// --print-after / --stop-after ask of them (docs/cli.md "Passes"). The IR passes from `lower`
// on are passes::passRegistry(); these come before them in driver::pipelineStages().
//
// Hooking a stage in (the Macro B `evaluate`): set its `built` to true, and in the loop that
// reads blocks call `if (!tap.after("evaluate", block)) continue;` on each block as it leaves
// the stage, before lowering it; when `tap.lowers()` is false nothing is lowered. After the
// last block, call `tap.finish()` before the lowering's finish().
#include <ostream>
#include <span>
#include <string_view>

#include "ncc/frontend/ast.h"
#include "ncc/driver/compile.h"
#include "ncc/passes/pass_printer.h"

namespace ncc::driver {

struct AstStage {
  std::string_view name;
  std::string_view summary;
  bool built;  // false: named (so that the error says so) but not in the pipeline yet
};

std::span<const AstStage> astStages();
const AstStage* findAstStage(std::string_view name);

// Prints the blocks leaving a stage named in --print-after, and, when --stop-after names it,
// writes them as the command's output and lets no block go further.
class AstStageTap {
 public:
  // `printer`: --print-after's output (nullptr when nothing is printed). `stop_out`: where the
  // blocks go when the pipeline stops after an AST stage (as text, like --emit=ir's IR).
  AstStageTap(const PassControl& control, passes::PassPrinter* printer, std::ostream* stop_out)
      : control_(control), printer_(printer), stop_out_(stop_out) {}
  // Call with each block as it leaves `stage`. False: the pipeline stops after `stage`, the
  // block goes no further.
  bool after(std::string_view stage, const ast::Block& block);
  // False when --stop-after names a stage before lowering: nothing is lowered.
  bool lowers() const { return !findAstStage(control_.stop_after); }
  // The end of the blocks: a printed stage that saw none still shows its header.
  void finish();

 private:
  const PassControl& control_;
  passes::PassPrinter* printer_;
  std::ostream* stop_out_;
};

}  // namespace ncc::driver
