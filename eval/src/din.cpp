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

}  // namespace

bool Evaluator::Impl::dinPlain(const ast::Block& block) const {
  if (!block.statements.empty()) return false;
  const NamedVariables& named = variables.named();
  for (const ast::Word& w : block.words)
    if (!isLiteral(w.value) || (named.any() && named.find(w.address.view()))) return false;
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
  ExpressionContext context{rules, variables};
  context.adp_scale = options.adp_scale;
  context.din = true;
  Failure failure;
  const auto failed = [&] {
    fail(failure);
    return nullptr;
  };

  const ast::Statement* jump = nullptr;
  const ast::Statement* structure = nullptr;
  for (const Item& item : items) {
    if (item.word) {
      const ast::Word& w = *item.word;
      if (named.any() && named.find(w.address.view())) {
        std::optional<Value> v = value(w.value, 0, true);
        if (!v) return nullptr;
        if (!named.write(w.address.view(), {}, *v, w.loc, failure)) return failed();
        continue;
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
        std::optional<Value> initial;
        if (st.value.kind != ast::Expr::Kind::Vacant) {
          initial = value(st.value, 0, true);
          if (!initial) return nullptr;
        }
        const std::string_view name = st.target.text ? *st.target.text : std::string_view();
        if (!named.define(name, st.type, *dims, initial, st.loc, failure)) return failed();
        break;
      }
      case K::Assign: {
        std::optional<Value> v = value(st.value, 0, true);
        if (!v) return nullptr;
        if (st.target.kind == ast::Expr::Kind::RParam && !st.target.args.empty()) {
          std::optional<Value> index = value(st.target.args[0], 0, true);
          if (!index) return nullptr;
          std::optional<int64_t> n = variableNumber(*index, rules, st.target.loc, failure);
          if (!n || !named.writeR(*n, *v, st.target.loc, failure)) return failed();
        } else if (st.target.kind == ast::Expr::Kind::Name && st.target.text) {
          std::optional<std::vector<int64_t>> indices = indicesOf(st.target.args, context, failure);
          if (!indices || !named.write(*st.target.text, *indices, *v, st.target.loc, failure))
            return failed();
        } else {
          fail(EvalError::VariableNumber, st.target.loc, "the left side is not a variable");
          return nullptr;
        }
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
        fail(EvalError::NotSupported, st.loc,
             absl::StrCat("the call of '", st.target.text ? *st.target.text : std::string(),
                          "': DIN subprogram calls by name are not supported yet (docs/din.md)"));
        return nullptr;
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
  open.push_back(Structure{kind, at});
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
  NamedVariables& named = variables.named();
  Failure failure;
  const auto condition = [&]() -> std::optional<bool> {
    std::optional<Value> c = value(st.value, 0, true);
    if (!c) return std::nullopt;
    return isTrue(*c);
  };
  const auto loopBack = [&](const ProgramPoint& to) {
    if (!countBackJump(st.loc)) return false;
    frame.cursor->seek(to);
    return true;
  };
  switch (st.kind) {
    case SK::If: {
      std::optional<bool> c = condition();
      if (!c) return false;
      if (*c) return openStructure(SK::If, at, st.loc);
      std::optional<SK> reached = skipStructure(st, {SK::Else, SK::EndIf});
      if (!reached) return false;
      return *reached == SK::EndIf || openStructure(SK::If, at, st.loc);
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
      Structure loop{SK::For, at};
      ExpressionContext context{rules, variables};
      context.din = true;
      if (init.target.kind == ast::Expr::Kind::RParam && !init.target.args.empty()) {
        std::optional<Value> index = value(init.target.args[0], 0, true);
        if (!index) return false;
        std::optional<int64_t> n = variableNumber(*index, rules, init.target.loc, failure);
        if (!n) {
          fail(failure);
          return false;
        }
        loop.r = *n;
      } else if (init.target.kind == ast::Expr::Kind::Name && init.target.text) {
        std::optional<std::vector<int64_t>> indices = indicesOf(init.target.args, context, failure);
        if (!indices) {
          fail(failure);
          return false;
        }
        loop.name = *init.target.text;
        loop.indices = std::move(*indices);
      } else {
        fail(EvalError::VariableNumber, init.target.loc, "the FOR counter is not a variable");
        return false;
      }
      std::optional<Value> start = value(init.value, 0, true);
      if (!start) return false;
      std::optional<Value> end = value(st.value, 0, true);
      if (!end) return false;
      loop.end = end->arithmetic();
      const bool written = loop.r >= 0
                               ? named.writeR(loop.r, *start, init.target.loc, failure)
                               : named.write(loop.name, loop.indices, *start, init.target.loc, failure);
      if (!written) {
        fail(failure);
        return false;
      }
      std::optional<Value> counter = loop.r >= 0 ? named.readR(loop.r, st.loc, failure)
                                                 : named.read(loop.name, loop.indices, st.loc, failure);
      if (!counter) {
        fail(failure);
        return false;
      }
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
      std::optional<Value> counter = s->r >= 0 ? named.readR(s->r, st.loc, failure)
                                               : named.read(s->name, s->indices, st.loc, failure);
      if (!counter) {
        fail(failure);
        return false;
      }
      const Value next = Value::of(counter->arithmetic() + 1);
      const bool written = s->r >= 0 ? named.writeR(s->r, next, st.loc, failure)
                                     : named.write(s->name, s->indices, next, st.loc, failure);
      if (!written) {
        fail(failure);
        return false;
      }
      if (next.number > s->end) {
        open.pop_back();
        return true;
      }
      frame.for_resume = s->at;
      return loopBack(s->at);
    }
    case SK::Case: {
      std::optional<Value> c = value(st.value, 0, true);
      if (!c) return false;
      bool after = false;
      for (const ast::Statement& branch : block.statements) {
        if (&branch == &st) after = true;
        if (!after || branch.kind != SK::CaseBranch) continue;
        bool taken = branch.value.kind == ast::Expr::Kind::Vacant;
        if (!taken) {
          std::optional<Value> constant = value(branch.value, 0, true);
          if (!constant) return false;
          taken = constant->arithmetic() == c->arithmetic();
        }
        if (taken) return dinJump(branch, at);
      }
      return true;  // no constant matches and no DEFAULT: the next block
    }
    default:
      fail(EvalError::NotSupported, st.loc, "a statement that is not a control structure");
      return false;
  }
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
  frame.cursor->seek(*target);
  return true;
}

}  // namespace ncc::eval
