#pragma once
// Block preparation: the loop that turns a program's blocks into IR, evaluation (macro
// statements, calls) into lowering (modal state, motion). One implementation, run twice: by
// the compiler ahead of time, over the source files, and by the VM while the program runs,
// over the block store the compiler wrote (docs/runtime.md). What the two differ in is given:
// where blocks come from (eval::ProgramStore), where the IR goes (ir::BlockSink) and whether
// the running machine can be asked (Settings::run_time).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "ncc/eval/evaluator.h"
#include "ncc/eval/program_store.h"
#include "ncc/eval/variables.h"
#include "ncc/ir/ir.h"
#include "ncc/machine/dialect.h"
#include "ncc/machine/machine_config.h"
#include "ncc/passes/lowering.h"
#include "ncc/passes/run_time_state.h"
#include "ncc/support/diagnostics.h"

namespace ncc::prepare {

struct Settings {
  Dialect dialect = Dialect::FanucM;
  const MachineConfig* machine = nullptr;  // required
  std::filesystem::path program_dir;
  // What ends an endless loop that neither moves nor dwells (NCC2419).
  eval::LoopLimits limits;
  // The running machine (the VM); null in the compiler.
  const passes::RunTimeState* run_time = nullptr;
};

// The common variables in force: the dialect's, or the set the machine file names
// (common_variables, Mazak's A-D).
std::vector<eval::VariableRange> commonVariables(const eval::MacroRules& rules,
                                                 const MachineConfig& machine);

// The machine file's code macros (g_code_macros, m_code_macros): the code as the evaluator
// names it ("M6", "G100"; the machine file reader checked the keys: `M06` is M6) -> program.
std::map<std::string, std::string> codeMacros(const MachineConfig& machine);

// M98's repeat count: the dialect's, unless the machine takes 8-digit program numbers
// (Sinumerik MD20734 bit 6: the count is then in L).
eval::RepeatEncoding repeatEncoding(const eval::MacroRules& rules, const MachineConfig& machine);

// What one step did.
enum class Step : uint8_t {
  Block,    // a block was evaluated and lowered (its IR, if any, went to the sink)
  End,      // the program ended (M02/M30, end of file or record, an alarm: see the diagnostics)
  RunTime,  // the next block needs a value known only when the program runs (runTimeReason());
            // nothing of it was emitted. Only without Settings::run_time.
};

class BlockLoop {
 public:
  // Reads the program from the start of `main_file` in `store`; IR goes to `out`.
  BlockLoop(const Settings& settings, eval::ProgramStore& store, uint32_t main_file,
            DiagnosticEngine& diags, ir::BlockSink& out);
  ~BlockLoop();
  BlockLoop(const BlockLoop&) = delete;
  BlockLoop& operator=(const BlockLoop&) = delete;

  // Before the first step: the program's variables (saved values of --vars are loaded here).
  eval::Variables& variables();
  // Called with each block evaluation hands to lowering, before it is lowered.
  std::function<void(const ast::Block&)> on_block;

  // Evaluates and lowers the next block.
  Step step();
  // Blocks evaluated and lowered so far (Step::Block results): the compiler's count is where
  // the VM's preparation takes over (it replays that many, emitting nothing).
  uint64_t steps() const { return steps_; }
  // Why and where, after Step::RunTime.
  const eval::Failure& runTimeReason() const { return run_time_reason_; }
  // Flushes the variable writes and finishes lowering (which finishes the sink).
  void finish();

  eval::Evaluator& evaluator() { return *evaluator_; }
  passes::Lowering& lowering() { return lowering_; }

 private:
  void flushWrites();

  // Between lowering and `out`: notes a block that moves or dwells (the evaluator's count of
  // blocks without progress starts again, eval::LoopLimits).
  struct ProgressTap final : ir::BlockSink {
    explicit ProgressTap(ir::BlockSink& n) : next(n) {}
    void accept(ir::Block&& block) override;
    void finish() override { next.finish(); }
    bool advances(const ir::Operation& op);
    ir::BlockSink& next;
    bool moved = false;
    AxisValues at{};  // the last move's target
  };

  ProgressTap progress_;
  passes::Lowering lowering_;
  eval::Variables variables_;
  std::unique_ptr<eval::Evaluator> evaluator_;
  // Variable writes reach the IR before the block that follows them, one block with each
  // variable's last value (the VM holds #1 to #9999: the system variables above are the
  // model's own).
  std::vector<ir::SetVariable> writes_;
  absl::flat_hash_map<uint32_t, size_t> write_index_;  // variable -> its entry in writes_
  SourceLocation writes_loc_;
  uint64_t unreadable_ = 0;
  uint64_t steps_ = 0;
  eval::Failure run_time_reason_;
};

}  // namespace ncc::prepare
