// The block loop of evaluation: reads the current program's blocks, keeps to the program's
// bounds, runs statements and turns word expressions into values. Calls and returns are in
// calls.cpp.
#include <cmath>
#include <utility>

#include "absl/strings/str_cat.h"
#include "evaluator_impl.h"
#include "ncc/eval/address_value.h"
#include "number_format.h"

namespace ncc::eval {

namespace {

// #3000 (alarm with message) and #3006 (stop with message): the same numbers in FANUC, Mazak
// and Sinumerik ISO mode.
constexpr int64_t kUserAlarmVariable = 3000;
constexpr int64_t kUserStopVariable = 3006;

// The message of #3000/#3006: the block's comment (`#3000=25 (TOOL BROKEN)`).
std::string messageOf(const ast::Block& block) {
  return block.comments.empty() ? std::string() : block.comments.front();
}

}  // namespace

bool isLiteral(const ast::Expr& e) {
  if (e.kind == ast::Expr::Kind::Number) return true;
  return e.kind == ast::Expr::Kind::Unary && e.args.size() == 1 &&
         e.args[0].kind == ast::Expr::Kind::Number &&
         (e.op == ast::Op::Minus || e.op == ast::Op::Plus);
}

double literalValue(const ast::Expr& e) {
  if (e.kind == ast::Expr::Kind::Number) return e.number;
  return e.op == ast::Op::Minus ? -e.args[0].number : e.args[0].number;
}

bool before(const ProgramPoint& a, const ProgramPoint& b) {
  if (a.position.offset != b.position.offset) return a.position.offset < b.position.offset;
  return a.position.column < b.position.column;
}

Evaluator::Impl::Impl(EvaluatorOptions o, ProgramStore& s, std::unique_ptr<BlockCursor> main,
                      Variables& v, DiagnosticEngine& d)
    : options(std::move(o)), rules(*options.rules), store(s), variables(v), diags(d) {
  Frame f;
  f.begin = ProgramPoint{main->file(), {}};
  f.cursor = std::move(main);
  f.is_main = true;
  frames.push_back(std::move(f));
}

void Evaluator::Impl::fail(const Failure& failure) {
  if (failure.error == EvalError::RunTimeValue) {
    run_time_reason = failure;
    end = ProgramEnd::RunTime;
    return;
  }
  std::string code = failure.error == EvalError::UserAlarm ? absl::StrCat(failure.user_code)
                                                           : std::string(rules.alarm(failure.error));
  diags.error(code, failure.loc, failure.message);
  end = ProgramEnd::Alarm;
}

void Evaluator::Impl::fail(EvalError error, SourceLocation loc, std::string message) {
  fail(Failure{error, loc, std::move(message), 0});
}

ExpressionContext Evaluator::Impl::expressionContext(bool din, int enclosing_brackets) {
  ExpressionContext context{rules, variables};
  context.enclosing_brackets = enclosing_brackets;
  context.adp_scale = options.adp_scale;
  context.din = din;
  return context;
}

std::optional<Value> Evaluator::Impl::value(const ast::Expr& e, int enclosing_brackets, bool din) {
  Failure failure;
  std::optional<Value> v = evaluate(e, expressionContext(din, enclosing_brackets), failure);
  if (!v) fail(failure);
  return v;
}

std::optional<int64_t> Evaluator::Impl::integerOf(const ast::Expr& e, SourceLocation loc,
                                                  const char* what) {
  std::optional<Value> v = value(e);
  if (!v) return std::nullopt;
  if (v->vacant || !(std::abs(v->number) < 1e15) || v->number != std::floor(v->number)) {
    fail(EvalError::AddressValue, loc,
         absl::StrCat(what, " must be an integer, not ",
                      v->vacant ? std::string("vacant") : absl::StrCat(v->number)));
    return std::nullopt;
  }
  return static_cast<int64_t>(v->number);
}

bool Evaluator::Impl::countBackJump(SourceLocation loc) {
  // After an error the program has failed: running its loop again would only repeat what the
  // first turn reported (and a loop whose moves failed may never end).
  if (diags.hasErrors()) {
    end = ProgramEnd::Alarm;
    return false;
  }
  const LoopLimits& limits = options.limits;
  ++back_jumps;
  if (limits.max_back_jumps > 0 && back_jumps > limits.max_back_jumps) {
    fail(EvalError::StepLimit, loc,
         absl::StrCat("the program jumped back ", limits.max_back_jumps,
                      " times here: an endless loop? (the limit is --max-back-jumps)"));
    return false;
  }
  if (limits.max_idle_blocks > 0 && blocks_read - progress_at > limits.max_idle_blocks) {
    fail(EvalError::StepLimit, loc,
         absl::StrCat("the program ran ", blocks_read - progress_at,
                      " blocks without a move or a dwell and jumps back here: an endless loop? "
                      "(the limit is --max-idle-blocks)"));
    return false;
  }
  return true;
}

ProgramPoint Evaluator::Impl::programEnd(Frame& frame) {
  if (!frame.end) frame.end = store.programEnd(frame.begin);
  return *frame.end;
}

bool Evaluator::Impl::beyondEnd(Frame& frame, const ProgramPoint& at) {
  // Only a program that starts with its O block has a next program to run into.
  if (!frame.header_at_begin || !frame.end) return false;
  return !before(at, *frame.end);
}

bool Evaluator::Impl::jumpToSequence(Frame& frame, int64_t n, const ProgramPoint& from,
                                     SequenceSearch order, SourceLocation loc,
                                     EvalError missing) {
  const ProgramPoint end_point = programEnd(frame);
  std::optional<ProgramPoint> target =
      store.findSequence(n, from, order, frame.begin, end_point);
  if (!target) {
    fail(missing, loc, absl::StrCat("no block starts with N", n, " in this program"));
    return false;
  }
  if (!before(from, *target) && !countBackJump(loc)) return false;
  frame.cursor->seek(*target);
  return true;
}

void Evaluator::Impl::programFinished() {
  Frame& f = frames.back();
  if (f.is_main) {
    if (end == ProgramEnd::Running) end = ProgramEnd::EndOfFile;
    return;
  }
  // A subprogram that ends without M99 returns (the end of its file or the next program).
  Pending p;
  p.kind = Pending::Kind::Return;
  p.loc = f.call_loc;
  perform(p);
}

const ast::Block* Evaluator::Impl::next() {
  while (end == ProgramEnd::Running) {
    if (!pending.empty()) {
      Pending p = std::move(pending.front());
      pending.pop_front();
      perform(p);
      continue;
    }
    Frame& f = frames.back();
    if (f.section_step) {  // the last block of a repeated section ran (din.cpp)
      f.section_step = false;
      if (!sectionStep(f)) return nullptr;
      continue;
    }
    const ast::Block* block = f.cursor->next();
    if (!block) {
      programFinished();
      continue;
    }
    ++blocks_read;
    const ProgramPoint at = f.cursor->lastPoint();
    if ((!f.sections.empty() || f.section_return) && sectionBoundary(f, at)) continue;
    if (block->program_number) {
      if (f.header_at_begin && at == f.begin) continue;  // the program's own O block
      if (f.is_main && !f.seen_content) {
        // The main program's O block: the program runs to the next O block.
        f.begin = at;
        f.header_at_begin = true;
        continue;
      }
      // The next program in the file: this one has ended.
      if (f.is_main) {
        end = ProgramEnd::NextProgram;
        return nullptr;
      }
      programFinished();
      continue;
    }
    if (beyondEnd(f, at)) {
      programFinished();
      continue;
    }
    if (block->percent) {
      if (f.is_main && f.seen_content) {
        end = ProgramEnd::EndOfRecord;
        return nullptr;
      }
      if (!f.is_main && f.seen_content) {
        programFinished();
        continue;
      }
      continue;  // the tape's opening '%' (a subprogram file's `%_N_NAME_SPF`)
    }
    if (!f.seen_content && !block->empty()) {
      f.seen_content = true;
      f.first_content = at;
      // A DIN subprogram given arguments binds them in its first block, its PROC.
      if (f.din_call && !f.din_arguments.empty() &&
          (block->statements.empty() || block->statements[0].kind != ast::Statement::Kind::Proc)) {
        fail(EvalError::TooManyArguments, f.call_loc,
             "too many parameters: the subprogram has no PROC with parameters");
        return nullptr;
      }
    }
    if (options.skipped && options.skipped(*block)) return block;  // lowering skips it
    if (plain(*block)) return block;  // most blocks: nothing to evaluate, nothing to move
    const ast::Block* out = block->language == frontend::Language::Din
                                ? evaluateDin(*block, at)
                                : evaluateBlock(*block, at);
    if (end != ProgramEnd::Running) return nullptr;
    if (!out) continue;
    modalCallAfter(*out, at);
    return out;
  }
  return nullptr;
}

bool Evaluator::Impl::plain(const ast::Block& block) const {
  // DIN text has none of the ISO calls (M98/M99/G65/G66, code macros); its words name a
  // variable when DEF declared one by the address (din.cpp).
  if (block.language == frontend::Language::Din) return modal_calls.empty() && dinPlain(block);
  if (!block.statements.empty() || !modal_calls.empty()) return false;
  for (const ast::Word& w : block.words)
    if (!isLiteral(w.value) || isCallWord(w)) return false;
  return true;
}

ast::Block& Evaluator::Impl::startEvaluated(const ast::Block& block) {
  ast::Block& out = evaluated.emplace();
  out.loc = block.loc;
  out.skip_level = block.skip_level;
  out.sequence = block.sequence;
  out.program_number = block.program_number;
  out.percent = block.percent;
  out.language = block.language;
  out.comments = block.comments;
  return out;
}

bool Evaluator::Impl::wordValue(const ast::Word& w, ast::Block& out, bool din) {
  if (isLiteral(w.value)) {
    out.words.push_back(w);
    return true;
  }
  // DIN `X=IC(5)` / `X=AC(..)`: the value inside, kept marked for lowering (block_words.cpp).
  const bool distance = din && w.value.kind == ast::Expr::Kind::Call && w.value.args.size() == 1 &&
                        (w.value.op == ast::Op::Ic || w.value.op == ast::Op::Ac);
  std::optional<Value> v = value(distance ? w.value.args[0] : w.value, 0, din);
  if (!v) return false;
  const AddressShape shape = addressShape(w.address);
  AddressLimits limits;
  limits.digits = options.address_digits;
  if (shape == AddressShape::Real && options.real_increment)
    limits.increment = options.real_increment();
  Failure failure;
  std::optional<AddressValue> a = addressValue(*v, shape, rules, limits, w.loc, failure);
  if (!a) {
    fail(failure);
    return false;
  }
  if (a->dropped) return true;  // an address whose variable is vacant is not there at all
  if (options.language_switch && w.address.is('G') &&
      (a->value == frontend::kSwitchToDin || a->value == frontend::kSwitchToIso)) {
    fail(EvalError::AddressValue, w.loc,
         absl::StrCat("G", formatNumber(a->value),
                      " must be written as a number: the language it switches to is read "
                      "from the program text, before any value is computed"));
    return false;
  }
  // A computed value is a number in the input unit, as if written with its decimal point;
  // an integer address takes it as the integer it is. Built in place: this runs for every
  // computed word of every loop turn.
  ast::Word& computed = out.words.emplace_back();
  computed.address = w.address;
  computed.loc = w.loc;
  ast::Expr* number = &computed.value;
  if (distance) {
    number->kind = ast::Expr::Kind::Call;
    number->op = w.value.op;
    number->loc = w.value.loc;
    number = &number->args.emplace_back();
  }
  if (a->value < 0) {
    number->kind = ast::Expr::Kind::Unary;
    number->op = ast::Op::Minus;
    number->loc = w.value.loc;
    number = &number->args.emplace_back();
  }
  number->kind = ast::Expr::Kind::Number;
  number->number = std::abs(a->value);
  number->has_point = shape == AddressShape::Real;
  number->loc = w.value.loc;
  return true;
}

const ast::Block* Evaluator::Impl::evaluateBlock(const ast::Block& block, const ProgramPoint& at) {
  Frame& frame = frames.back();

  // Statements read the values from before the block (Mazak §13-6: `#1=200 #2=#1+200` adds to
  // the old #1); their writes take effect together at the end of the block.
  struct Write {
    int64_t number;
    Value value;
    SourceLocation loc;
  };
  std::vector<Write> writes;
  enum class Flow : uint8_t { None, Goto, LoopBack, SkipLoop } flow = Flow::None;
  int64_t goto_target = 0;
  SourceLocation flow_loc = block.loc;
  int loop_id = 0;

  auto assign = [&](const ast::Statement& st) -> bool {
    Failure failure;
    ExpressionContext context{rules, variables};
    std::optional<int64_t> number = assignmentTarget(st.target, context, failure);
    if (!number) {
      fail(failure);
      return false;
    }
    std::optional<Value> v = value(st.value);
    if (!v) return false;
    writes.push_back({*number, *v, st.loc});
    return true;
  };

  for (const ast::Statement& st : block.statements) {
    using K = ast::Statement::Kind;
    switch (st.kind) {
      case K::Assign:
        if (!assign(st)) return nullptr;
        break;
      case K::IfThen: {
        std::optional<Value> c = value(st.value, 1);
        if (!c) return nullptr;
        if (isTrue(*c) && st.then_assign && !assign(*st.then_assign)) return nullptr;
        break;
      }
      case K::IfGoto:
      case K::Goto: {
        if (st.kind == K::IfGoto) {
          std::optional<Value> c = value(st.value, 1);
          if (!c) return nullptr;
          if (!isTrue(*c)) break;
        }
        std::optional<int64_t> n = integerOf(st.target, st.loc, "the GOTO target");
        if (!n) return nullptr;
        if (*n < 0 || *n > 99999) {
          fail(EvalError::GotoTarget, st.loc, absl::StrCat("GOTO ", *n, ": no such sequence number"));
          return nullptr;
        }
        flow = Flow::Goto;
        goto_target = *n;
        flow_loc = st.loc;
        break;
      }
      case K::While: {
        if (st.loop_id < 1 || st.loop_id > rules.max_do_id) {
          fail(EvalError::DoNumber, st.loc,
               absl::StrCat("DO ", st.loop_id, ": loop numbers are 1 to ", rules.max_do_id));
          return nullptr;
        }
        std::optional<Value> c = value(st.value, 1);
        if (!c) return nullptr;
        loop_id = st.loop_id;
        flow_loc = st.loc;
        // Coming back to this WHILE (END or a GOTO) re-enters the same loop.
        for (size_t i = 0; i < frame.loops.size(); ++i)
          if (frame.loops[i].at == at) {
            frame.loops.resize(i);
            break;
          }
        if (isTrue(*c)) {
          if (static_cast<int>(frame.loops.size()) >= rules.max_do_nesting) {
            fail(EvalError::DoNesting, st.loc,
                 absl::StrCat("WHILE ... DO nested more than ", rules.max_do_nesting, " deep"));
            return nullptr;
          }
          frame.loops.push_back({st.loop_id, at});
        } else {
          flow = Flow::SkipLoop;
        }
        break;
      }
      case K::End: {
        // A loop left by a jump stays on the stack until an END of an outer loop meets it.
        size_t i = frame.loops.size();
        while (i > 0 && frame.loops[i - 1].id != st.loop_id) --i;
        if (i == 0) {
          fail(EvalError::EndWithoutDo, st.loc,
               absl::StrCat("END ", st.loop_id, " without WHILE ... DO ", st.loop_id));
          return nullptr;
        }
        frame.loops.resize(i);
        flow = Flow::LoopBack;
        flow_loc = st.loc;
        loop_id = st.loop_id;
        break;
      }
      case K::Define:
      case K::Label:
      case K::Call:
      case K::If:
      case K::Else:
      case K::EndIf:
      case K::EndWhile:
      case K::For:
      case K::EndFor:
      case K::Repeat:
      case K::Until:
      case K::Loop:
      case K::EndLoop:
      case K::Case:
      case K::CaseBranch:
      case K::Proc:
      case K::Parameter:
      case K::Return:
      case K::RepeatSection:
        // DIN statements: a DIN block goes to evaluateDin (din.cpp); an ISO block never has
        // them (a tree from elsewhere, a damaged store).
        fail(EvalError::NotSupported, st.loc, "a DIN statement in an ISO block");
        return nullptr;
    }
    if (flow != Flow::None) break;  // a jump ends the block
  }

  // The block as lowering gets it, built before anything below reads the cursor again (a
  // skipped loop does: `block` is the cursor's): the words with the values from before the
  // block's assignments, no statements.
  ast::Block& out = startEvaluated(block);
  out.words.reserve(block.words.size());
  for (const ast::Word& w : block.words)
    if (!wordValue(w, out)) return nullptr;

  for (const Write& w : writes) {
    if (w.number == kUserAlarmVariable) {
      if (w.value.vacant) continue;
      const int64_t n = static_cast<int64_t>(w.value.number);
      std::optional<int64_t> code = rules.userAlarmNumber(n);
      if (!code) {
        fail(EvalError::AddressValue, w.loc,
             absl::StrCat("#3000 = ", n, ": the alarm number is out of range"));
        return nullptr;
      }
      std::string message = messageOf(out);
      fail(Failure{EvalError::UserAlarm, w.loc,
                   message.empty() ? absl::StrCat("user alarm #3000 = ", n)
                                   : absl::StrCat("user alarm #3000 = ", n, ": ", message),
                   *code});
      return nullptr;
    }
    if (w.number == kUserStopVariable) {
      // The control stops with the message; the run goes on as after cycle start.
      diags.warning(std::string(rules.alarm(EvalError::UserStop)), w.loc,
                    absl::StrCat("program stop #3006: ",
                                 messageOf(out).empty() ? "(no message)" : messageOf(out)));
      continue;
    }
    Failure failure;
    if (!variables.write(w.number, w.value, w.loc, failure)) {
      fail(failure);
      return nullptr;
    }
  }

  switch (flow) {
    case Flow::None: break;
    case Flow::Goto:
      if (!jumpToSequence(frame, goto_target, at, rules.goto_search, flow_loc,
                          EvalError::GotoTarget))
        return nullptr;
      break;
    case Flow::LoopBack: {
      const Loop& loop = frame.loops.back();
      if (!countBackJump(flow_loc)) return nullptr;
      frame.cursor->seek(loop.at);
      break;
    }
    case Flow::SkipLoop: {
      // Past the matching END: read on without running anything, counting inner loops with the
      // same number.
      int depth = 0;
      while (true) {
        const ast::Block* b = frame.cursor->next();
        ++blocks_read;
        if (!b || b->program_number) {
          fail(EvalError::LoopNotClosed, flow_loc,
               absl::StrCat("WHILE ... DO ", loop_id, " has no END ", loop_id));
          return nullptr;
        }
        bool done = false;
        for (const ast::Statement& st : b->statements) {
          if (st.kind == ast::Statement::Kind::While && st.loop_id == loop_id) ++depth;
          if (st.kind == ast::Statement::Kind::End && st.loop_id == loop_id && depth-- == 0)
            done = true;
        }
        if (done) break;
      }
      break;
    }
  }

  bool consumed = false;
  if (!callWords(out, at, consumed)) return nullptr;
  if (consumed) return nullptr;
  if (out.words.empty() && !out.sequence) return nullptr;
  return &out;
}

// ---- the public class ----

Evaluator::Evaluator(EvaluatorOptions options, ProgramStore& store,
                     std::unique_ptr<BlockCursor> main, Variables& variables,
                     DiagnosticEngine& diags)
    : impl_(std::make_unique<Impl>(std::move(options), store, std::move(main), variables, diags)) {}

Evaluator::~Evaluator() = default;

const ast::Block* Evaluator::next() { return impl_->next(); }

void Evaluator::setLimits(const LoopLimits& limits) { impl_->options.limits = limits; }

void Evaluator::madeProgress() { impl_->progress_at = impl_->blocks_read; }

void Evaluator::programEndCode() {
  if (impl_->end == ProgramEnd::Running) impl_->end = ProgramEnd::ProgramEndCode;
}

uint64_t Evaluator::rejectedBlocks() const {
  uint64_t n = impl_->rejected_closed;
  for (const Frame& f : impl_->frames) n += f.cursor->rejectedBlocks();
  return n;
}

ProgramEnd Evaluator::end() const { return impl_->end; }
const Failure& Evaluator::runTimeReason() const { return impl_->run_time_reason; }

BlockCursor& Evaluator::mainCursor() { return *impl_->frames.front().cursor; }

const BlockCursor* Evaluator::currentCursor() const { return impl_->frames.back().cursor.get(); }

}  // namespace ncc::eval
