#include "ncc/driver/compile.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <streambuf>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <system_error>

#include "absl/strings/str_cat.h"
#include "ncc/backend/bytecode_writer.h"
#include "ncc/bytecode/format.h"
#include "ncc/eval/evaluator.h"
#include "ncc/eval/macro_rules.h"
#include "ncc/eval/variables.h"
#include "ncc/driver/variables_file.h"
#include "ncc/frontend/block_reader.h"
#include "ncc/ir/printer.h"
#include "ncc/passes/dialect_table.h"
#include "ncc/passes/lowering.h"
#include "ncc/passes/pass_manager.h"
#include "ncc/prepare/block_loop.h"
#include "ncc/eval/block_store.h"
#include "block_store_builder.h"
#include "run_budget.h"
#include "ast_stages.h"
#include "source_program_store.h"

namespace ncc::driver {

namespace {

frontend::ReaderOptions readerOptionsFor(Dialect dialect) {
  const passes::LanguageTables tables = passes::languageTables(dialect);
  frontend::ReaderOptions options;
  // FANUC and Mazak end a block at ';' (EOB); the Siemens controls (the dialects with DIN)
  // read ';' as the start of an annotation that runs to the end of the line.
  options.semicolon_ends_block = tables.din == nullptr;
  options.language_switch = tables.din != nullptr;
  options.initial_language = tables.initial;
  return options;
}

ir::AxisNames axisNames(const MachineConfig& machine) {
  ir::AxisNames names;
  for (const AxisConfig& axis : machine.axes) names.push_back(axis.name);
  return names;
}

// The '%' end-of-record mark, alone or after a sequence number (`N194 %`).
bool isEndOfRecord(std::string_view text) {
  size_t i = 0;
  if (i < text.size() && (text[i] == 'N' || text[i] == 'n')) {
    ++i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
  }
  return i < text.size() && text[i] == '%';
}

// A program number starts another program (`O1000`, `:1000`): a subprogram stored after the
// main program.
bool startsProgram(std::string_view text) {
  return !text.empty() && (text[0] == 'O' || text[0] == 'o' || text[0] == ':');
}

// Blanks and ( ) comments only: nothing a control would read.
bool onlyComments(std::string_view text) {
  bool in_comment = false;
  for (char c : text) {
    if (in_comment)
      in_comment = c != ')';
    else if (c == '(')
      in_comment = true;
    else if (c != ' ' && c != '\t')
      return false;
  }
  return true;
}

// The next block's text that is not only comments, or nullopt at the end of the file.
std::optional<frontend::BlockReader::Text> nextNonComment(frontend::BlockReader& reader) {
  std::optional<frontend::BlockReader::Text> next;
  while ((next = reader.nextText()) && onlyComments(next->text)) {
  }
  return next;
}

// The text after the closing '%' is not part of the program (the tape ends there): it is not
// parsed, and text there draws one warning.
void afterEndOfRecord(frontend::BlockReader& reader, DiagnosticEngine& diags) {
  if (std::optional<frontend::BlockReader::Text> after = nextNonComment(reader))
    diags.warning("NCC0020", after->loc,
                  "text after the closing '%' is not part of the program and is ignored");
}

// The text after M02/M30 is never executed (the control stops and rewinds there). It is not
// parsed, so nothing there is an error. Programs stored after the main program (`O` numbers)
// are read only when called; other text draws one warning. A '%' there closes the record.
// DIN text after M30 is read when a REPEAT or a jump reaches its labels (docs/din.md).
void afterProgramEnd(frontend::BlockReader& reader, DiagnosticEngine& diags) {
  if (reader.language() == frontend::Language::Din) return;
  std::optional<frontend::BlockReader::Text> next = nextNonComment(reader);
  if (!next) return;
  if (isEndOfRecord(next->text)) return afterEndOfRecord(reader, diags);
  if (startsProgram(next->text)) return;
  diags.warning("NCC0022", next->loc,
                "text after the end of the program (M02/M30) is never executed and is ignored");
}

// --vars FILE: loads the values kept from the last run into `variables` and returns them;
// nullopt after reporting (NCC0017).
std::optional<std::map<int64_t, double>> loadSavedVariables(Session& session,
                                                            eval::Variables& variables) {
  std::map<int64_t, double> loaded;
  if (!session.variablesFile()) return loaded;
  std::optional<std::map<int64_t, SavedVariable>> saved =
      readVariablesFile(*session.variablesFile(), session.sources(), session.diagnostics());
  if (!saved) return std::nullopt;
  bool ok = true;
  for (const auto& [n, v] : *saved) {
    if (variables.setPersistent(n, v.value, v.where)) {
      loaded[n] = v.value;
      continue;
    }
    session.diagnostics().error(
        "NCC0017", v.where,
        absl::StrCat("#", n, " is not a variable the controller keeps across runs (its "
                     "persistent common variables)"));
    ok = false;
  }
  if (!ok) return std::nullopt;
  return loaded;
}

// Keeps nothing of what is written but answers seeks, for `ncc check`'s bytecode writer (which
// patches its header at the end): check runs every check compile runs, NCC7017 included.
class DiscardingBuffer final : public std::streambuf {
 protected:
  std::streamsize xsputn(const char*, std::streamsize n) override {
    advance(n);
    return n;
  }
  int_type overflow(int_type c) override {
    advance(1);
    return traits_type::not_eof(c);
  }
  pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode) override {
    const off_type base = dir == std::ios_base::beg ? 0 : dir == std::ios_base::cur ? at_ : end_;
    if (base + off < 0) return pos_type(off_type(-1));
    at_ = base + off;
    return pos_type(at_);
  }
  pos_type seekpos(pos_type p, std::ios_base::openmode mode) override {
    return seekoff(off_type(p), std::ios_base::beg, mode);
  }

