#include "antlr_block_parser.h"

#include <algorithm>
#include <climits>
#include <string>
#include <vector>

#include "IsoLexer.h"
#include "IsoParser.h"
#include "absl/strings/str_cat.h"
#include "antlr4-runtime.h"
#include "antlr_support.h"
#include "diagnostic_codes.h"
#include "lexical.h"
#include "number_text.h"

namespace ncc::frontend {

namespace {

using ncc_iso::IsoLexer;
using ncc_iso::IsoParser;
using antlr4::Token;

// absl::StrCat takes absl::string_view, which is not std::string_view in this abseil build.
std::string str(std::string_view s) { return std::string(s); }

// Builds the AST of one successfully parsed block and performs the checks the grammar leaves
// to the frontend. Every node gets the location of its first character in the original line.
class Builder : public BlockText {
 public:
  using BlockText::BlockText;

  // ---- checks on the token list, before parsing: they give the precise messages ----------

  void checkTokens(const std::vector<Token*>& tokens) {
    // Characters outside the alphabet first: they explain whatever else looks wrong.
    for (const Token* t : tokens) {
      if (t->getType() == IsoLexer::ERROR_CHAR)
        fail(codes::kUnexpectedChar, at(t),
             absl::StrCat("unexpected character ", describeChar(original_[t->getStartIndex()])));
      if (t->getType() == IsoLexer::OPEN_COMMENT)
        fail(codes::kUnclosedComment, at(t), "comment '(' is not closed by ')'");
    }
    std::vector<const Token*> open_brackets;
    // The parser recurses once per sign (unary) and a few times per bracket; chains are loops.
    // Signs in a row before a bracket nest it deeper ("-[-[-[..."), so each open bracket keeps
    // its level: brackets and signs around it. The level never exceeds the depth of the tree
    // the builder makes there (each counts a node of it, or a binary operation for the first
    // sign of "1-[..]"), so this refuses nothing the builder would take, only earlier: the
    // parser never recurses more than kMaxExprDepth signs and kMaxNesting brackets deep.
    std::vector<int> levels;
    int sign_run = 0;
    for (size_t i = 0; i < tokens.size(); ++i) {
      const Token* t = tokens[i];
      const size_t type = t->getType();
      const int signs_before = sign_run;
      sign_run = (type == IsoLexer::PLUS || type == IsoLexer::MINUS) ? sign_run + 1 : 0;
      if (sign_run > kMaxNesting)
        fail(codes::kNesting, at(t), absl::StrCat("more than ", kMaxNesting, " signs in a row"));
      const int level = levels.empty() ? 0 : levels.back();
      if (level + sign_run > ast::kMaxExprDepth) fail(codes::kExprDepth, at(t), tooDeep());
      switch (type) {
        case IsoLexer::LBRACK:
          open_brackets.push_back(t);
          if (open_brackets.size() > kMaxNesting)
            fail(codes::kNesting, at(t),
                 absl::StrCat("brackets nested deeper than ", kMaxNesting, " levels"));
          {
            // The bracket of IF [..] / WHILE [..] makes no node (its contents are the condition).
            const size_t before = i > 0 ? tokens[i - 1]->getType() : 0;
            const bool condition = before == IsoLexer::IF || before == IsoLexer::WHILE;
            levels.push_back(level + signs_before + (condition ? 0 : 1));
          }
          if (levels.back() > ast::kMaxExprDepth) fail(codes::kExprDepth, at(t), tooDeep());
          break;
        case IsoLexer::RBRACK:
          if (open_brackets.empty()) fail(codes::kUnopenedBracket, at(t), "unbalanced ']'");
          open_brackets.pop_back();
          levels.pop_back();
          break;
        case IsoLexer::COMMA:
          if (open_brackets.empty()) checkCommaAddress(tokens, i);
          break;
        case IsoLexer::LETTER:
          if (open_brackets.empty()) checkHasValue(tokens, i);
          break;
        default:
          break;
      }
    }
    if (!open_brackets.empty())
      fail(codes::kUnclosedBracket, at(open_brackets.front()), "unbalanced '['");
  }

