#pragma once
// Lowering: AST blocks -> canonical IR blocks. This is the modal-state machine of the ISO
// family: it applies the dialect's G-code group table (one-shot vs modal, one code per group
// per block), the decimal-point and increment-system rules, units, G90/G91, feeds, and the
// semantics of motion, dwell, coordinate systems, offsets and reference returns. Targets are
// emitted in the work space with the frame in force (see ir.h).
#include <array>
#include <filesystem>
#include <memory>
#include <optional>

#include "ncc/eval/variables.h"
#include "ncc/frontend/ast.h"
#include "ncc/frontend/language.h"
#include "ncc/ir/ir.h"
#include "ncc/machine/dialect.h"
#include "ncc/machine/machine_config.h"
#include "ncc/passes/run_time_state.h"
#include "ncc/support/diagnostics.h"

namespace ncc::passes {

struct LoweringOptions {
  Dialect dialect = Dialect::FanucM;
  const MachineConfig* machine = nullptr;  // required
  std::filesystem::path program_dir;       // where called subprograms are looked up
  // Set when the VM prepares blocks while the program runs; null in the compiler, where a
  // block that needs a run-time value ends the ahead-of-time preparation (LowerResult).
  const RunTimeState* run_time = nullptr;
};

// What the caller (the block loop) must do after a block.
struct LowerResult {
  bool program_end = false;  // M02 / M30: stop reading
  // The block needs a value known only when the program runs (it moves from where a G31
  // stopped): why. It produced no IR and changed no state; the rest of the program is
  // prepared at run time (docs/runtime.md). Never set with LoweringOptions::run_time.
  std::optional<eval::Failure> needs_run_time;
};

class Lowering {
 public:
  Lowering(LoweringOptions options, DiagnosticEngine& diags, ir::BlockSink& out);
  ~Lowering();

  // Lowers one block; IR blocks go to `out`. Errors are reported with the block's location
  // and the controller's alarm number; the erroneous block produces no IR.
  LowerResult lower(const ast::Block& block);
  // A block the frontend could not read (a syntax error) was skipped: what it would have
  // changed is not known, so every position and modal group is unknown until later blocks
  // determine them again; blocks that depend on them get no diagnostic (docs/semantics.md,
  // Error recovery).
  void blockUnreadable();
  // The controller model's system variables (#2001, #4001, #5001, #5221, ...): views of the
  // state lowering keeps, for the evaluator (passes/src/system_variables.cpp).
  eval::SystemVariables& systemVariables();
  // Macro variables the evaluator wrote since the last block: recorded in the IR (in program
  // order among the moves) so that the VM holds them.
  void variablesWritten(SourceLocation loc, std::vector<ir::SetVariable> writes);
  // Whether the block-skip switch skips `block` ('/', '/n').
  bool skips(const ast::Block& block) const;
  // Reports what makes `block` an error whatever the values and the modal state when it runs:
  // an address or a literal G code the dialect does not have or ncc does not support, a word
  // given twice. For the blocks a compile leaves to run time (docs/runtime.md); false if any.
  bool checkStatically(const ast::Block& block) const;
  // The value of a macro-call argument word as the program means it, in the input unit: a
  // length without a decimal point is in least input increments under decimal_point =
  // "standard" (`X10` = 0.010 mm); other addresses and calculator notation take the number.
  double argumentValue(const ast::Word& word) const;
  // The least input increment of a length in the unit in force (0.001 mm, 0.0001 inch), and
  // the digits an address holds (format_digits).
  double leastIncrement() const;
  // Mazak figure rotation (M98 P H I J K L, §13-7; eval::EvaluatorOptions::FigureRotationHooks):
  // the call starts where the tool is, about that point + I J K (mm, in the plane); false when
  // G68 is in force (alarm 850). Run k >= 1 starts from the call's start point again and is
  // turned by k times the angle the first run swept about the centre; at the end the
  // programmed point is where the tool is.
  bool figureRotationBegin(const std::array<std::optional<double>, 3>& ijk);
  void figureRotationRun(int64_t run);
  void figureRotationEnd();
  int addressDigits() const;
  // End of input: finishes the sink. (None of fanuc-m, mazak-m, siemens-iso-m requires
  // M02/M30: Mazak memory operation implies M30, and the Siemens examples end without it.)
  void finish();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace ncc::passes