 private:
  void advance(std::streamsize n) {
    at_ += n;
    end_ = std::max(end_, at_);
  }
  off_type at_ = 0;
  off_type end_ = 0;
};

// Receives the IR and keeps nothing.
struct DiscardingSink : ir::BlockSink {
  void accept(ir::Block&&) override {}
  void finish() override {}
};

// In front of a pipeline: notes in the session's CompileFacts that a lowered block asks for
// cutter compensation.
class FactsTap : public ir::BlockSink {
 public:
  FactsTap(CompileFacts& facts, ir::BlockSink& next) : facts_(facts), next_(next) {}
  void accept(ir::Block&& block) override {
    if (block.comp && (block.comp->side != ir::CutterComp::Side::Off || block.comp->offset_3d))
      facts_.cutter_comp = true;
    next_.accept(std::move(block));
  }
  void finish() override { next_.finish(); }

 private:
  CompileFacts& facts_;
  ir::BlockSink& next_;
};

// The rest of the program goes to the VM's block preparation (docs/runtime.md): an ir::Prepare
// carrying the block store, after the blocks prepared so far.
// `main_end`: where the main program ended, when the compile got there (--defer): the text
// after it is never executed (without it, the builder finds the program's M02/M30 itself).
void prepareAtRunTime(Session& session, SourceProgramStore& store, prepare::BlockLoop& loop,
                      bool deferred, std::optional<eval::ProgramPoint> main_end,
                      std::map<int64_t, double> saved, ir::BlockSink& entry) {
  const eval::MacroRules& rules = eval::macroRules(session.dialect());
  BlockStoreTargets targets;
  targets.code_macros = prepare::codeMacros(session.machine());
  targets.program_number_digits =
      prepare::repeatEncoding(rules, session.machine()) == eval::RepeatEncoding::HighDigitsOfP
          ? rules.program_number_digits
          : 0;
  // The compile stopped before the end: the text after the written M02/M30 draws the warning
  // it would have drawn.
  if (!main_end && (main_end = writtenMainEnd(store, session.mainFile()))) {
    frontend::BlockReader reader(session.sources(), session.mainFile(), session.diagnostics(),
                                 readerOptionsFor(session.dialect()));
    reader.seek(main_end->position);
    reader.next();
    afterProgramEnd(reader, session.diagnostics());
  }
  targets.main_end = main_end;
  eval::BlockStore blocks = buildBlockStore(store, session.mainFile(), targets, session.diagnostics());
  if (session.diagnostics().hasErrors()) return;
  // What the run may reach is checked here as far as it can be without the run's values
  // (addresses and codes the dialect lacks), so that check, compile and run agree; the rest is
  // checked as the blocks run. Never-executed text after the main program's end is not.
  // Under a modal call (G66) any word may be an argument: then nothing is checked here.
  const eval::Evaluator& evaluator = loop.evaluator();
  bool modal_call = evaluator.modalCallInForce();
  for (const eval::StoredFile& file : blocks.files)
    for (const eval::StoredBlock& b : file.blocks) modal_call |= evaluator.mayStartModalCall(b.block);
  // DIN: a word whose address a DEF or PROC declares assigns that variable (`E=7` after
  // `PROC FILL(VAR REAL E)`), which only the run knows: such blocks are left to it.
  std::unordered_set<std::string> declared;
  for (const eval::StoredFile& file : blocks.files)
    for (const eval::StoredBlock& b : file.blocks)
      for (const ast::Statement& st : b.block.statements)
        if ((st.kind == ast::Statement::Kind::Define || st.kind == ast::Statement::Kind::Parameter) &&
            st.target.text)
          declared.insert(*st.target.text);
  const auto assignsVariable = [&](const ast::Block& block) {
    if (declared.empty() || block.language != frontend::Language::Din) return false;
    for (const ast::Word& w : block.words)
      if (declared.count(std::string(w.address.view()))) return true;
    return false;
  };
  for (const eval::StoredFile& file : blocks.files)
    for (const eval::StoredBlock& b : file.blocks)
      if (!modal_call && !evaluator.mayTakeArguments(b.block) && !assignsVariable(b.block) &&
          !(main_end && file.id == main_end->file && main_end->position < b.position))
        loop.lowering().checkStatically(b.block);
  if (session.diagnostics().hasErrors()) return;
  blocks.ahead_blocks = deferred ? 0 : loop.steps();
  blocks.limits = session.loopLimits();
  blocks.saved_variables = std::move(saved);
  ir::Prepare prepare;
  prepare.ahead_blocks = blocks.ahead_blocks;
  prepare.files = static_cast<uint32_t>(blocks.files.size());
  for (const eval::StoredFile& f : blocks.files) prepare.blocks += f.blocks.size();
  prepare.store = std::make_shared<const std::vector<uint8_t>>(eval::encodeBlockStore(blocks));
  ir::Block block;
  block.loc = deferred ? SourceLocation{session.mainFile(), 1, 1} : loop.runTimeReason().loc;
  block.ops.push_back(std::move(prepare));
  session.compileFacts().prepared_at_run_time = true;
  entry.accept(std::move(block));
}

// Reads blocks through the evaluator (macro statements, calls) and lowers them until the end
// of the program: M02/M30, or a '%' after the program's first block (the end of the record).
// What follows is never executed; it is not parsed either, and draws a warning at most.
// From a block that needs a value known only when the program runs (or from the start, with
// --defer) the VM prepares the blocks: the compiler writes the block store for it.
// `budget` is the run's bounds in front of the final sink: the compile stops where the run
// would (run_budget.h).
void lowerProgram(Session& session, ir::BlockSink& entry, AstStageTap& tap,
                  const RunBudgetSink& budget) {
  DiagnosticEngine& diags = session.diagnostics();
  const eval::MacroRules& rules = eval::macroRules(session.dialect());
  SourceProgramStore store(session.sources(), diags, session.programDir(),
                           std::vector<std::string>(rules.program_file_names.begin(),
                                                    rules.program_file_names.end()),
                           readerOptionsFor(session.dialect()));
  prepare::Settings settings;
  settings.dialect = session.dialect();
  settings.machine = &session.machine();
  settings.program_dir = session.programDir();
  settings.limits = session.loopLimits();
  // --defer: the whole program is still evaluated here, for its diagnostics and the programs
  // it calls, but its IR goes nowhere: the VM prepares every block. It still passes the
  // passes, whose alarms (a corner that does not fit, docs/semantics.md) are then reported
  // here as they are without --defer.
  DiscardingSink discard;
  const bool deferred = session.defer();
  std::optional<passes::PassManager> checks;  // built for --defer only
  std::optional<RunBudgetSink> deferred_budget;
  if (deferred) {
    deferred_budget.emplace(session.machine(), session.bounds(), discard);
    passes::PipelineOptions check_options;
    check_options.axis_count = session.machine().axisCount();
    check_options.dialect = session.dialect();
    check_options.verify = false;
    check_options.compensate = session.compensate();
    checks.emplace(check_options, diags, *deferred_budget);
  }
  const RunBudgetSink& bounds = deferred ? *deferred_budget : budget;
  FactsTap checked(session.compileFacts(), deferred ? checks->entry() : entry);
  prepare::BlockLoop loop(settings, store, session.mainFile(), diags, checked);
  // After on_write: the loaded values reach the VM too, so a run ends with every kept
  // variable, written by the program or not (and --vars saves them all back).
  std::optional<std::map<int64_t, double>> saved = loadSavedVariables(session, loop.variables());
  if (!saved) {
    if (deferred) entry.finish();
    loop.finish();
    return;
  }
  loop.on_block = [&](const ast::Block& block) {
    if (session.blockObserver()) session.blockObserver()(block.loc);
    // Lowered even when the pipeline stops after evaluation: the evaluator reads the state
    // lowering keeps (positions, modal codes, offsets); the IR then goes nowhere.
    tap.after("evaluate", block);
  };
  prepare::Step step;
  while ((step = loop.step()) == prepare::Step::Block && !bounds.exceeded()) {
  }
  tap.finish();
  if (const std::optional<RunBudgetSink::Exceeded>& passed = bounds.exceeded();
      passed && session.boundAction() == BoundAction::Report)
    diags.error(passed->code, passed->loc, passed->message);
  const eval::Evaluator& evaluator = loop.evaluator();
  if (step == prepare::Step::RunTime && !deferred)
    diags.report(Severity::Note, "NCC0023", loop.runTimeReason().loc,
                 absl::StrCat("the program is prepared while it runs from here: ",
                              loop.runTimeReason().message));
  // The text after the main program's end, when the program ended in the main file's reader.
  std::optional<eval::ProgramPoint> main_end;
  if (step == prepare::Step::End && &loop.evaluator().mainCursor() == evaluator.currentCursor()) {
    if (evaluator.end() == eval::ProgramEnd::ProgramEndCode)
      main_end = loop.evaluator().mainCursor().lastPoint();
    frontend::BlockReader& main_reader = SourceProgramStore::readerOf(loop.evaluator().mainCursor());
    if (evaluator.end() == eval::ProgramEnd::EndOfRecord) afterEndOfRecord(main_reader, diags);
    if (evaluator.end() == eval::ProgramEnd::ProgramEndCode) afterProgramEnd(main_reader, diags);
  }
  if ((step == prepare::Step::RunTime || deferred) && !diags.hasErrors())
    prepareAtRunTime(session, store, loop, deferred, main_end, std::move(*saved), entry);
  if (deferred && step == prepare::Step::RunTime) {
    // Where the compile stops for a value known at run time, the checking passes drop what
    // they hold, as the pipeline does at its PREPARE block (the VM prepares it again).
    ir::Block stop;
    stop.loc = loop.runTimeReason().loc;
    stop.ops.push_back(ir::Prepare{});
    checks->entry().accept(std::move(stop));
  }
  if (deferred) entry.finish();
  loop.finish();
}


// The pipeline of `which` from lowering to `sink`, shaped by `control` (names checked by
// checkPassControl); `printer` receives what --print-after asks for.
bool compileWith(Session& session, ir::BlockSink& sink, Pipeline which,
                 const PassControl& control = {}, passes::PassPrinter* printer = nullptr,
                 std::ostream* stop_out = nullptr) {
  AstStageTap tap(control, printer, stop_out);
  // Stopped after evaluation (--stop-after=evaluate): lowering still runs for the state the
  // evaluator reads, and its IR goes nowhere.
  const bool lowers = tap.lowers();
  DiscardingSink discard;
  passes::PipelineOptions options;
  options.axis_count = session.machine().axisCount();
  options.dialect = session.dialect();
  options.compensate = session.compensate();
  session.compileFacts() = {};
  if (lowers) {
    if (which == Pipeline::Check) options.travel_limits = &session.machine();
    options.verify_each = control.verify_each;
    options.print_after = control.print_after;
    options.printer = printer;
    options.stop_after = control.stop_after;
  }
  RunBudgetSink budget(session.machine(), session.bounds(), lowers ? sink : discard);
  passes::PassManager pipeline(options, session.diagnostics(), budget);
  lowerProgram(session, pipeline.entry(), tap, budget);
  return !session.diagnostics().hasErrors();
}
}  // namespace

