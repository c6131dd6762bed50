// DIN blocks (docs/din.md): a block's assignments, DEFs, words and jump run left to right as
// written, each seeing what the ones before it wrote (Fundamentals: a block's instructions
// execute in their order). Words go to lowering with their values; a word whose address DEF
// declared as a variable (`COUNT=COUNT+1`) is an assignment instead.
#include <algorithm>

#include "absl/container/inlined_vector.h"
#include "absl/strings/str_cat.h"
#include "evaluator_impl.h"

namespace ncc::eval {

namespace {

SequenceSearch searchOf(ast::Jump jump, const MacroRules& rules) {
  switch (jump) {
    case ast::Jump::Sequence: return rules.goto_search;
    case ast::Jump::Forward: return SequenceSearch::Forward;
    case ast::Jump::Backward: return SequenceSearch::Backward;
    case ast::Jump::Both:
    case ast::Jump::BothQuiet: return SequenceSearch::ForwardThenFromStart;
  }
  return rules.goto_search;
}

const char* jumpName(ast::Jump jump) {
  switch (jump) {
    case ast::Jump::Forward: return "GOTOF";
    case ast::Jump::Backward: return "GOTOB";
    case ast::Jump::BothQuiet: return "GOTOC";
    default: return "GOTO";
  }
}

// SET(...) or REP(...): the values of an array (fillArray).
bool isArrayValues(const ast::Expr& e) {
  return e.kind == ast::Expr::Kind::Call && (e.op == ast::Op::Set || e.op == ast::Op::Rep);
}

// M17: the end of a subprogram (Fundamentals, subprogram technique), as RET.
bool isReturnWord(const ast::Word& w) {
  return w.address.is('M') && isLiteral(w.value) && literalValue(w.value) == 17;
}

// DIN `V=7`: the word assigns V when a DEF or PROC declared it in the running program.
bool namesVariable(const ast::Word& w, const NamedVariables& named) {
  return named.any() && named.find(w.address.view());
}

// `L10`: a call of the subprogram L10 (Fundamentals, "subprogram call"), unless a DEF or PROC
// made L a variable of the program.
bool isSubprogramWord(const ast::Word& w, const NamedVariables& named) {
  return w.address.is('L') && !namesVariable(w, named);
}

struct BuiltIn;
const BuiltIn* builtIn(std::string_view name);

}  // namespace

bool Evaluator::Impl::dinPlain(const ast::Block& block) const {
  if (!block.statements.empty()) return false;
  const NamedVariables& named = variables.named();
  for (const ast::Word& w : block.words)
    if (!isLiteral(w.value) || isReturnWord(w) || isSubprogramWord(w, named) ||
        namesVariable(w, named))
      return false;
  return true;
}

const ast::Block* Evaluator::Impl::evaluateDin(const ast::Block& block, const ProgramPoint& at) {
  ast::Block& out = startEvaluated(block);

  // Words and statements in the order they were written.
  struct Item {
    uint32_t column;
    const ast::Word* word;
    const ast::Statement* statement;
  };
  absl::InlinedVector<Item, 16> items;
  for (const ast::Word& w : block.words) items.push_back({w.loc.column, &w, nullptr});
  for (const ast::Statement& st : block.statements) items.push_back({st.loc.column, nullptr, &st});
  std::stable_sort(items.begin(), items.end(),
                   [](const Item& a, const Item& b) { return a.column < b.column; });

  NamedVariables& named = variables.named();
  const ExpressionContext context = expressionContext(true);
  Failure failure;
  const auto failed = [&] {
    fail(failure);
    return nullptr;
  };

  // `MYKONTUR P3`, `L10 P3`: P is the call's repeat count, not a word of the block.
  repeat_word = nullptr;
  bool calls = false;
  for (const ast::Statement& st : block.statements)
    calls = calls || (st.kind == ast::Statement::Kind::Call && st.target.text && !builtIn(*st.target.text));
  for (const ast::Word& w : block.words) calls = calls || isSubprogramWord(w, named);
  if (calls)
    for (const ast::Word& w : block.words)
      if (w.address.is('P') && !namesVariable(w, named)) repeat_word = &w;

  // MCALL NAME(...): the call after it in the block is made modal, not now.
  const ast::Statement* mcall = nullptr;
  const ast::Statement* modal_target = nullptr;
  const ast::Word* modal_l = nullptr;  // MCALL L10
  for (const Item& item : items) {
    if (mcall && !modal_target && !modal_l && item.word && isSubprogramWord(*item.word, named)) {
      modal_l = item.word;
      continue;
    }
    if (!item.statement || item.statement->kind != ast::Statement::Kind::Call) continue;
    if (!mcall && item.statement->target.text && *item.statement->target.text == "MCALL")
      mcall = item.statement;
    else if (mcall && !modal_target && !modal_l)
      modal_target = item.statement;
  }

  const ast::Statement* jump = nullptr;
  const ast::Statement* structure = nullptr;
  for (const Item& item : items) {
    if (item.word) {
      const ast::Word& w = *item.word;
      if (isReturnWord(w)) {
        dinReturn(w.loc, at);
        continue;
      }
      if (&w == repeat_word) continue;  // read by the call
      if (&w == modal_l) continue;  // made modal by the MCALL before it
      if (isSubprogramWord(w, named)) {
        if (!dinCallNumbered(w, at)) return nullptr;
        continue;
      }
      if (namesVariable(w, named) && isArrayValues(w.value)) {
        if (!fillArray(VariableRef{-1, std::string(w.address.view()), {}}, w.value)) return nullptr;
        continue;
      }
      if (namesVariable(w, named)) {
        std::optional<Datum> v = datum(w.value, named.find(w.address.view())->type);
        if (!v) return nullptr;
        if (!named.write(w.address.view(), {}, *v, w.loc, failure)) return failed();
        continue;
      }
      if (w.address.is('T') && w.value.kind == ast::Expr::Kind::String) {
        // T="name" selects a tool by its name under tool management (Fundamentals, tool
        // selection); ncc's tools are numbers (machine file).
        fail(EvalError::NotSupported, w.loc,
             absl::StrCat("T=\"", *w.value.text,
                          "\": tools by name (tool management) are not supported yet; T n selects tool n"));
        return nullptr;
      }
      if (!wordValue(w, out, true)) return nullptr;
      continue;
    }
    const ast::Statement& st = *item.statement;
    using K = ast::Statement::Kind;
    switch (st.kind) {
      case K::Label:
        break;
      case K::Define: {
        std::optional<std::vector<int64_t>> dims = indicesOf(st.target.args, context, failure);
        if (!dims) return failed();
        const bool array_values = isArrayValues(st.value);
        std::optional<Datum> initial;
        if (st.value.kind != ast::Expr::Kind::Vacant && !array_values) {
          initial = datum(st.value, st.type);
          if (!initial) return nullptr;
        }
        const std::string_view name = st.target.text ? *st.target.text : std::string_view();
        if (!named.define(name, st.type, st.length, *dims, initial, st.loc, failure))
          return failed();
        if (array_values && !fillArray(VariableRef{-1, std::string(name), {}}, st.value)) return nullptr;
        break;
      }
      case K::Assign: {
        if (isArrayValues(st.value)) {
          std::optional<VariableRef> ref = variableRef(st.target);
          if (!ref || !fillArray(*ref, st.value)) return nullptr;
          break;
        }
        const NamedVariables::Variable* target =
            st.target.kind == ast::Expr::Kind::Name && st.target.text ? named.find(*st.target.text)
                                                                      : nullptr;
        std::optional<Datum> v = datum(st.value, target ? target->type : ast::DataType::Real);
        if (!v) return nullptr;
        const bool variable = (st.target.kind == ast::Expr::Kind::RParam && !st.target.args.empty()) ||
                              (st.target.kind == ast::Expr::Kind::Name && st.target.text);
        if (!variable) {
          fail(EvalError::VariableNumber, st.target.loc, "the left side is not a variable");
          return nullptr;
        }
        std::optional<VariableRef> ref = variableRef(st.target);
        if (!ref || !write(*ref, *v, st.target.loc)) return nullptr;
        break;
      }
      case K::IfGoto: {
        std::optional<Value> c = value(st.value, 0, true);
        if (!c) return nullptr;
        if (isTrue(*c)) jump = &st;
        break;
      }
      case K::Goto:
        jump = &st;
        break;
      case K::Call:
        if (&st == modal_target) break;  // made modal by the MCALL before it
        if (&st == mcall) {
          if (modal_l) {
            std::optional<std::string> name = subprogramNumbered(*modal_l);
            if (!name || !dinModalCall(*name, nullptr, st.loc)) return nullptr;
          } else if (!dinModalCall(modal_target && modal_target->target.text
                                       ? *modal_target->target.text
                                       : std::string(),
                                   modal_target, st.loc)) {
            return nullptr;
          }
          break;
        }
        if (!dinCall(st, at, out)) return nullptr;
        break;
      case K::Proc:
        if (!dinProc(block, st, at)) return nullptr;
        break;
      case K::Parameter:
        break;  // bound by its PROC
      case K::Return:
        dinReturn(st.loc, at);
        break;
      case K::If:
      case K::Else:
      case K::EndIf:
      case K::While:
      case K::EndWhile:
      case K::For:
      case K::EndFor:
      case K::Repeat:
      case K::Until:
      case K::Loop:
      case K::EndLoop:
      case K::Case:
      case K::RepeatSection:
        structure = &st;
        break;
      case K::CaseBranch:
        break;  // read by its CASE
      case K::IfThen:
      case K::End:
        // The DIN parser makes none of these: a tree from elsewhere (a damaged store).
        fail(EvalError::NotSupported, st.loc, "an ISO macro statement in a DIN block");
        return nullptr;
    }
    if (jump || structure) break;  // a jump ends the block; a structure is alone in it
  }

  if (structure && !dinControl(block, *structure, at)) return nullptr;
  if (jump && !dinJump(*jump, at)) return nullptr;
  if (out.words.empty() && !out.sequence) return nullptr;
  return &out;
}

// ---- control structures (Job Planning, program flow control) ----------------------------
// An open structure is kept per program (Frame::structures) from its opening block to its end:
// WHILE, REPEAT and LOOP go back to their opening block, FOR to the block after it. A jump out
// of a structure is allowed: the structure stays open until an end of an enclosing one meets
// it (as ISO's WHILE ... DO), and coming back to an opening block re-opens it afresh.

namespace {

using SK = ast::Statement::Kind;

constexpr int64_t kMaxSectionRepeats = 9999;  // REPEAT ... P=n
constexpr size_t kMaxSections = 16;  // sections repeated inside each other (as structures)

// Structures open at once in one program (840D: 16 per program level).
constexpr size_t kMaxStructures = 16;

const char* keyword(SK k) {
  switch (k) {
    case SK::If: return "IF";
    case SK::Else: return "ELSE";
    case SK::EndIf: return "ENDIF";
    case SK::While: return "WHILE";
    case SK::EndWhile: return "ENDWHILE";
    case SK::For: return "FOR";
    case SK::EndFor: return "ENDFOR";
    case SK::Repeat: return "REPEAT";
    case SK::Until: return "UNTIL";
    case SK::Loop: return "LOOP";
    case SK::EndLoop: return "ENDLOOP";
    default: return "CASE";
  }
}

bool opens(SK k) {
  return k == SK::If || k == SK::While || k == SK::For || k == SK::Repeat || k == SK::Loop;
}
bool closes(SK k) {
  return k == SK::EndIf || k == SK::EndWhile || k == SK::EndFor || k == SK::Until ||
         k == SK::EndLoop;
}

// Drops the structure opened at `at` and those inside it: its opening block runs again.
void reenter(std::vector<Structure>& open, const ProgramPoint& at) {
  for (size_t i = 0; i < open.size(); ++i)
    if (open[i].at == at) {
      open.resize(i);
      return;
    }
}

}  // namespace

bool Evaluator::Impl::openStructure(SK kind, const ProgramPoint& at, SourceLocation loc) {
  std::vector<Structure>& open = frames.back().structures;
  if (open.size() >= kMaxStructures) {
    fail(EvalError::StructureDepth, loc,
         absl::StrCat("control structures nested more than ", kMaxStructures, " deep"));
    return false;
  }
  Structure opened;
  opened.kind = kind;
  opened.at = at;
  open.push_back(std::move(opened));
  return true;
}

Structure* Evaluator::Impl::closeStructure(SK kind, const ast::Statement& st) {
  std::vector<Structure>& open = frames.back().structures;
  for (size_t i = open.size(); i-- > 0;)
    if (open[i].kind == kind) {
      open.resize(i + 1);
      return &open.back();
    }
  fail(EvalError::StructureNesting, st.loc,
       absl::StrCat(keyword(st.kind), " without ", keyword(kind)));
  return nullptr;
}

// Reads past `st`'s block: a caller that needs `st` afterwards copies what it needs first.
std::optional<SK> Evaluator::Impl::skipStructure(const ast::Statement& st,
                                                 std::initializer_list<SK> ends) {
  Frame& frame = frames.back();
  const SK expected = *(ends.end() - 1);  // ENDIF for IF's {ELSE, ENDIF}
  const SourceLocation loc = st.loc;
  const std::string opening = keyword(st.kind);
  int depth = 0;
  while (true) {
    const ast::Block* b = frame.cursor->next();
    ++blocks_read;
    if (!b || b->program_number || b->percent || beyondEnd(frame, frame.cursor->lastPoint())) {
      fail(EvalError::StructureNesting, loc,
           absl::StrCat(opening, " without ", keyword(expected), " before the end of the program"));
      return std::nullopt;
    }
    if (b->language != frontend::Language::Din) continue;
    for (const ast::Statement& s : b->statements) {
      if (opens(s.kind) && !(s.kind == SK::While && s.loop_id != 0)) {
        ++depth;
      } else if (closes(s.kind) || s.kind == SK::Else) {
        if (depth > 0) {
          if (s.kind != SK::Else) --depth;
          continue;
        }
        for (SK end : ends)
          if (s.kind == end) return end;
        if (s.kind == SK::Else) continue;  // ELSE of an enclosing IF: not ours to stop at
        fail(EvalError::StructureNesting, s.loc,
             absl::StrCat(keyword(s.kind), " where ", keyword(expected), " closes the ", opening,
                          " at line ", loc.line));
        return std::nullopt;
      }
    }
  }
}

bool Evaluator::Impl::dinControl(const ast::Block& block, const ast::Statement& st,
                                 const ProgramPoint& at) {
  Frame& frame = frames.back();
  std::vector<Structure>& open = frame.structures;
  const auto condition = [&]() -> std::optional<bool> {
    std::optional<Value> c = value(st.value, 0, true);
    if (!c) return std::nullopt;
    return isTrue(*c);
  };
  const auto loopBack = [&](const ProgramPoint& to) {
    if (!countBackJump(st.loc)) return false;
    jumpWithinSections(frame, to);
    frame.cursor->seek(to);
    return true;
  };
  switch (st.kind) {
    case SK::If: {
      std::optional<bool> c = condition();
      if (!c) return false;
      if (*c) return openStructure(SK::If, at, st.loc);
      const SourceLocation loc = st.loc;  // `st` is the cursor's: skipping reads past it
      std::optional<SK> reached = skipStructure(st, {SK::Else, SK::EndIf});
      if (!reached) return false;
      return *reached == SK::EndIf || openStructure(SK::If, at, loc);
    }
    case SK::Else:
      // The end of the IF branch: on past the ENDIF.
      if (!closeStructure(SK::If, st)) return false;
      open.pop_back();
      return skipStructure(st, {SK::EndIf}).has_value();
    case SK::EndIf:
      if (!closeStructure(SK::If, st)) return false;
      open.pop_back();
      return true;
    case SK::While: {
      reenter(open, at);
      std::optional<bool> c = condition();
      if (!c) return false;
      if (*c) return openStructure(SK::While, at, st.loc);
      return skipStructure(st, {SK::EndWhile}).has_value();
    }
    case SK::Repeat:
    case SK::Loop:
      reenter(open, at);
      return openStructure(st.kind, at, st.loc);
    case SK::EndWhile:
    case SK::EndLoop: {
      Structure* s = closeStructure(st.kind == SK::EndWhile ? SK::While : SK::Loop, st);
      if (!s) return false;
      const ProgramPoint to = s->at;
      open.pop_back();
      return loopBack(to);
    }
    case SK::Until: {
      Structure* s = closeStructure(SK::Repeat, st);
      if (!s) return false;
      const ProgramPoint to = s->at;
      open.pop_back();
      std::optional<bool> c = condition();
      if (!c) return false;
      return *c || loopBack(to);
    }
    case SK::For: {
      if (frame.for_resume == at) {  // ENDFOR came back: the counter is counted already
        frame.for_resume.reset();
        return true;
      }
      reenter(open, at);
      if (!st.then_assign) {
        fail(EvalError::NotSupported, st.loc, "FOR without its counter");  // a damaged tree
        return false;
      }
      const ast::Statement& init = *st.then_assign;
      Structure loop;
      loop.kind = SK::For;
      loop.at = at;
      std::optional<VariableRef> counter_ref = variableRef(init.target);
      if (!counter_ref) return false;
      loop.counter = std::move(*counter_ref);
      std::optional<Value> start = value(init.value, 0, true);
      if (!start) return false;
      std::optional<Value> end = value(st.value, 0, true);
      if (!end) return false;
      loop.end = end->arithmetic();
      if (!write(loop.counter, *start, init.target.loc)) return false;
      std::optional<Value> counter = read(loop.counter, st.loc);
      if (!counter) return false;
      if (counter->arithmetic() <= loop.end) {
        if (!openStructure(SK::For, at, st.loc)) return false;
        open.back() = std::move(loop);
        return true;
      }
      return skipStructure(st, {SK::EndFor}).has_value();
    }
    case SK::EndFor: {
      Structure* s = closeStructure(SK::For, st);
      if (!s) return false;
      std::optional<Value> counter = read(s->counter, st.loc);
      if (!counter) return false;
      const Value next = Value::of(counter->arithmetic() + 1);
      if (!write(s->counter, next, st.loc)) return false;
      if (next.number > s->end) {
        open.pop_back();
        return true;
      }
      frame.for_resume = s->at;
      return loopBack(s->at);
    }
    case SK::Case: {
      // As `==` compares: a string with string constants, a number with numbers, a CHAR with
      // either (CASE (FORM) OF "A" GOTOF ..., or its code); a string against a number is 12150.
      const ValueKind kind = kindOf(st.value, variables);
      bool after = false;
      for (const ast::Statement& branch : block.statements) {
        if (&branch == &st) after = true;
        if (!after || branch.kind != SK::CaseBranch) continue;
        bool taken = branch.value.kind == ast::Expr::Kind::Vacant;
        if (!taken) {
          const bool text_constant = branch.value.kind == ast::Expr::Kind::String;
          if ((kind == ValueKind::String && !text_constant) ||
              (kind == ValueKind::Number && text_constant)) {
            fail(EvalError::TypeMismatch, branch.value.loc,
                 "CASE compares a string with a number (NUMBER(...) reads the number a string holds)");
            return false;
          }
          const ast::DataType as = text_constant ? ast::DataType::String : ast::DataType::Real;
          std::optional<Datum> c = datum(st.value, as);
          if (!c) return false;
          std::optional<Datum> constant = datum(branch.value, as);
          if (!constant) return false;
          taken = *constant == *c;
        }
        if (taken) return dinJump(branch, at);
      }
      return true;  // no constant matches and no DEFAULT: the next block
    }
    case SK::RepeatSection:
      return dinRepeatSection(st, at);
    default:
      fail(EvalError::NotSupported, st.loc, "a statement that is not a control structure");
      return false;
  }
}

// ---- program section repetition (Job Planning, "Program section repetition") --------------
// REPEATB LABEL P=n runs the block with the label (searched back, then forward) n times;
// REPEAT START END P=n the blocks from START to END (START searched back, then forward; END
// after it); REPEAT START P=n the blocks from START (searched back) up to the REPEAT, or up to
// an ENDLABEL: block between them. Then the program goes on after the REPEAT. P is 1 to 9999
// (1 when not written); sections nest.

bool Evaluator::Impl::dinRepeatSection(const ast::Statement& st, const ProgramPoint& at) {
  Frame& frame = frames.back();
  int64_t n = 1;
  if (st.value.kind != ast::Expr::Kind::Vacant) {
    std::optional<Value> v = value(st.value, 0, true);
    if (!v) return false;
    const double p = v->arithmetic();
    if (!(p >= 1 && p <= kMaxSectionRepeats) || p != std::floor(p)) {
      fail(EvalError::AddressValue, st.value.loc,
           absl::StrCat("P=", p, ": a section is repeated 1 to ", kMaxSectionRepeats, " times"));
      return false;
    }
    n = static_cast<int64_t>(p);
  }
  const ProgramPoint end_point = programEnd(frame);
  const std::string start_name = st.target.text ? *st.target.text : std::string();
  const bool single = st.loop_id == 1;
  const bool end_written = !st.target.args.empty() && st.target.args[0].text;
  std::optional<ProgramPoint> start =
      store.findLabel(start_name, at, SequenceSearch::Backward, frame.begin, end_point);
  if (!start && (single || end_written))
    start = store.findLabel(start_name, at, SequenceSearch::Forward, frame.begin, end_point);
  const char* keyword = single ? "REPEATB" : "REPEAT";
  if (!start) {
    fail(EvalError::JumpTarget, st.loc,
         absl::StrCat(keyword, ": label ", start_name, " not found in this program",
                      single || end_written ? "" : " before the REPEAT"));
    return false;
  }
  if (frame.sections.size() >= kMaxSections) {
    fail(EvalError::StructureDepth, st.loc,
         absl::StrCat(keyword, ": program sections repeated inside each other more than ",
                      kMaxSections, " deep"));
    return false;
  }
  Section section{*start, std::nullopt, at, n - 1, st.loc};
  if (single) {
    section.end = *start;
  } else if (end_written) {
    const std::string& end_name = *st.target.args[0].text;
    section.end = end_name == start_name
                      ? start
                      : store.findLabel(end_name, *start, SequenceSearch::Forward, frame.begin,
                                        end_point);
    if (!section.end) {
      fail(EvalError::JumpTarget, st.loc,
           absl::StrCat("REPEAT: end label ", end_name, " not found after ", start_name));
      return false;
    }
  } else {
    section.end = store.findLabel("ENDLABEL", *start, SequenceSearch::Forward, *start, at);
  }
  frame.sections.push_back(section);
  frame.cursor->seek(*start);
  return before(at, *start) || countBackJump(st.loc);
}

bool Evaluator::Impl::sectionBoundary(Frame& f, const ProgramPoint& at) {
  if (f.section_return && at == *f.section_return) {
    f.section_return.reset();
    return true;  // the REPEAT whose section is done: the program goes on after it
  }
  if (f.sections.empty()) return false;
  const Section& s = f.sections.back();
  if (!s.end && at == s.repeat_at) {
    sectionStep(f);  // back to the REPEAT: the section's end
    return true;
  }
  // A REPEAT inside the section it repeats (`MA: REPEATB MA P=3`) does not start it again.
  bool own_repeat = false;
  for (const Section& open : f.sections) own_repeat = own_repeat || at == open.repeat_at;
  if (s.end && at == *s.end) f.section_step = true;  // after this block
  return own_repeat;
}

bool Evaluator::Impl::sectionStep(Frame& f) {
  Section& s = f.sections.back();
  if (s.left > 0) {
    --s.left;
    f.cursor->seek(s.start);
    return countBackJump(s.loc);
  }
  const ProgramPoint back = s.repeat_at;
  const bool elsewhere = s.end.has_value();
  f.sections.pop_back();
  if (elsewhere) {  // on after the REPEAT, which is not to run again
    f.cursor->seek(back);
    f.section_return = back;
  }
  return true;
}

// ---- variables named by reference ---------------------------------------------------------

std::optional<VariableRef> Evaluator::Impl::variableRef(const ast::Expr& e) {
  Failure failure;
  VariableRef ref;
  if (e.kind == ast::Expr::Kind::RParam && !e.args.empty()) {
    std::optional<Value> index = value(e.args[0], 0, true);
    if (!index) return std::nullopt;
    std::optional<int64_t> n = variableNumber(*index, rules, e.loc, failure);
    if (!n) {
      fail(failure);
      return std::nullopt;
    }
    ref.r = *n;
    return ref;
  }
  if (e.kind == ast::Expr::Kind::Name && e.text) {
    std::optional<std::vector<int64_t>> indices = indicesOf(e.args, expressionContext(true), failure);
    if (!indices) {
      fail(failure);
      return std::nullopt;
    }
    ref.name = *e.text;
    ref.indices = std::move(*indices);
    return ref;
  }
  fail(EvalError::VariableNumber, e.loc, "not a variable");
  return std::nullopt;
}

std::optional<Datum> Evaluator::Impl::datum(const ast::Expr& e, ast::DataType type) {
  if (type != ast::DataType::String && kindOf(e, variables) != ValueKind::String) {
    std::optional<Value> v = value(e, 0, true);
    if (!v) return std::nullopt;
    return Datum(*v);
  }
  Failure failure;
  std::optional<std::string> t = evaluateText(e, expressionContext(true), failure);
  if (!t) {
    fail(failure);
    return std::nullopt;
  }
  return Datum(std::move(*t));
}

std::optional<Value> Evaluator::Impl::read(const VariableRef& ref, SourceLocation loc) {
  Failure failure;
  NamedVariables& named = variables.named();
  std::optional<Value> v =
      ref.r >= 0 ? named.readR(ref.r, loc, failure) : named.read(ref.name, ref.indices, loc, failure);
  if (!v) fail(failure);
  return v;
}

bool Evaluator::Impl::write(const VariableRef& ref, const Datum& v, SourceLocation loc) {
  Failure failure;
  NamedVariables& named = variables.named();
  bool ok = false;
  if (ref.r < 0) {
    ok = named.write(ref.name, ref.indices, v, loc, failure);
  } else if (const Value* number = std::get_if<Value>(&v)) {
    ok = named.writeR(ref.r, *number, loc, failure);
  } else {
    failure = {EvalError::TypeMismatch, loc,
               absl::StrCat("R", ref.r, " is REAL: a string is not a number (NUMBER(\"...\") reads one)"), 0};
  }
  if (!ok) fail(failure);
  return ok;
}

// ---- array values (Job Planning, "Definition and initialization of array variables") ------
// `A[1,0]=SET(1, , 3)`: the elements from A[1,0] on, in memory order (the last index runs
// fastest), take the values in turn; an omitted value leaves its element as it is. `REP(v)`
// gives v to every element from there to the end of the array, `REP(v, n)` to n of them. In
// a DEF the values start at the first element. More values than elements is alarm 12260.

bool Evaluator::Impl::fillArray(const VariableRef& ref, const ast::Expr& e) {
  NamedVariables& named = variables.named();
  Failure failure;
  if (ref.r >= 0) {
    fail(EvalError::TypeMismatch, e.loc,
         absl::StrCat(ast::opText(e.op), "(...) gives an array its values; R", ref.r, " is no array"));
    return false;
  }
  std::optional<size_t> left = named.elementsFrom(ref.name, ref.indices, e.loc, failure);
  if (!left) {
    fail(failure);
    return false;
  }
  const ast::DataType type = named.find(ref.name)->type;
  std::vector<std::optional<Datum>> values;
  if (e.op == ast::Op::Rep) {
    std::optional<Datum> v = datum(e.args[0], type);
    if (!v) return false;
    size_t count = *left;
    if (e.args.size() > 1) {
      std::optional<int64_t> n = integerOf(e.args[1], e.args[1].loc, "REP's count");
      if (!n) return false;
      if (*n < 0 || static_cast<uint64_t>(*n) > *left) {
        fail(EvalError::TooManyValues, e.args[1].loc,
             absl::StrCat("REP(..., ", *n, "): ", *left, " elements are left in ", ref.name));
        return false;
      }
      count = static_cast<size_t>(*n);
    }
    values.assign(count, *v);
  } else {
    if (e.args.size() > *left) {
      fail(EvalError::TooManyValues, e.args[*left].loc,
           absl::StrCat("SET: ", e.args.size(), " values, ", *left, " elements are left in ",
                        ref.name));
      return false;
    }
    for (const ast::Expr& a : e.args) {
      if (a.kind == ast::Expr::Kind::Vacant) {
        values.emplace_back();
        continue;
      }
      std::optional<Datum> v = datum(a, type);
      if (!v) return false;
      values.push_back(std::move(*v));
    }
  }
  if (!named.fill(ref.name, ref.indices, values, e.loc, failure)) {
    fail(failure);
    return false;
  }
  return true;
}

// ---- subprograms (Fundamentals, subprogram technique) --------------------------------------

namespace {

// Names the control knows before the program folder (issue 33 builds the cycles): a call of
// one is never looked for as a file. Block commands are words of their block: lowering reads
// them with the block's other words (the frame instructions: DialectTable::frame_commands,
// lowering_frames.cpp); the rest not built yet is refused.
struct BuiltIn {
  // Done: what the command asks for is how ncc evaluates anyway (STOPRE, docs/din.md).
  enum class Use : uint8_t { NotBuilt, BlockCommand, SetAlarm, Message, Done };
  std::string_view name;
  bool prefix;  // CYCLE81, CYCLE800 ...: every name that starts so
  const char* what;
  Use use = Use::NotBuilt;
};
using U = BuiltIn::Use;
constexpr BuiltIn kBuiltIns[] = {
    {"TRANS", false, "programmable frame", U::BlockCommand},
    {"ATRANS", false, "programmable frame", U::BlockCommand},
    {"ROT", false, "programmable frame", U::BlockCommand},
    {"AROT", false, "programmable frame", U::BlockCommand},
    {"SCALE", false, "programmable frame", U::BlockCommand},
    {"ASCALE", false, "programmable frame", U::BlockCommand},
    {"MIRROR", false, "programmable frame", U::BlockCommand},
    {"AMIRROR", false, "programmable frame", U::BlockCommand},
    {"SETAL", false, "setting an alarm", U::SetAlarm},
    {"CYCLE", true, "Siemens cycle"},
    {"POCKET", true, "Siemens milling cycle"}, {"SLOT", true, "Siemens milling cycle"},
    {"HOLES", true, "Siemens hole pattern"},  {"LONGHOLE", false, "Siemens milling cycle"},
    {"MSG", false, "operator message", U::Message},
    {"STOPRE", false, "preprocessing stop", U::Done},  {"BSPLINE", false, "spline interpolation"},
    {"ASPLINE", false, "spline interpolation"}, {"CSPLINE", false, "spline interpolation"},
    {"POLY", false, "polynomial interpolation"}, {"TRANSMIT", false, "kinematic transformation"},
    {"TRACYL", false, "kinematic transformation"}, {"TRAORI", false, "kinematic transformation"},
    {"TRAFOOF", false, "kinematic transformation"}, {"WAITP", false, "positioning axes"},
    {"WAITS", false, "spindle synchronisation"}, {"SOFT", false, "acceleration profile"},
    {"BRISK", false, "acceleration profile"}, {"FFWON", false, "feedforward control"},
    {"FFWOF", false, "feedforward control"}, {"CDON", false, "collision detection"},
    {"CDOF", false, "collision detection"},
    {"EXTERN", false, "external subprogram declaration"},
    {"CIP", false, "circle through an intermediate point"},
    {"CT", false, "circle with tangential transition"}, {"SUPA", false, "frame suppression"},
    {"CFC", false, "constant feed at the contour"}, {"CFTCP", false, "feed at the tool centre"},
    {"CFIN", false, "constant feed at inner arcs"}, {"DRIVE", false, "acceleration profile"},
};

// SETAL(n) (Fundamentals, "Set alarm"; the alarm ranges of the Diagnostics Manual): the cycle
// and user alarms 60000-69999; those of 62000-62999 and 67000-67999 are shown and the program
// goes on, the others stop it.
constexpr int64_t kFirstCycleAlarm = 60000, kLastCycleAlarm = 69999;
constexpr int64_t kMaxRepeats = 9999;  // `P` of a subprogram call (Fundamentals)
bool alarmContinues(int64_t n) { return (n >= 62000 && n <= 62999) || (n >= 67000 && n <= 67999); }

const BuiltIn* builtIn(std::string_view name) {
  for (const BuiltIn& b : kBuiltIns)
    if (b.prefix ? name.substr(0, b.name.size()) == b.name : name == b.name) return &b;
  return nullptr;
}

}  // namespace

bool Evaluator::Impl::dinCall(const ast::Statement& st, const ProgramPoint& at, ast::Block& out) {
  const std::string name = st.target.text ? *st.target.text : std::string();
  if (const BuiltIn* b = builtIn(name)) {
    if (b->use == U::BlockCommand && st.target.args.empty()) {
      out.words.push_back(ast::Word{name, ast::Expr::literal(0, false, st.loc), st.loc});
      return true;
    }
    if (b->use == U::BlockCommand) {
      fail(EvalError::NotSupported, st.loc,
           absl::StrCat(name, " takes its values as words of its block (", name,
                        " X.. Y..), not in parentheses"));
      return false;
    }
    if (b->use == U::SetAlarm) return setAlarm(st);
    if (b->use == U::Message) return message(st);
    if (b->use == U::Done) {
      if (st.target.args.empty()) return true;
      fail(EvalError::TooManyArguments, st.loc, absl::StrCat(name, " takes no arguments"));
      return false;
    }
    fail(EvalError::NotSupported, st.loc,
         absl::StrCat("'", name, "' (", b->what, ") is not supported yet (docs/din.md)"));
    return false;
  }
  std::optional<Pending> call = dinPending(name, st.loc, at);
  if (!call || !dinArguments(st, call->din_arguments)) return false;
  pending.push_back(std::move(*call));
  return true;
}

bool Evaluator::Impl::dinArguments(const ast::Statement& st, std::vector<DinArgument>& out) {
  for (const ast::Expr& arg : st.target.args) {
    DinArgument& a = out.emplace_back();
    a.loc = arg.loc;
    if (arg.kind == ast::Expr::Kind::Vacant) continue;  // omitted: the parameter gets 0
    a.value = datum(arg, ast::DataType::None);
    if (!a.value) return false;
    a.character = kindOf(arg, variables) == ValueKind::Char;
    if (arg.kind == ast::Expr::Kind::Name || arg.kind == ast::Expr::Kind::RParam) {
      a.ref = variableRef(arg);
      if (!a.ref) return false;
    }
  }
  return true;
}

// MCALL NAME(args) (Fundamentals, "Modal subprogram call"): NAME is called with the arguments
// as they are now after each later block of this program level that moves an axis, until
// MCALL alone cancels it or another MCALL replaces it; the called program's own blocks do not
// call it again. Siemens cycles (MCALL CYCLE81 ...) are the next issue's.
bool Evaluator::Impl::dinModalCall(const std::string& name, const ast::Statement* st,
                                   SourceLocation loc) {
  if (!modal_calls.empty() && modal_calls.back().din && modal_calls.back().depth == frames.size())
    modal_calls.pop_back();
  if (name.empty()) return true;
  if (const BuiltIn* b = builtIn(name)) {
    fail(EvalError::NotSupported, st ? st->loc : loc,
         absl::StrCat("MCALL ", name, ": '", name, "' (", b->what, ") is not supported yet (docs/din.md)"));
    return false;
  }
  ModalCall mc;
  mc.din = true;
  mc.name = name;
  mc.depth = frames.size();
  mc.loc = loc;
  if (st && !dinArguments(*st, mc.din_arguments)) return false;
  modal_calls.push_back(std::move(mc));
  return true;
}

std::optional<Pending> Evaluator::Impl::dinPending(std::string name, SourceLocation loc,
                                                   const ProgramPoint& at) {
  Pending p;
  p.kind = Pending::Kind::Call;
  p.din = true;
  p.name = std::move(name);
  p.loc = loc;
  p.at = at;
  if (!repeat_word) return p;
  std::optional<Value> v = value(repeat_word->value, 0, true);
  if (!v) return std::nullopt;
  const double n = v->arithmetic();
  if (!(n >= 1 && n <= kMaxRepeats) || n != std::floor(n)) {
    fail(EvalError::AddressValue, repeat_word->loc,
         absl::StrCat("P", n, ": a subprogram runs 1 to ", kMaxRepeats, " times"));
    return std::nullopt;
  }
  p.repeats = static_cast<int64_t>(n);
  return p;
}

std::optional<std::string> Evaluator::Impl::subprogramNumbered(const ast::Word& w) {
  // The name keeps the digits as written: L0123 and L123 are different programs.
  std::optional<Value> v = value(w.value, 0, true);
  if (!v) return std::nullopt;
  const double n = v->arithmetic();
  if (!(n >= 0 && n <= 9999999) || n != std::floor(n)) {
    fail(EvalError::AddressValue, w.loc, absl::StrCat("L", n, ": subprogram numbers are 0 to 9999999"));
    return std::nullopt;
  }
  std::string digits = absl::StrCat(static_cast<int64_t>(n));
  if (w.value.kind == ast::Expr::Kind::Number && w.value.digits > digits.size())
    digits.insert(0, w.value.digits - digits.size(), '0');
  return "L" + digits;
}

bool Evaluator::Impl::dinCallNumbered(const ast::Word& w, const ProgramPoint& at) {
  std::optional<std::string> name = subprogramNumbered(w);
  if (!name) return false;
  std::optional<Pending> call = dinPending(*name, w.loc, at);
  if (!call) return false;
  pending.push_back(std::move(*call));
  return true;
}

bool Evaluator::Impl::setAlarm(const ast::Statement& st) {
  if (st.target.args.size() > 2) {
    fail(EvalError::TooManyArguments, st.loc, "SETAL takes the alarm number (and a text)");
    return false;
  }
  if (st.target.args.empty() || st.target.args[0].kind == ast::Expr::Kind::Vacant) {
    fail(EvalError::AddressValue, st.loc, "SETAL takes the alarm number (and a text): it is missing");
    return false;
  }
  std::optional<Value> v = value(st.target.args[0], 0, true);
  if (!v) return false;
  const double n = v->arithmetic();
  if (!(n >= kFirstCycleAlarm && n <= kLastCycleAlarm) || n != std::floor(n)) {
    fail(EvalError::AddressValue, st.target.args[0].loc,
         absl::StrCat("SETAL(", n, "): cycle and user alarms are ", kFirstCycleAlarm, " to ",
                      kLastCycleAlarm));
    return false;
  }
  const int64_t code = static_cast<int64_t>(n);
  if (alarmContinues(code)) {
    diags.warning(absl::StrCat(code), st.loc, absl::StrCat("SETAL(", code, "): the program goes on"));
    return true;
  }
  fail(Failure{EvalError::UserAlarm, st.loc, absl::StrCat("SETAL(", code, ")"), code});
  return false;
}

// MSG("text") shows the text on the operator panel until the next MSG (Fundamentals, "Output
// messages"); MSG() clears it. A run has no panel: each text is a note at its block, so the
// run's output shows what the operator would read, in program order. A second argument (the
// display mode of later software) is read and not used.
bool Evaluator::Impl::message(const ast::Statement& st) {
  const std::vector<ast::Expr>& args = st.target.args;
  if (args.size() > 2) {
    fail(EvalError::TooManyArguments, st.loc, "MSG takes the text (and a display mode)");
    return false;
  }
  if (args.empty() || args[0].kind == ast::Expr::Kind::Vacant) return true;  // clears the text
  std::optional<Datum> text = datum(args[0], ast::DataType::String);
  if (!text) return false;
  if (args.size() == 2 && args[1].kind != ast::Expr::Kind::Vacant && !value(args[1], 0, true))
    return false;
  if (messages_shown == kMaxMessages) {
    diags.report(Severity::Note, "NCC2440", st.loc,
                 absl::StrCat("MSG: more than ", kMaxMessages, " messages; the others are not shown"));
  } else if (messages_shown < kMaxMessages) {
    diags.report(Severity::Note, "NCC2440", st.loc,
                 absl::StrCat("MSG: ", std::get<std::string>(*text)));
  }
  ++messages_shown;
  return true;
}

bool Evaluator::Impl::dinProc(const ast::Block& block, const ast::Statement& st,
                              const ProgramPoint& at) {
  Frame& frame = frames.back();
  const std::string name = st.target.text ? *st.target.text : std::string();
  if (!(at == frame.first_content)) {
    fail(EvalError::ProcPlacement, st.loc,
         absl::StrCat("PROC ", name, " must be the first block of its program"));
    return false;
  }
  std::vector<const ast::Statement*> params;
  for (const ast::Statement& s : block.statements)
    if (s.kind == SK::Parameter) params.push_back(&s);
  const std::vector<DinArgument>& args = frame.din_arguments;
  if (args.size() > params.size()) {
    fail(EvalError::TooManyArguments, frame.call_loc,
         absl::StrCat("too many parameters: ", name, " takes ", params.size(), ", the call gives ",
                      args.size()));
    return false;
  }
  NamedVariables& named = variables.named();
  Failure failure;
  for (size_t i = 0; i < params.size(); ++i) {
    const ast::Statement& param = *params[i];
    const DinArgument* arg = i < args.size() ? &args[i] : nullptr;
    const std::string param_name = param.target.text ? *param.target.text : std::string();
    if (param.loop_id == 1 && frame.din_call) {
      if (!arg || !arg->ref) {
        fail(EvalError::ArgumentNotVariable, arg ? arg->loc : frame.call_loc,
             absl::StrCat("parameter ", param_name, " of ", name,
                          " is VAR (passed by reference): the call must give a variable"));
        return false;
      }
      frame.by_reference.emplace_back(param_name, *arg->ref);
    }
    // An omitted argument is 0 (cycles notes §1.3.4).
    std::optional<Datum> initial = arg ? arg->value : std::nullopt;
    if (arg && arg->character && param.type == ast::DataType::String && initial &&
        std::holds_alternative<Value>(*initial)) {
      const double code = std::get<Value>(*initial).arithmetic();
      initial = Datum(code == 0.0 ? std::string() : std::string(1, static_cast<char>(code)));
    }
    if (!named.define(param_name, param.type, param.length, {}, initial,
                      arg ? arg->loc : param.loc, failure)) {
      fail(failure);
      return false;
    }
  }
  return true;
}

void Evaluator::Impl::dinReturn(SourceLocation loc, const ProgramPoint& at) {
  Pending p;
  p.kind = Pending::Kind::Return;
  p.din = true;
  p.loc = loc;
  p.at = at;
  pending.push_back(std::move(p));
}

bool Evaluator::Impl::dinJump(const ast::Statement& st, const ProgramPoint& at) {
  Frame& frame = frames.back();
  const SequenceSearch order = searchOf(st.jump, rules);
  const ProgramPoint end_point = programEnd(frame);
  std::optional<ProgramPoint> target;
  std::string what;
  if (st.target.kind == ast::Expr::Kind::Name && st.target.text) {
    what = absl::StrCat("label ", *st.target.text);
    target = store.findLabel(*st.target.text, at, order, frame.begin, end_point);
  } else {
    std::optional<int64_t> n = integerOf(st.target, st.loc, "the jump target");
    if (!n) return false;
    what = absl::StrCat("block N", *n);
    target = store.findSequence(*n, at, order, frame.begin, end_point);
  }
  if (!target) {
    if (st.jump == ast::Jump::BothQuiet) return true;  // GOTOC: no alarm, the program goes on
    const char* where = order == SequenceSearch::Forward    ? " between here and the end"
                        : order == SequenceSearch::Backward ? " between the start and here"
                                                            : "";
    fail(EvalError::JumpTarget, st.loc,
         absl::StrCat(jumpName(st.jump), ": jump destination ", what, " not found", where,
                      " in this program"));
    return false;
  }
  if (!before(at, *target) && !countBackJump(st.loc)) return false;
  jumpWithinSections(frame, *target);
  frame.cursor->seek(*target);
  return true;
}

// A jump ends the step of a section whose last block it leaves from, and closes every section
// it leaves: the program goes on from the target, not from the section's start.
void Evaluator::Impl::jumpWithinSections(Frame& f, const ProgramPoint& target) {
  f.section_step = false;
  while (!f.sections.empty()) {
    const Section& s = f.sections.back();
    const ProgramPoint& last = s.end ? *s.end : s.repeat_at;
    if (!before(target, s.start) && !before(last, target)) break;  // inside: it stays open
    f.sections.pop_back();
  }
}

}  // namespace ncc::eval