  static bool startsValue(size_t type) {
    return type == IsoLexer::NUMBER || type == IsoLexer::HASH || type == IsoLexer::LBRACK ||
           type == IsoLexer::PLUS || type == IsoLexer::MINUS;
  }

  void checkHasValue(const std::vector<Token*>& tokens, size_t i) {
    if (i + 1 < tokens.size() && startsValue(tokens[i + 1]->getType())) return;
    bool comma = i > 0 && tokens[i - 1]->getType() == IsoLexer::COMMA;
    const Token* where = comma ? tokens[i - 1] : tokens[i];
    fail(codes::kNoValue, at(where),
         absl::StrCat("address '", comma ? "," : "", str(upper(tokens[i])), "' has no value"));
  }

  void checkCommaAddress(const std::vector<Token*>& tokens, size_t i) {
    const Token* next = i + 1 < tokens.size() ? tokens[i + 1] : nullptr;
    if (!next || next->getType() != IsoLexer::LETTER)
      fail(codes::kUnexpectedToken, at(tokens[i]), "unexpected ','");
    if (!isCommaAddressLetter(upper(next)[0]))
      fail(codes::kCommaAddress, at(tokens[i]),
           absl::StrCat("unknown comma address ',", str(upper(next)), "' (expected ,A ,C or ,R)"));
  }

  // ---- the parser's own error --------------------------------------------------------------

  [[noreturn]] void failAt(const Token* t) {
    switch (t->getType()) {
      case Token::EOF:
        fail(codes::kIncomplete, at(t), "block ends before the statement is complete");
      case IsoLexer::SLASH:
        fail(codes::kSkipNotAtStart, at(t), "block skip '/' must be at the start of the block");
      case IsoLexer::NUMBER:
        fail(codes::kUnexpectedToken, at(t),
             absl::StrCat("number '", str(written(t)), "' has no address"));
      default:
        fail(codes::kUnexpectedToken, at(t), absl::StrCat("unexpected '", str(written(t)), "'"));
    }
  }

  // ---- AST --------------------------------------------------------------------------------

  // An expression being built with its depth (ast::kMaxExprDepth), counted bottom-up so that a
  // chain is refused at the operator where it becomes too deep, reading left to right.
  struct Node {
    ast::Expr expr;
    int depth = 1;
  };

  Node node(ast::Expr e, int depth) {
    if (depth > ast::kMaxExprDepth) fail(codes::kExprDepth, e.loc, tooDeep());
    return Node{std::move(e), depth};
  }

  ast::Block block(IsoParser::BlockContext* ctx) {
    ast::Block b;
    b.loc = start_;
    if (auto* s = ctx->blockStart()) {
      if (s->PERCENT()) {
        b.percent = true;
      } else {
        b.skip_level = 1;
        if (auto* n = s->NUMBER()) {
          std::string_view text = upper(n);
          if (text.size() != 1 || text[0] < '0' || text[0] > '9')
            fail(codes::kSkipLevel, at(n),
                 absl::StrCat("block skip level '", str(text), "' is not a digit 0 to 9"));
          b.skip_level = text[0] - '0';
        }
      }
    }
    for (auto* item : ctx->item()) addItem(b, item);
    return b;
  }

