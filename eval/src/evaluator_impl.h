#pragma once
// The evaluator's state, shared by its files:
//   evaluator.cpp  the block loop: program boundaries, statements (assignments, IF, GOTO,
//                  WHILE/END), word values, the step limit
//   calls.cpp      M98/M99, G65, G66/G66.1/G67: frames, arguments, repeats, returns
//   din.cpp        DIN blocks: DEF, assignments in written order, R parameters, jumps,
//                  control structures, calls by name and PROC
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ncc/eval/evaluator.h"
#include "ncc/eval/expression.h"

namespace ncc::eval {

// An open WHILE ... DO m: where its WHILE block starts.
struct Loop {
  int id = 0;
  ProgramPoint at;
};

// A DIN variable a FOR counts with or a VAR argument names: R r, or a variable and its indices.
struct VariableRef {
  int64_t r = -1;
  std::string name;
  std::vector<int64_t> indices;
};

// An argument of a DIN call by name: its value (none when omitted, `F(1,,3)`), and the
// variable it names when it is one (a VAR parameter writes it back on return).
struct DinArgument {
  std::optional<Datum> value;
  bool character = false;  // a CHAR: its code, or its one-character text for a STRING parameter
  std::optional<VariableRef> ref;
  SourceLocation loc;
};

// An open DIN control structure (din.cpp): IF, WHILE, FOR, REPEAT or LOOP, and where its
// opening block starts.
struct Structure {
  ast::Statement::Kind kind = ast::Statement::Kind::If;
  ProgramPoint at;
  // FOR: the counter and the end value, taken once when the loop starts.
  double end = 0;
  VariableRef counter;
};

// A DIN program section being repeated (REPEAT/REPEATB, din.cpp): from `start` to `end`
// (included; none: up to the REPEAT block itself), `left` more times, then on after `repeat_at`.
struct Section {
  ProgramPoint start;
  std::optional<ProgramPoint> end;
  ProgramPoint repeat_at;
  int64_t left = 0;
  SourceLocation loc;  // the REPEAT, where a repeat counts as a jump back
};

// One program being run: the main program, or a subprogram / macro called by the frame below.
struct Frame {
  std::unique_ptr<BlockCursor> cursor;
  ProgramPoint begin;            // the program's first block (its O block, or the file start)
  std::optional<ProgramPoint> end;  // where the next program starts (known once asked)
  bool header_at_begin = false;  // the block at `begin` is the program's own O block
  ProgramPoint call_point;       // the caller's call block (M99 P searches from there)
  SourceLocation call_loc;
  int64_t repeats_left = 0;      // runs still to come after this one (M98 L, G65 L)
  bool macro = false;            // a macro call: it opened a level of locals
  bool figure_rotation = false;  // Mazak M98 I J K L: each repeat is turned (FigureRotationHooks)
  int64_t run = 0;               // the run being made (0: the first)
  bool is_main = false;
  std::string code;              // a code macro's code ("M6"): it acts as the plain code inside
  bool seen_content = false;
  ProgramPoint first_content;     // the program's first block with content (its PROC)
  std::vector<Loop> loops;
  std::vector<Structure> structures;
  std::optional<ProgramPoint> for_resume;  // ENDFOR went back to this FOR: run its body again
  // A DIN subprogram called by name: its own scope of variables, the call's arguments (bound
  // by its PROC), and the VAR parameters to write back to the caller's variables on return.
  bool din_call = false;
  std::vector<DinArgument> din_arguments;
  std::vector<std::pair<std::string, VariableRef>> by_reference;
  // DIN program sections being repeated, innermost last; `section_step` when the block just
  // run ended the innermost; `section_return`: the REPEAT block to pass over when it is done.
  std::vector<Section> sections;
  bool section_step = false;
  std::optional<ProgramPoint> section_return;
};

// A modal macro call in force (G66: after each motion block; G66.1: every block).
struct ModalCall {
  int64_t program = 0;
  Variables::Locals arguments;
  int64_t repeats = 1;
  bool every_block = false;
  size_t depth = 0;  // frames open when it was given: blocks deeper do not call it
  SourceLocation loc;
  // DIN MCALL: the subprogram by name and its arguments, taken when MCALL was given.
  bool din = false;
  std::string name;
  std::vector<DinArgument> din_arguments;
};

// A call or return to perform before the next block is read (the block's other words were
// lowered first: `X100. M98 P100` moves, then calls).
struct Pending {
  enum class Kind : uint8_t { Call, Return } kind = Kind::Call;
  int64_t program = 0;
  bool local = false;               // M98 H without P: a sequence of the caller's program
  std::string name;                 // a program called by name (code macros)
  std::string code;                 // the code that called it (code macros)
  std::optional<int64_t> sequence;  // M98 H (call) / M99 P (return)
  int64_t repeats = 1;
  bool macro = false;
  Variables::Locals arguments;
  std::optional<std::array<std::optional<double>, 3>> figure;  // M98 I J K with L > 1
  // DIN: a call by name (`name`) with its arguments, or a return (M17, RET).
  bool din = false;
  std::vector<DinArgument> din_arguments;
  SourceLocation loc;
  ProgramPoint at;  // the call or return block
};

struct Evaluator::Impl {
  Impl(EvaluatorOptions o, ProgramStore& s, std::unique_ptr<BlockCursor> main, Variables& v,
       DiagnosticEngine& d);