bool compileToSink(Session& session, ir::BlockSink& sink) {
  return compileWith(session, sink, Pipeline::Compile);
}

bool check(Session& session, const PassControl& control, std::ostream* print_out) {
  // Every pass runs, and the backend into nothing, so every diagnostic of a compile appears
  // (NCC7017: a value beyond the bytecode's bounds), and motion targets are checked against the
  // machine's travel limits.
  DiscardingBuffer nothing;
  std::ostream out(&nothing);
  backend::BytecodeWriter writer(out, session.machine(), session.dialect(), session.sources(),
                                 &session.diagnostics());
  DiscardingSink discard;  // --stop-after: the IR may not have reached machine space
  std::optional<passes::PassPrinter> printer;
  if (print_out) printer.emplace(*print_out, axisNames(session.machine()));
  return compileWith(session, control.stop_after.empty() ? static_cast<ir::BlockSink&>(writer) : discard,
                     Pipeline::Check, control, printer ? &*printer : nullptr);
}

bool emitAst(Session& session, std::ostream& out) {
  frontend::BlockReader reader(session.sources(), session.mainFile(), session.diagnostics(),
                               readerOptionsFor(session.dialect()));
  while (std::optional<ast::Block> block = reader.next()) out << frontend::printBlock(*block) << '\n';
  return !session.diagnostics().hasErrors();
}

bool emitIr(Session& session, std::ostream& out, const PassControl& control) {
  if (control.print_after.empty()) {
    ir::PrintingSink printer(out, axisNames(session.machine()));
    return compileWith(session, printer, Pipeline::Compile, control, nullptr, &out);
  }
  // The output is what the taps print; the IR leaving the last pass is not written again.
  passes::PassPrinter printer(out, axisNames(session.machine()));
  DiscardingSink discard;
  return compileWith(session, discard, Pipeline::Compile, control, &printer, &out);
}

bool emitBytecode(Session& session, std::ostream& out, const PassControl& control) {
  backend::BytecodeWriter writer(out, session.machine(), session.dialect(), session.sources(),
                                 &session.diagnostics());
  PassControl verify_only;
  verify_only.verify_each = control.verify_each;
  bool ok = compileWith(session, writer, Pipeline::Compile, verify_only);
  return ok && writer.ok() && !session.diagnostics().hasErrors();
}

}  // namespace ncc::driver