  // Items and statements are told apart by their first token: dynamic_cast on every parse
  // tree node is a large part of the ANTLR runtime's cost already.
  void addItem(ast::Block& b, IsoParser::ItemContext* item) {
    switch (item->getStart()->getType()) {
      case IsoLexer::COMMENT: {
        std::string_view text = written(item->getStart());
        b.comments.emplace_back(text.substr(1, text.size() - 2));
        break;
      }
      case IsoLexer::LETTER: {
        auto* w = static_cast<IsoParser::WordItemContext*>(item);
        char letter = upper(w->getStart())[0];
        if (letter == 'N' || letter == 'O') {
          blockNumber(b, letter, at(w->getStart()), w->value());
          break;
        }
        b.words.push_back(ast::Word{ast::Address(letter), value(w->value()), at(w->getStart())});
        break;
      }
      case IsoLexer::COMMA: {
        auto* cw = static_cast<IsoParser::CommaWordItemContext*>(item);
        b.words.push_back(ast::Word{ast::Address(absl::StrCat(",", str(upper(cw->LETTER())))),
                                    value(cw->value()), at(cw->getStart())});
        break;
      }
      case IsoLexer::COLON: {
        auto* p = static_cast<IsoParser::ColonProgramItemContext*>(item);
        storeBlockNumber(b, 'O', at(p->getStart()), p->NUMBER(), nullptr);
        break;
      }
      default:
        b.statements.push_back(
            statement(static_cast<IsoParser::StatementItemContext*>(item)->statement()));
    }
  }

  void blockNumber(ast::Block& b, char letter, SourceLocation where, IsoParser::ValueContext* v) {
    storeBlockNumber(b, letter, where, v->NUMBER(), v->sign);
  }

  // N and O take an unsigned integer written as digits (no sign, point or expression).
  void storeBlockNumber(ast::Block& b, char letter, SourceLocation where,
                        antlr4::tree::TerminalNode* number, Token* sign) {
    const char* what = letter == 'N' ? "sequence number" : "program number";
    std::optional<int64_t>& slot = letter == 'N' ? b.sequence : b.program_number;
    std::string_view text = number ? upper(number) : std::string_view();
    if (!number || sign || text.find('.') != std::string_view::npos)
      fail(codes::kBlockNumber, where,
           absl::StrCat(what, " '", letter == 'N' ? "N" : "O",
                        "' needs an unsigned integer without a decimal point"));
    std::optional<int64_t> n = readInteger(text);
    if (!n) fail(codes::kNumberRange, where, absl::StrCat(what, " '", str(text), "' is too large"));
    if (slot) fail(codes::kDuplicateNumber, where, absl::StrCat("second ", what, " in one block"));
    slot = *n;
  }

  Node literal(antlr4::tree::TerminalNode* number, const Token* sign) {
    std::string_view text = upper(number);
    std::optional<NumberText> n = readNumber(text);
    if (!n)
      fail(codes::kNumberRange, at(number),
           absl::StrCat("number '", str(text.substr(0, 40)), text.size() > 40 ? "...'" : "'",
                        " is out of range"));
    bool negative = sign && sign->getType() == IsoLexer::MINUS;
    ast::Expr e = ast::Expr::literal(negative ? -n->value : n->value, n->has_point,
                                     sign ? at(sign) : at(number));
    e.digits = n->digits;
    return Node{std::move(e), 1};
  }

  Node signed_(Token* sign, Node inner) {
    if (!sign) return inner;
    ast::Expr e;
    e.kind = ast::Expr::Kind::Unary;
    e.op = sign->getType() == IsoLexer::MINUS ? ast::Op::Minus : ast::Op::Plus;
    e.loc = at(sign);
    e.args.push_back(std::move(inner.expr));
    return node(std::move(e), inner.depth + 1);
  }

  // value and target share a shape: sign? (NUMBER | variable | bracket)
  template <typename Ctx>
  Node operand(Ctx* v) {
    if (auto* n = v->NUMBER()) return literal(n, v->sign);
    if (auto* var = v->variable()) return signed_(v->sign, variable(var));
    return signed_(v->sign, bracket(v->bracket()));
  }
  ast::Expr value(IsoParser::ValueContext* v) { return operand(v).expr; }

  Node variable(IsoParser::VariableContext* v) {
    ast::Expr e;
    e.kind = ast::Expr::Kind::Variable;
    e.loc = at(v->HASH());
    Node number = v->NUMBER() ? literal(v->NUMBER(), nullptr) : expr(v->bracket()->expr());
    e.args.push_back(std::move(number.expr));
    return node(std::move(e), number.depth + 1);
  }