  EvaluatorOptions options;
  const MacroRules& rules;
  ProgramStore& store;
  Variables& variables;
  DiagnosticEngine& diags;
  std::vector<Frame> frames;
  std::vector<ModalCall> modal_calls;
  std::deque<Pending> pending;
  ProgramEnd end = ProgramEnd::Running;
  Failure run_time_reason;  // with ProgramEnd::RunTime
  uint64_t back_jumps = 0;
  uint64_t blocks_read = 0;    // from every cursor
  uint64_t progress_at = 0;    // blocks_read at the last block that moved or dwelt
  uint64_t rejected_closed = 0;  // unreadable blocks of cursors already closed

  // ---- evaluator.cpp ----
  const ast::Block* next();
  // Evaluates a block with statements, expressions or call words; nullopt when nothing is
  // left for lowering (a pure statement block, a G65 call).
  // A block without statements, expressions or calls, and no modal call in force: it goes to
  // lowering as read.
  bool plain(const ast::Block& block) const;
  // A block that is not plain, evaluated into `evaluated` (next() lets plain ones through);
  // nullptr when nothing of it goes on (a jump, a call, an error).
  const ast::Block* evaluateBlock(const ast::Block& block, const ProgramPoint& at);
  std::optional<ast::Block> evaluated;  // the last block evaluateBlock made
  // `evaluated` started anew with `block`'s number, skip level, marks and comments.
  ast::Block& startEvaluated(const ast::Block& block);
  // Reports the failure with the dialect's alarm number and stops the program.
  void fail(const Failure& failure);
  void fail(EvalError error, SourceLocation loc, std::string message);
  // `enclosing_brackets`: 1 for the bracketed condition of IF / WHILE (the parser keeps its
  // contents only).
  std::optional<Value> value(const ast::Expr& e, int enclosing_brackets = 0, bool din = false);
  // What an expression of this program is evaluated with: the rules, the variables, ADP's
  // scale, the language; `enclosing_brackets` as ExpressionContext says.
  ExpressionContext expressionContext(bool din, int enclosing_brackets = 0);
  // A word's value into `out`: as written, or computed and checked for its address (dropped
  // when vacant); false after failing.
  bool wordValue(const ast::Word& w, ast::Block& out, bool din = false);
  // The integer a word or target designates (GOTO n, P, L, H); nullopt after failing.
  std::optional<int64_t> integerOf(const ast::Expr& e, SourceLocation loc, const char* what);
  // Jumps to N n of the current program (GOTO, M99 P in the caller).
  bool jumpToSequence(Frame& frame, int64_t n, const ProgramPoint& from, SequenceSearch order,
                      SourceLocation loc, EvalError missing);
  // Counts a jump back; false (after failing) past the limit.
  bool countBackJump(SourceLocation loc);
  ProgramPoint programEnd(Frame& frame);
  bool beyondEnd(Frame& frame, const ProgramPoint& at);
  // The current program ended without M99 (end of file, next O block, '%').
  void programFinished();

