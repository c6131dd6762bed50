#pragma once
// Evaluation: the stage between the block sources and lowering. It runs the program's macro
// statements (assignments, IF, GOTO, WHILE) and calls (M98, M99, G65, G66/G67), and hands
// lowering blocks whose words hold plain values: `X#1` becomes `X12.5`, a word whose variable
// is vacant is dropped, the call words are gone. Plain blocks (no `#`, no call) pass through
// untouched. docs/middle.md places it among the stages; docs/macro.md gives the semantics.
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ncc/eval/loop_limits.h"
#include "ncc/eval/macro_rules.h"
#include "ncc/eval/program_store.h"
#include "ncc/eval/variables.h"
#include "ncc/frontend/ast.h"
#include "ncc/support/diagnostics.h"

namespace ncc::eval {

struct EvaluatorOptions {
  const MacroRules* rules = nullptr;  // required
  LoopLimits limits;
  // M98 repeats in the high digits of P (M98 P30021) rather than in L.
  RepeatEncoding repeat = RepeatEncoding::LAddress;
  // Whether a block is skipped by the block-skip switch ('/'); a skipped block is not
  // evaluated either.
  std::function<bool(const ast::Block&)> skipped;
  // Whether an address names an axis of the machine (for G66: a block with axis words is a
  // motion block).
  std::function<bool(std::string_view address)> is_axis;
  // The value a G65/G66 argument word passes (`X10` without a point may mean 0.010 mm under
  // the decimal-point parameter); unset: the value as written.
  std::function<double(const ast::Word& word)> argument_value;
  // A value computed for an address: lengths are rounded to the least input increment in force
  // (in the input unit; unset: not rounded) and every address holds at most `address_digits`
  // digits.
  std::function<double()> real_increment;
  int address_digits = 8;
  // G and M codes that call a macro (the machine file's g_code_macros / m_code_macros): the
  // code as written ("M6", "G100") -> the program, an O number ("9020") or a name
  // ("M6_MAKRO"). The block's other words are the arguments, as with G65; inside the macro a
  // code calls nothing and acts as the plain code.
  std::map<std::string, std::string> code_macros;
  // The reader switches language on G290/G291 as written (ReaderOptions::language_switch):
  // a value computed for G that is one of them is refused, since the reader cannot see it.
  bool language_switch = false;
  // Mazak figure rotation (M98 P H I J K L, MacroRules::figure_rotation): the controller turns
  // run k (0 .. L-1) of the subprogram. `begin` when the call starts, with I J K as passed (mm;
  // nullopt where not written), false when the controller refuses (G68 in force); `run` before
  // each later run; `end` when the call returns for good. Unset: such a call is refused.
  struct FigureRotationHooks {
    std::function<bool(const std::array<std::optional<double>, 3>& ijk)> begin;
    std::function<void(int64_t run)> run;
    std::function<void()> end;
  };
  FigureRotationHooks figure_rotation;
  // ADP[x]: least input increments per input unit (1000 with 0.001 mm).
  double adp_scale = 1000.0;
};

// Why the program ended.
enum class ProgramEnd : uint8_t {
  Running,
  EndOfFile,       // the main program's file ended
  EndOfRecord,     // '%' after the main program's first block
  NextProgram,     // the main program reached the O block of another program
  ProgramEndCode,  // M02 / M30 (seen by lowering)
  Alarm,           // an evaluation error or #3000: reported, the run stops
  RunTime,         // the next block needs a value known only when the program runs
                   // (runTimeReason()): the rest is prepared at run time (docs/runtime.md)
};

class Evaluator {
 public:
  Evaluator(EvaluatorOptions options, ProgramStore& store, std::unique_ptr<BlockCursor> main,
            Variables& variables, DiagnosticEngine& diags);
  ~Evaluator();
  Evaluator(const Evaluator&) = delete;
  Evaluator& operator=(const Evaluator&) = delete;

  // The next block for lowering, or nullptr when the program has ended (end()). The block is
  // the evaluator's (or its cursor's): valid until the next call.
  const ast::Block* next();
  // Lowering saw M02/M30 in the block last returned: the program ends there.
  void programEndCode();
  // Whether evaluation may read `block`'s words as a call's arguments rather than as the
  // dialect's addresses: a call word or code macro in it, a G code computed only when it runs,
  // or a modal call (G66/G66.1) in force now or started by a block of `others`; DIN: a call by
  // name or by L (its P is the repeat count). A compile
  // checks the blocks it leaves to run time only where this is false.
  bool mayTakeArguments(const ast::Block& block) const;
  // Whether `block` may start a modal call (G66, G66.1, or a G computed at run time).
  bool mayStartModalCall(const ast::Block& block) const;
  bool modalCallInForce() const;
  // New loop limits from the next jump back on.
  void setLimits(const LoopLimits& limits);
  // The block last returned moved the tool or dwelt: the count of blocks without progress
  // (LoopLimits::max_idle_blocks) starts again.
  void madeProgress();
  // Unreadable blocks (syntax errors) skipped by the readers so far.
  uint64_t rejectedBlocks() const;

  ProgramEnd end() const;
  // Why and where evaluation stopped with ProgramEnd::RunTime.
  const Failure& runTimeReason() const;
  // The main program's cursor (for the text after its end), and the cursor the last block
  // came from.
  BlockCursor& mainCursor();
  const BlockCursor* currentCursor() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ncc::eval