  Node bracket(IsoParser::BracketContext* b) {
    ast::Expr e;
    e.kind = ast::Expr::Kind::Bracket;
    e.loc = at(b->LBRACK());
    Node inner = expr(b->expr());
    e.args.push_back(std::move(inner.expr));
    return node(std::move(e), inner.depth + 1);
  }

  Node binary(Node lhs, antlr4::ParserRuleContext* op, Node rhs) {
    ast::Expr e;
    e.kind = ast::Expr::Kind::Binary;
    // The grammar's operator tokens are the table's binary operators.
    e.op = ast::opNamed(upper(op->getStart())).value_or(ast::Op::None);
    e.loc = at(op->getStart());
    e.args.push_back(std::move(lhs.expr));
    e.args.push_back(std::move(rhs.expr));
    return node(std::move(e), std::max(lhs.depth, rhs.depth) + 1);
  }

  // The three binary levels have the same shape: operand (op operand)*, left-associative.
  // The parse tree of a chain is flat; the AST is left-deep, one level per operator.
  template <typename Next, typename Ctx, typename Fn>
  Node leftAssociative(Ctx* ctx, Fn&& operandOf) {
    auto& children = ctx->children;
    Node lhs = operandOf(static_cast<Next*>(children[0]));
    for (size_t i = 1; i + 1 < children.size(); i += 2) {
      auto* op = static_cast<antlr4::ParserRuleContext*>(children[i]);
      lhs = binary(std::move(lhs), op, operandOf(static_cast<Next*>(children[i + 1])));
    }
    return lhs;
  }

  Node expr(IsoParser::ExprContext* ctx) {
    return leftAssociative<IsoParser::AdditiveContext>(
        ctx, [this](IsoParser::AdditiveContext* c) { return additive(c); });
  }
  Node additive(IsoParser::AdditiveContext* ctx) {
    return leftAssociative<IsoParser::MultiplicativeContext>(
        ctx, [this](IsoParser::MultiplicativeContext* c) { return multiplicative(c); });
  }
  Node multiplicative(IsoParser::MultiplicativeContext* ctx) {
    return leftAssociative<IsoParser::UnaryContext>(
        ctx, [this](IsoParser::UnaryContext* c) { return unary(c); });
  }

  Node unary(IsoParser::UnaryContext* ctx) {
    if (!ctx->sign) return primary(ctx->primary());
    // A sign directly before a number is part of the literal, as in a word value.
    IsoParser::UnaryContext* inner = ctx->unary();
    if (!inner->sign && inner->primary()->NUMBER())
      return literal(inner->primary()->NUMBER(), ctx->sign);
    return signed_(ctx->sign, unary(inner));
  }

  Node primary(IsoParser::PrimaryContext* ctx) {
    if (auto* n = ctx->NUMBER()) return literal(n, nullptr);
    if (auto* v = ctx->variable()) return variable(v);
    if (auto* b = ctx->bracket()) return bracket(b);
    return call(ctx->call());
  }

  Node call(IsoParser::CallContext* ctx) {
    ast::Expr e;
    e.kind = ast::Expr::Kind::Call;
    const Token* name = ctx->getStart();
    e.loc = at(name);
    const std::string fn = canonicalFunctionName(upper(name));
    // The grammar's function names are the table's functions (or their aliases).
    e.op = ast::opNamed(fn).value_or(ast::Op::None);
    int deepest = 0;
    for (auto* arg : ctx->expr()) {
      Node a = expr(arg);
      deepest = std::max(deepest, a.depth);
      e.args.push_back(std::move(a.expr));
    }
    // ATAN has one argument, or two written [a]/[b] or [a,b]; the others a fixed count.
    const size_t expected = ast::opInfo(e.op).arity;
    const bool ok = e.op == ast::Op::Atan ? e.args.size() <= 2 : e.args.size() == expected;
    if (!ok)
      fail(codes::kArity, at(name),
           e.op == ast::Op::Atan ? std::string("ATAN takes [a], [a]/[b] or [a,b]")
                                 : absl::StrCat("function '", fn, "' takes ", expected,
                                                expected == 1 ? " argument" : " arguments"));
    return node(std::move(e), deepest + 1);
  }

