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
      case K::IfThen:
      case K::While:
      case K::End:
        // The DIN parser makes none of these: a tree from elsewhere (a damaged store).
        fail(EvalError::NotSupported, st.loc, "an ISO macro statement in a DIN block");
        return nullptr;
    }
    if (jump) break;  // a jump ends the block
  }

  if (jump && !dinJump(*jump, at)) return nullptr;
  if (out.words.empty() && !out.sequence) return nullptr;
  return &out;
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