  // ---- din.cpp ----
  // A DIN block that goes to lowering as read: words of numbers, none naming a variable.
  bool dinPlain(const ast::Block& block) const;
  // A DIN block's statements and words, left to right; nullptr when nothing of it goes on.
  const ast::Block* evaluateDin(const ast::Block& block, const ProgramPoint& at);
  // A DIN jump (GOTOF, GOTOB, GOTO, GOTOC) to a label or block number of the current program.
  bool dinJump(const ast::Statement& jump, const ProgramPoint& at);
  // A control structure's keyword (IF, ELSE, ENDIF, WHILE, FOR, REPEAT, LOOP, CASE, and their
  // ends) in `block`; false after failing.
  bool dinControl(const ast::Block& block, const ast::Statement& st, const ProgramPoint& at);
  bool openStructure(ast::Statement::Kind kind, const ProgramPoint& at, SourceLocation loc);
  // The innermost open structure of `kind` (those opened inside it were left by a jump and
  // are dropped); nullptr after failing (`st` closes nothing).
  Structure* closeStructure(ast::Statement::Kind kind, const ast::Statement& st);
  // Reads on without running anything to the block of `ends` that closes `st`'s level (an
  // ELSE or ENDIF for an IF); the kind found, nullopt after failing.
  std::optional<ast::Statement::Kind> skipStructure(const ast::Statement& st,
                                                    std::initializer_list<ast::Statement::Kind> ends);
  // The variable `e` names (an R parameter, a variable or its element); nullopt after failing.
  std::optional<VariableRef> variableRef(const ast::Expr& e);
  std::optional<Value> read(const VariableRef& ref, SourceLocation loc);
  bool write(const VariableRef& ref, const Datum& v, SourceLocation loc);
  // The value of `e` for a variable of type `type` (None: not known yet, a PROC's argument): a
  // text for a STRING or where `e` is a string, else a number.
  std::optional<Datum> datum(const ast::Expr& e, ast::DataType type);
  // The arguments of a DIN call by name, evaluated (a VAR parameter's variable kept).
  bool dinArguments(const ast::Statement& st, std::vector<DinArgument>& out);
  // MCALL NAME(...) (`st`: the call made modal, null for MCALL L10) or MCALL alone (an empty
  // name: cancels).
  bool dinModalCall(const std::string& name, const ast::Statement* st, SourceLocation loc);
  // L10: the subprogram's name, the digits as written ("L10", "L0010").
  std::optional<std::string> subprogramNumbered(const ast::Word& w);
  // `A[i]=SET(...)`, `REP(...)`: the values of the array `ref` from its element on.
  bool fillArray(const VariableRef& ref, const ast::Expr& e);
  // MSG("text"): the text as a note at the block (din.cpp).
  bool message(const ast::Statement& st);
  static constexpr uint64_t kMaxMessages = 100;  // notes of MSG in one run; then one that says so
  uint64_t messages_shown = 0;
  // REPEAT START [END] P=n, REPEATB LABEL P=n: opens the section and goes to its start.
  bool dinRepeatSection(const ast::Statement& st, const ProgramPoint& at);
  // Before the block at `at` runs: true when it is not to run (the REPEAT that ended its
  // section, or was passed back over); marks the last block of a section (section_step).
  bool sectionBoundary(Frame& f, const ProgramPoint& at);
  // After the last block of the innermost section: its start again, or on after its REPEAT.
  bool sectionStep(Frame& f);
  // A jump or loop to `target`: no section step after this block, and the sections it leaves
  // are closed.
  void jumpWithinSections(Frame& f, const ProgramPoint& target);
  // A call by name: a built-in not built yet is refused; otherwise the call is scheduled with
  // its arguments evaluated (the subprogram is looked for in the program folder when made).
  // A subprogram call by name; a block command (TRANS ...) becomes a word of `out`.
  bool dinCall(const ast::Statement& st, const ProgramPoint& at, ast::Block& out);
  // SETAL(n): a cycle or user alarm; the program stops, or goes on after a warning.
  bool setAlarm(const ast::Statement& st);
  // `L10`: a call of the subprogram L10 (the digits as written).
  bool dinCallNumbered(const ast::Word& w, const ProgramPoint& at);
  // A DIN call of `name`, run as often as the block's P says (`P3`, repeat_word); nullopt
  // after reporting a bad count.
  std::optional<Pending> dinPending(std::string name, SourceLocation loc, const ProgramPoint& at);
  const ast::Word* repeat_word = nullptr;  // the DIN block's P of a call, while evaluating it
  // PROC: binds the call's arguments to the parameters in a new scope of variables.
  bool dinProc(const ast::Block& block, const ast::Statement& st, const ProgramPoint& at);
  // M17 or RET: returns after the block (in the main program: its end).
  void dinReturn(SourceLocation loc, const ProgramPoint& at);

  // ---- calls.cpp ----
  // Whether a literal word is a call word (M98, M99, G65, G66, G66.1, G67) or a code macro:
  // such a block needs evaluation even when every word is a number.
  bool isCallWord(const ast::Word& w) const;
  // Call words of an evaluated block (M98, M99, G65, G66, G66.1, G67): removes them and
  // schedules the call or return; false after failing. `consumed`: the whole block was a
  // call (G65: every other word is an argument).
  bool callWords(ast::Block& block, const ProgramPoint& at, bool& consumed);
  // A G or M code the machine file makes a macro call (code_macros): consumes the block.
  bool codeMacro(ast::Block& block, const ProgramPoint& at, bool& consumed);
  // After a block went to lowering: a G66 call follows a motion block.
  void modalCallAfter(const ast::Block& block, const ProgramPoint& at);
  bool perform(const Pending& p);
  bool call(const Pending& p);
  bool ret(const Pending& p);
  // Arguments of G65/G66 (specification I and II) into a fresh set of locals.
  std::optional<Variables::Locals> arguments(const std::vector<ast::Word>& words,
                                             bool every_block);
  void closeFrame();
};

// True when `e` is a number as written (`10.`, `-5`): no variable, no operator.
bool isLiteral(const ast::Expr& e);
// Value of a literal word (isLiteral).
double literalValue(const ast::Expr& e);
// Whether `a` starts before `b` in the same file.
bool before(const ProgramPoint& a, const ProgramPoint& b);

}  // namespace ncc::eval