  ast::Statement statement(IsoParser::StatementContext* ctx) {
    ast::Statement s;
    s.loc = at(ctx->getStart());
    const size_t first = ctx->getStart()->getType();
    const bool if_then = first == IsoLexer::IF && ctx->children.size() > 2 &&
                         ctx->children[2]->getText() == "THEN";
    if (first == IsoLexer::HASH) {
      auto* a = static_cast<IsoParser::AssignStatementContext*>(ctx);
      s.kind = ast::Statement::Kind::Assign;
      s.target = variable(a->variable()).expr;
      s.value = expr(a->expr()).expr;
    } else if (first == IsoLexer::GOTO) {
      auto* g = static_cast<IsoParser::GotoStatementContext*>(ctx);
      s.kind = ast::Statement::Kind::Goto;
      s.target = operand(g->target()).expr;
    } else if (first == IsoLexer::IF && !if_then) {
      auto* ig = static_cast<IsoParser::IfGotoStatementContext*>(ctx);
      s.kind = ast::Statement::Kind::IfGoto;
      s.value = expr(ig->bracket()->expr()).expr;
      s.target = operand(ig->target()).expr;
    } else if (if_then) {
      auto* it = static_cast<IsoParser::IfThenStatementContext*>(ctx);
      s.kind = ast::Statement::Kind::IfThen;
      s.value = expr(it->bracket()->expr()).expr;
      ast::Statement& then = s.then_assign.emplace();
      then.kind = ast::Statement::Kind::Assign;
      then.loc = at(it->variable()->HASH());
      then.target = variable(it->variable()).expr;
      then.value = expr(it->expr()).expr;
    } else if (first == IsoLexer::WHILE) {
      auto* w = static_cast<IsoParser::WhileStatementContext*>(ctx);
      s.kind = ast::Statement::Kind::While;
      s.value = expr(w->bracket()->expr()).expr;
      s.loop_id = loopId(w->NUMBER());
    } else {
      auto* e = static_cast<IsoParser::EndStatementContext*>(ctx);
      s.kind = ast::Statement::Kind::End;
      s.loop_id = loopId(e->NUMBER());
    }
    return s;
  }

  int loopId(antlr4::tree::TerminalNode* n) {
    std::optional<int64_t> id;
    if (upper(n).find('.') == std::string_view::npos) id = readInteger(upper(n));
    if (!id || *id > INT_MAX)
      fail(codes::kLoopId, at(n),
           absl::StrCat("loop identifier '", str(upper(n)), "' is not an integer"));
    return static_cast<int>(*id);
  }

};

}  // namespace

struct AntlrBlockParser::Engine : AntlrEngine<IsoLexer, IsoParser> {};

AntlrBlockParser::AntlrBlockParser() : engine_(std::make_unique<Engine>()) {}
AntlrBlockParser::~AntlrBlockParser() = default;

std::optional<ast::Block> AntlrBlockParser::parse(std::string_view text, SourceLocation start,
                                                  DiagnosticEngine& diags) {
  Engine& e = *engine_;
  const std::vector<Token*> tokens = e.lex(text);
  Builder builder(text, e.upper, start, diags);
  std::optional<ast::Block> result;
  try {
    builder.checkTokens(tokens);
    Token* offending = nullptr;
    IsoParser::BlockContext* tree = e.parse(offending);
    if (!tree) builder.failAt(offending);
    result = builder.block(tree);
  } catch (const BlockRejected&) {
    result.reset();
  }
  e.reset();
  return result;
}

}  // namespace ncc::frontend
