#include "din_block_parser.h"

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "DinLexer.h"
#include "DinParser.h"
#include "absl/strings/str_cat.h"
#include "antlr4-runtime.h"
#include "antlr_support.h"
#include "diagnostic_codes.h"
#include "lexical.h"
#include "number_text.h"

namespace ncc::frontend {

namespace {

using antlr4::Token;
using ncc_din::DinLexer;
using ncc_din::DinParser;
using Kind = ast::Expr::Kind;
using SKind = ast::Statement::Kind;

std::string str(std::string_view s) { return std::string(s); }

// SET and SPRINT take a list: as many values as an array has elements (NamedVariables::kMaxElements).
constexpr uint16_t kManyArguments = 65535;

// The DIN functions ncc evaluates (Programming Manual Fundamentals, arithmetic functions;
// Job Planning, string functions), with the argument counts they take.
struct DinFunction {
  const char* name;
  ast::Op op;
  uint16_t min_args = 1;
  uint16_t max_args = 1;
  bool omissions = false;  // an argument may be left out (SET(1,,3))
};
constexpr std::array kFunctions = {
    DinFunction{"SIN", ast::Op::Sin},       DinFunction{"COS", ast::Op::Cos},
    DinFunction{"TAN", ast::Op::Tan},       DinFunction{"ASIN", ast::Op::Asin},
    DinFunction{"ACOS", ast::Op::Acos},     DinFunction{"ATAN2", ast::Op::Atan2, 2, 2},
    DinFunction{"SQRT", ast::Op::Sqrt},     DinFunction{"ABS", ast::Op::Abs},
    DinFunction{"POT", ast::Op::Pot},       DinFunction{"TRUNC", ast::Op::Trunc},
    DinFunction{"ROUND", ast::Op::Round},   DinFunction{"LN", ast::Op::Ln},
    DinFunction{"EXP", ast::Op::Exp},       DinFunction{"MINVAL", ast::Op::MinVal, 2, 2},
    DinFunction{"MAXVAL", ast::Op::MaxVal, 2, 2}, DinFunction{"IC", ast::Op::Ic},
    DinFunction{"AC", ast::Op::Ac},
    DinFunction{"STRLEN", ast::Op::StrLen},  DinFunction{"INDEX", ast::Op::Index, 2, 2},
    DinFunction{"RINDEX", ast::Op::RIndex, 2, 2}, DinFunction{"MINDEX", ast::Op::MIndex, 2, 2},
    DinFunction{"MATCH", ast::Op::Match, 2, 2}, DinFunction{"SUBSTR", ast::Op::SubStr, 2, 3},
    DinFunction{"TOUPPER", ast::Op::ToUpper}, DinFunction{"TOLOWER", ast::Op::ToLower},
    DinFunction{"NUMBER", ast::Op::Number},  DinFunction{"ISNUMBER", ast::Op::IsNumber},
    DinFunction{"SPRINT", ast::Op::Sprint, 1, kManyArguments},
    DinFunction{"SET", ast::Op::Set, 1, kManyArguments, true}, DinFunction{"REP", ast::Op::Rep, 1, 2},
};

ast::DataType typeNamed(std::string_view name) {
  for (size_t i = 1; i < ast::kDataTypeNames.size(); ++i)
    if (name == ast::kDataTypeNames[i]) return static_cast<ast::DataType>(i);
  return ast::DataType::None;
}

// Variable names: letters, digits and '_', at most 31 (Fundamentals, variable names).
constexpr size_t kMaxNameLength = 31;

// R parameters are `R` and a number (R0 .. R99 on a standard 840D; machine data raises it).
bool isRParameter(std::string_view s) {
  if (s.size() < 2 || s[0] != 'R') return false;
  return std::all_of(s.begin() + 1, s.end(), isDigit);
}

class Builder : public BlockText {
 public:
  using BlockText::BlockText;

  [[noreturn]] void notYet(SourceLocation where, std::string_view what) {
    fail(codes::kDinNotSupported, where,
         absl::StrCat("DIN ", str(what), " is not supported yet (docs/din.md lists what is)"));
  }

  // ---- checks on the token list, before parsing ------------------------------------------

  void checkTokens(const std::vector<Token*>& tokens) {
    for (const Token* t : tokens) {
      if (t->getType() == DinLexer::ERROR_CHAR)
        fail(codes::kUnexpectedChar, at(t),
             absl::StrCat("unexpected character ", describeChar(original_[t->getStartIndex()])));
      if (t->getType() == DinLexer::OPEN_STRING)
        fail(codes::kUnclosedString, at(t), "string '\"' is not closed by '\"'");
    }
    // The parser recurses once per sign and a few times per bracket: bound both before it runs.
    int open = 0;
    int signs = 0;
    std::vector<const Token*> brackets;
    for (const Token* t : tokens) {
      const size_t type = t->getType();
      signs = (type == DinLexer::PLUS || type == DinLexer::MINUS || type == DinLexer::NOT ||
               type == DinLexer::B_NOT)
                  ? signs + 1
                  : 0;
      if (signs > kMaxNesting)
        fail(codes::kNesting, at(t), absl::StrCat("more than ", kMaxNesting, " signs in a row"));
      if (type == DinLexer::LPAREN || type == DinLexer::LBRACK) {
        brackets.push_back(t);
        if (++open > kMaxNesting)
          fail(codes::kNesting, at(t),
               absl::StrCat("brackets nested deeper than ", kMaxNesting, " levels"));
      } else if (type == DinLexer::RPAREN || type == DinLexer::RBRACK) {
        const char closing = type == DinLexer::RPAREN ? ')' : ']';
        if (brackets.empty() || (brackets.back()->getType() == DinLexer::LPAREN) != (closing == ')'))
          fail(codes::kUnopenedBracket, at(t), absl::StrCat("unbalanced '", std::string(1, closing), "'"));
        brackets.pop_back();
        --open;
      }
    }
    if (!brackets.empty())
      fail(codes::kUnclosedBracket, at(brackets.front()),
           absl::StrCat("unbalanced '", brackets.front()->getType() == DinLexer::LPAREN ? "(" : "[",
                        "'"));
  }

  [[noreturn]] void failAt(const Token* t) {
    switch (t->getType()) {
      case Token::EOF:
        fail(codes::kIncomplete, at(t), "block ends before the statement is complete");
      case DinLexer::SLASH:
        fail(codes::kSkipNotAtStart, at(t), "block skip '/' must be at the start of the block");
      case DinLexer::NUMBER:
        fail(codes::kUnexpectedToken, at(t),
             absl::StrCat("number '", str(written(t)), "' has no address"));
      default:
        fail(codes::kUnexpectedToken, at(t), absl::StrCat("unexpected '", str(written(t)), "'"));
    }
  }

  // ---- the block -------------------------------------------------------------------------

  void block(DinParser::BlockContext* ctx, ast::Block& b) {
    b.loc = start_;
    b.language = Language::Din;
    if (auto* s = ctx->blockStart()) {
      b.skip_level = 1;
      if (auto* n = s->NUMBER()) {
        std::string_view text = upper(n);
        if (text.size() != 1 || !isDigit(text[0]))
          fail(codes::kSkipLevel, at(n),
               absl::StrCat("block skip level '", str(text), "' is not a digit 0 to 9"));
        b.skip_level = text[0] - '0';
      }
    }
    const std::vector<DinParser::ItemContext*> items = ctx->item();
    for (size_t i = 0; i < items.size(); ++i) item(b, items[i], i == 0);
    structureAlone(b);
  }

  static bool isStructure(SKind k) {
    switch (k) {
      case SKind::If: case SKind::Else: case SKind::EndIf: case SKind::While:
      case SKind::EndWhile: case SKind::For: case SKind::EndFor: case SKind::Repeat:
      case SKind::Until: case SKind::Loop: case SKind::EndLoop: case SKind::Case:
      case SKind::Proc: case SKind::Return: case SKind::RepeatSection:
        return true;
      default:
        return false;
    }
  }

  // A control structure's keyword stands alone in its block, with the block number and labels
  // (Job Planning, program flow control: the structures are executed by the interpreter, not
  // by the block's motion): `IF A>1 X10` is refused rather than half-read. So do PROC and RET.
  void structureAlone(const ast::Block& b) {
    const ast::Statement* structure = nullptr;
    for (const ast::Statement& st : b.statements)
      if (isStructure(st.kind)) structure = &st;
    if (!structure) return;
    SourceLocation other{};
    bool found = false;
    auto consider = [&](SourceLocation loc) {
      if (!found || loc.column < other.column) other = loc;
      found = true;
    };
    for (const ast::Word& w : b.words) consider(w.loc);
    for (const ast::Statement& st : b.statements)
      if (&st != structure && st.kind != SKind::Label && st.kind != SKind::CaseBranch &&
          st.kind != SKind::Parameter)
        consider(st.loc);
    if (!found) return;
    fail(codes::kUnexpectedToken, other,
         absl::StrCat("a control structure keyword (", structureName(structure->kind),
                      ") stands alone in its block, with its block number and labels"));
  }

  static const char* structureName(SKind k) {
    switch (k) {
      case SKind::If: return "IF";
      case SKind::Else: return "ELSE";
      case SKind::EndIf: return "ENDIF";
      case SKind::While: return "WHILE";
      case SKind::EndWhile: return "ENDWHILE";
      case SKind::For: return "FOR";
      case SKind::EndFor: return "ENDFOR";
      case SKind::Repeat: return "REPEAT";
      case SKind::Until: return "UNTIL";
      case SKind::Loop: return "LOOP";
      case SKind::EndLoop: return "ENDLOOP";
      case SKind::Proc: return "PROC";
      case SKind::Return: return "RET";
      case SKind::RepeatSection: return "REPEAT";
      default: return "CASE";
    }
  }

  ast::Statement& statement(ast::Block& b, SKind kind, const Token* t) {
    ast::Statement& s = b.statements.emplace_back();
    s.kind = kind;
    s.loc = at(t);
    return s;
  }

  void item(ast::Block& b, DinParser::ItemContext* ctx, bool first) {
    if (auto* w = dynamic_cast<DinParser::WordItemContext*>(ctx)) {
      word(b, w->WORD()->getSymbol(), first);
    } else if (auto* a = dynamic_cast<DinParser::AssignItemContext*>(ctx)) {
      assign(b, a);
    } else if (auto* sw = dynamic_cast<DinParser::SignedWordItemContext*>(ctx)) {
      std::string_view address = upper(sw->IDENT());
      if (address.size() != 1)
        fail(codes::kUnexpectedToken, at(sw->IDENT()),
             absl::StrCat("address '", str(address), "' takes its value after '='"));
      ast::Word& w = b.words.emplace_back();
      w.address = ast::Address(address[0]);
      w.loc = at(sw->IDENT());
      w.value = literal(sw->NUMBER()->getSymbol(), 0, sw->sign).expr;
    } else if (auto* l = dynamic_cast<DinParser::LabelItemContext*>(ctx)) {
      ast::Statement& s = b.statements.emplace_back();
      s.kind = SKind::Label;
      s.loc = at(l->IDENT());
      s.target = name(l->IDENT()->getSymbol());
    } else if (auto* d = dynamic_cast<DinParser::DefItemContext*>(ctx)) {
      define(b, d);
    } else if (auto* g = dynamic_cast<DinParser::GotoItemContext*>(ctx)) {
      ast::Statement& s = b.statements.emplace_back();
      s.kind = SKind::Goto;
      s.loc = at(g->getStart());
      jump(s, g->jump(), g->jumpTarget());
    } else if (auto* ig = dynamic_cast<DinParser::IfGotoItemContext*>(ctx)) {
      ast::Statement& s = b.statements.emplace_back();
      s.kind = SKind::IfGoto;
      s.loc = at(ig->IF());
      s.value = expr(ig->expr()).expr;
      jump(s, ig->jump(), ig->jumpTarget());
    } else if (auto* i = dynamic_cast<DinParser::IfItemContext*>(ctx)) {
      statement(b, SKind::If, i->IF()->getSymbol()).value = expr(i->expr()).expr;
    } else if (auto* w = dynamic_cast<DinParser::WhileItemContext*>(ctx)) {
      statement(b, SKind::While, w->WHILE()->getSymbol()).value = expr(w->expr()).expr;
    } else if (auto* u = dynamic_cast<DinParser::UntilItemContext*>(ctx)) {
      statement(b, SKind::Until, u->UNTIL()->getSymbol()).value = expr(u->expr()).expr;
    } else if (auto* f = dynamic_cast<DinParser::ForItemContext*>(ctx)) {
      forLoop(b, f);
    } else if (auto* cs = dynamic_cast<DinParser::CaseItemContext*>(ctx)) {
      caseOf(b, cs);
    } else if (auto* pr = dynamic_cast<DinParser::ProcItemContext*>(ctx)) {
      proc(b, pr);
    } else if (dynamic_cast<DinParser::RetItemContext*>(ctx)) {
      statement(b, SKind::Return, ctx->getStart());
    } else if (dynamic_cast<DinParser::ElseItemContext*>(ctx)) {
      statement(b, SKind::Else, ctx->getStart());
    } else if (dynamic_cast<DinParser::EndIfItemContext*>(ctx)) {
      statement(b, SKind::EndIf, ctx->getStart());
    } else if (dynamic_cast<DinParser::EndWhileItemContext*>(ctx)) {
      statement(b, SKind::EndWhile, ctx->getStart());
    } else if (dynamic_cast<DinParser::EndForItemContext*>(ctx)) {
      statement(b, SKind::EndFor, ctx->getStart());
    } else if (auto* rs = dynamic_cast<DinParser::RepeatSectionItemContext*>(ctx)) {
      repeatSection(b, rs);
    } else if (dynamic_cast<DinParser::RepeatItemContext*>(ctx)) {
      if (upper(ctx->getStart()) == "REPEATB")
        fail(codes::kUnexpectedToken, at(ctx->getStart()),
             "REPEATB takes the label of the block to repeat: REPEATB LABEL P=n");
      statement(b, SKind::Repeat, ctx->getStart());
    } else if (dynamic_cast<DinParser::LoopItemContext*>(ctx)) {
      statement(b, SKind::Loop, ctx->getStart());
    } else if (dynamic_cast<DinParser::EndLoopItemContext*>(ctx)) {
      statement(b, SKind::EndLoop, ctx->getStart());
    } else if (auto* c = dynamic_cast<DinParser::CallItemContext*>(ctx)) {
      call(b, c->IDENT()->getSymbol(), c->arguments());
    } else if (auto* ws = dynamic_cast<DinParser::WordsItemContext*>(ctx)) {
      wordsRun(b, ws->WORDS()->getSymbol(), first);
    } else if (auto* n = dynamic_cast<DinParser::NameItemContext*>(ctx)) {
      call(b, n->IDENT()->getSymbol(), nullptr);
    } else if (auto* m = dynamic_cast<DinParser::MainBlockItemContext*>(ctx)) {
      // A main block `:10` is numbered like an N block (Fundamentals, block structure).
      sequence(b, at(m->COLON()), upper(m->NUMBER()));
    }
  }

  // `X100`, `G1`, `N10`: a letter and its number. N numbers the block: it comes first.
  void word(ast::Block& b, const Token* t, bool first) {
    std::string_view text = upper(t);
    if (text[0] == 'N') {
      numberFirst(b, at(t), first);
      sequence(b, at(t), text.substr(1));
      return;
    }
    ast::Word& w = b.words.emplace_back();
    w.address = ast::Address(text[0]);
    w.loc = at(t);
    w.value = literal(t, 1, nullptr).expr;
  }

  // `G1X10.Y5`: words without blanks between them.
  void wordsRun(ast::Block& b, const Token* t, bool first) {
    std::string_view text = upper(t);
    size_t i = 0;
    while (i < text.size()) {
      size_t end = i + 1;
      while (end < text.size() && (isDigit(text[end]) || text[end] == '.')) ++end;
      const SourceLocation where = at(t->getStartIndex() + i);
      std::string_view digits = text.substr(i + 1, end - i - 1);
      if (text[i] == 'N') {
        numberFirst(b, where, first && i == 0);
        sequence(b, where, digits);
      } else {
        ast::Word& w = b.words.emplace_back();
        w.address = ast::Address(text[i]);
        w.loc = where;
        w.value = number(digits, at(t->getStartIndex() + i + 1), false).expr;
      }
      i = end;
    }
  }

  void numberFirst(const ast::Block& b, SourceLocation where, bool first) {
    if (b.sequence) fail(codes::kDuplicateNumber, where, "second block number in one block");
    if (!first)
      fail(codes::kUnexpectedToken, where, "a block number 'N' must start the block");
  }

  void sequence(ast::Block& b, SourceLocation where, std::string_view digits) {
    if (digits.find('.') != std::string_view::npos)
      fail(codes::kBlockNumber, where, "block number 'N' needs an unsigned integer without a decimal point");
    std::optional<int64_t> n = readInteger(digits);
    if (!n) fail(codes::kNumberRange, where, absl::StrCat("block number '", str(digits), "' is too large"));
    if (b.sequence) fail(codes::kDuplicateNumber, where, "second block number in one block");
    b.sequence = *n;
  }

  // `name = expr`: an R parameter or array element is assigned; a name that fits an address
  // is a word (`X=R1+5`, `CR=25`, `COUNT=COUNT+1`): evaluation tells a variable from an
  // address, since only it knows what DEF declared.
  void assign(ast::Block& b, DinParser::AssignItemContext* a) {
    DinParser::NameContext* n = a->name();
    const Token* t = n->getStart();
    std::string_view text = upper(t);
    if (t->getType() == DinLexer::WORD && !isRParameter(text) &&
        text.find('.') != std::string_view::npos)
      fail(codes::kUnexpectedToken, at(t), absl::StrCat("'", str(text), "' is not a name"));
    Node value = expr(a->expr());
    if (n->LBRACK() || isRParameter(text) || text.size() > ast::Address::kCapacity) {
      ast::Statement& s = b.statements.emplace_back();
      s.kind = SKind::Assign;
      s.loc = at(t);
      s.target = target(n);
      s.value = std::move(value.expr);
      return;
    }
    ast::Word& w = b.words.emplace_back();
    w.address = ast::Address(text);
    w.loc = at(t);
    w.value = std::move(value.expr);
  }

  // A name as a variable: `R10`, `R[i]`, `COUNT`, `A[i,j]`, `$AA_IW[X]`.
  ast::Expr target(DinParser::NameContext* n) {
    const Token* t = n->getStart();
    std::string_view text = upper(t);
    std::vector<DinParser::ExprContext*> indices = n->expr();
    if (isRParameter(text) && indices.empty()) {
      ast::Expr e;
      e.kind = Kind::RParam;
      e.loc = at(t);
      e.args.push_back(number(text.substr(1), at(t->getStartIndex() + 1), false).expr);
      return e;
    }
    if (text == "R" && indices.size() == 1) {
      ast::Expr e;
      e.kind = Kind::RParam;
      e.loc = at(t);
      e.args.push_back(expr(indices[0]).expr);
      return e;
    }
    if (t->getType() == DinLexer::WORD && text.find('.') != std::string_view::npos)
      fail(codes::kUnexpectedToken, at(t), absl::StrCat("'", str(text), "' is not a name"));
    ast::Expr e = name(t);
    for (DinParser::ExprContext* i : indices) e.args.push_back(expr(i).expr);
    if (e.args.size() > 3)
      fail(codes::kArity, at(t), absl::StrCat("'", str(text), "': arrays have at most 3 dimensions"));
    return e;
  }

  // "text": as written, without its quotes.
  ast::Expr stringLiteral(const Token* t) {
    ast::Expr e;
    e.kind = Kind::String;
    e.loc = at(t);
    std::string_view text = written(t);
    e.text = std::string(text.substr(1, text.size() - 2));
    return e;
  }

  ast::Expr name(const Token* t) {
    ast::Expr e;
    e.kind = Kind::Name;
    e.loc = at(t);
    e.text = std::string(upper(t));
    return e;
  }

  void define(ast::Block& b, DinParser::DefItemContext* d) {
    DinParser::TypeNameContext* tn = d->typeName();
    const ast::DataType type = typeNamed(upper(tn->IDENT()));
    if (type == ast::DataType::None)
      fail(codes::kUnknownType, at(tn->IDENT()),
           absl::StrCat("unknown type '", str(upper(tn->IDENT())),
                        "' (INT, REAL, BOOL, CHAR, STRING[n], AXIS, FRAME)"));
    const int length = stringLength(tn, type);
    for (DinParser::DefinitionContext* def : d->definition()) {
      ast::Statement& s = b.statements.emplace_back();
      s.kind = SKind::Define;
      s.loc = at(def->IDENT());
      s.type = type;
      s.length = length;
      s.target = name(def->IDENT()->getSymbol());
      if (s.target.text->size() > kMaxNameLength)
        fail(codes::kUnexpectedToken, at(def->IDENT()),
             absl::StrCat("'", *s.target.text, "': a name has at most ", kMaxNameLength,
                          " characters"));
      std::vector<DinParser::ExprContext*> exprs = def->expr();
      const size_t dims = exprs.size() - (def->EQUALS() ? 1 : 0);
      if (dims > 3)
        fail(codes::kArity, at(def->IDENT()), "arrays have at most 3 dimensions");
      for (size_t i = 0; i < dims; ++i) s.target.args.push_back(expr(exprs[i]).expr);
      if (def->EQUALS()) {
        s.value = expr(exprs.back()).expr;
      } else {
        s.value.kind = Kind::Vacant;  // no initial value: the type's zero
        s.value.loc = s.loc;
      }
    }
  }

  // STRING[n]: n characters at most, 1 to 200 (Job Planning, variable types: STRING); the
  // other types take no length.
  int stringLength(DinParser::TypeNameContext* tn, ast::DataType type) {
    if (type != ast::DataType::String) {
      if (tn->LBRACK())
        fail(codes::kUnexpectedToken, at(tn->LBRACK()), "only STRING takes a length [n]");
      return 0;
    }
    if (!tn->NUMBER())
      fail(codes::kUnexpectedToken, at(tn->IDENT()),
           absl::StrCat("STRING takes its length: STRING[n], n from 1 to ", ast::kMaxStringLength));
    std::string_view text = upper(tn->NUMBER());
    int n = 0;
    for (char c : text) n = isDigit(c) && n <= ast::kMaxStringLength ? n * 10 + (c - '0') : 1 << 20;
    if (n < 1 || n > ast::kMaxStringLength)
      fail(codes::kNumberRange, at(tn->NUMBER()),
           absl::StrCat("STRING[", str(text), "]: a string holds 1 to ", ast::kMaxStringLength,
                        " characters"));
    return n;
  }

  void jump(ast::Statement& s, DinParser::JumpContext* j, DinParser::JumpTargetContext* t) {
    switch (j->getStart()->getType()) {
      case DinLexer::GOTOF: s.jump = ast::Jump::Forward; break;
      case DinLexer::GOTOB: s.jump = ast::Jump::Backward; break;
      case DinLexer::GOTO: s.jump = ast::Jump::Both; break;
      default: s.jump = ast::Jump::BothQuiet; break;
    }
    if (auto* id = t->IDENT()) {
      s.target = name(id->getSymbol());
    } else if (auto* w = t->WORD()) {
      std::string_view text = upper(w);
      if (text[0] != 'N' || text.find('.') != std::string_view::npos)
        fail(codes::kUnexpectedToken, at(w),
             absl::StrCat("'", str(text), "' is neither a label nor a block number"));
      s.target = number(text.substr(1), at(w->getSymbol()->getStartIndex() + 1), false).expr;
    } else {
      if (upper(t->NUMBER()).find('.') != std::string_view::npos)
        fail(codes::kBlockNumber, at(t->NUMBER()), "a block number has no decimal point");
      s.target = literal(t->NUMBER()->getSymbol(), 0, nullptr).expr;
    }
  }

  // REPEAT START [END] [P=n], REPEATB LABEL [P=n]: the labels and the count.
  void repeatSection(ast::Block& b, DinParser::RepeatSectionItemContext* r) {
    const Token* keyword = r->REPEAT()->getSymbol();
    ast::Statement& s = statement(b, SKind::RepeatSection, keyword);
    s.loop_id = upper(keyword) == "REPEATB" ? 1 : 0;
    s.target = name(r->start);
    if (r->end) {
      if (s.loop_id == 1)
        fail(codes::kUnexpectedToken, at(r->end), "REPEATB repeats one block: it takes one label");
      s.target.args.push_back(name(r->end));
    }
    if (r->count) {
      if (upper(r->count) != "P")
        fail(codes::kUnexpectedToken, at(r->count),
             absl::StrCat("'", str(upper(r->count)), "=': the repeat count is P=n"));
      s.value = expr(r->expr()).expr;
    } else {
      s.value.kind = Kind::Vacant;
      s.value.loc = s.loc;
    }
  }

  // FOR COUNTER = 0 TO NUMBER: the counter is an R parameter or a variable.
  void forLoop(ast::Block& b, DinParser::ForItemContext* f) {
    DinParser::NameContext* n = f->name();
    ast::Statement& s = statement(b, SKind::For, f->FOR()->getSymbol());
    ast::Statement& init = s.then_assign.emplace();
    init.kind = SKind::Assign;
    init.loc = at(n->getStart());
    init.target = target(n);
    init.value = expr(f->expr(0)).expr;
    s.value = expr(f->expr(1)).expr;
  }

  // CASE (expr) OF 7 GOTOF L1 9 GOTOF L2 DEFAULT GOTOF L3: the Case statement, then a branch
  // per constant, DEFAULT's with a vacant constant.
  void caseOf(ast::Block& b, DinParser::CaseItemContext* c) {
    statement(b, SKind::Case, c->CASE()->getSymbol()).value = expr(c->expr()).expr;
    for (DinParser::CaseBranchContext* br : c->caseBranch()) {
      ast::Statement& s = statement(b, SKind::CaseBranch, br->getStart());
      s.value = br->STRING() ? stringLiteral(br->STRING()->getSymbol())
                             : literal(br->NUMBER()->getSymbol(), 0, br->sign).expr;
      jump(s, br->jump(), br->jumpTarget());
    }
    if (c->DEFAULT()) {
      ast::Statement& s = statement(b, SKind::CaseBranch, c->DEFAULT()->getSymbol());
      s.value.kind = Kind::Vacant;
      s.value.loc = s.loc;
      jump(s, c->jump(), c->jumpTarget());
    }
  }

  // PROC NAME(REAL A, VAR INT B) DISPLOF: the Proc statement, then one Parameter each.
  void proc(ast::Block& b, DinParser::ProcItemContext* p) {
    ast::Statement& s = statement(b, SKind::Proc, p->PROC()->getSymbol());
    s.target = name(p->procName);
    for (DinParser::ParameterContext* param : p->parameter()) {
      DinParser::TypeNameContext* tn = param->typeName();
      const ast::DataType type = typeNamed(upper(tn->IDENT()));
      if (type == ast::DataType::None)
        fail(codes::kUnknownType, at(tn->IDENT()),
             absl::StrCat("unknown type '", str(upper(tn->IDENT())),
                          "' (INT, REAL, BOOL, CHAR, STRING[n], AXIS, FRAME)"));
      if (param->LBRACK()) notYet(at(param->LBRACK()), "array parameters of a PROC");
      ast::Statement& ps = statement(b, SKind::Parameter, param->IDENT()->getSymbol());
      ps.type = type;
      ps.length = stringLength(tn, type);
      ps.loop_id = param->VAR() ? 1 : 0;
      ps.target = name(param->IDENT()->getSymbol());
    }
    // Attributes: what the operator panel shows and single-block stops, which a run does not
    // have; SAVE (modal settings and frames restored on return) is not built yet.
    for (const Token* a : p->attributes) {
      const std::string_view attribute = upper(a);
      if (attribute == "SAVE")
        notYet(at(a), "'PROC ... SAVE' (restoring modal settings and frames on return)");
      if (attribute != "DISPLOF" && attribute != "DISPLON" && attribute != "SBLOF" &&
          attribute != "SBLON" && attribute != "ACTBLOCNO")
        fail(codes::kUnexpectedToken, at(a),
             absl::StrCat("'", str(attribute),
                          "' is not a PROC attribute (SAVE, DISPLOF, DISPLON, SBLOF, SBLON, ACTBLOCNO)"));
    }
  }

  // A subprogram called by name, with its arguments (`POSITION1 (10, 20)`, `MYKONTUR`).
  void call(ast::Block& b, const Token* t, DinParser::ArgumentsContext* args) {
    ast::Statement& s = b.statements.emplace_back();
    s.kind = SKind::Call;
    s.loc = at(t);
    s.target = name(t);
    if (args) s.target.args = arguments(args);
  }

  std::vector<ast::Expr> arguments(DinParser::ArgumentsContext* ctx) {
    std::vector<ast::Expr> out;
    std::vector<DinParser::ArgumentContext*> list = ctx->argument();
    if (list.size() == 1 && !list[0]->expr()) return out;  // F(): none
    for (DinParser::ArgumentContext* a : list) {
      if (a->expr()) {
        out.push_back(expr(a->expr()).expr);
      } else {
        ast::Expr& omitted = out.emplace_back();
        omitted.kind = Kind::Vacant;
        omitted.loc = at(a->getStart());
      }
    }
    return out;
  }

  // ---- expressions -----------------------------------------------------------------------

  struct Node {
    ast::Expr expr;
    int depth = 1;
  };
  Node node(ast::Expr e, int depth) {
    if (depth > ast::kMaxExprDepth) fail(codes::kExprDepth, e.loc, tooDeep());
    return Node{std::move(e), depth};
  }

  Node number(std::string_view text, SourceLocation where, bool negative) {
    std::optional<NumberText> n = readNumber(text);
    if (!n)
      fail(codes::kNumberRange, where,
           absl::StrCat("number '", str(text.substr(0, 40)), text.size() > 40 ? "...'" : "'",
                        " is out of range"));
    ast::Expr e = ast::Expr::literal(negative ? -n->value : n->value, n->has_point, where);
    e.digits = n->digits;
    return Node{std::move(e), 1};
  }
  // The number of token `t` from character `skip` on (a WORD's after its letter).
  Node literal(const Token* t, size_t skip, const Token* sign) {
    const bool negative = sign && sign->getType() == DinLexer::MINUS;
    return number(upper(t).substr(skip), sign ? at(sign) : at(t->getStartIndex() + skip), negative);
  }

  static const Token* firstToken(antlr4::tree::ParseTree* t) {
    if (auto* terminal = dynamic_cast<antlr4::tree::TerminalNode*>(t)) return terminal->getSymbol();
    return static_cast<antlr4::ParserRuleContext*>(t)->getStart();
  }

  ast::Op binaryOp(const Token* t) {
    switch (t->getType()) {
      case DinLexer::EQEQ: return ast::Op::Eq;
      case DinLexer::NOTEQ: return ast::Op::Ne;
      case DinLexer::LESS: return ast::Op::Lt;
      case DinLexer::GREATER: return ast::Op::Gt;
      case DinLexer::LESSEQ: return ast::Op::Le;
      case DinLexer::GREATEREQ: return ast::Op::Ge;
      case DinLexer::CONCAT: return ast::Op::Concat;
      default: return ast::opNamed(upper(t)).value_or(ast::Op::None);  // + - * / DIV MOD OR ...
    }
  }

  // Every binary level: operand (op operand)*, left-associative, a left-deep tree.
  template <typename Fn>
  Node chain(antlr4::ParserRuleContext* ctx, Fn&& operand) {
    auto& children = ctx->children;
    Node lhs = operand(children[0]);
    for (size_t i = 1; i + 1 < children.size(); i += 2) {
      const Token* op = firstToken(children[i]);
      Node rhs = operand(children[i + 1]);
      ast::Expr e;
      e.kind = Kind::Binary;
      e.op = binaryOp(op);
      e.loc = at(op);
      const int depth = std::max(lhs.depth, rhs.depth) + 1;
      e.args.push_back(std::move(lhs.expr));
      e.args.push_back(std::move(rhs.expr));
      lhs = node(std::move(e), depth);
    }
    return lhs;
  }

  Node expr(DinParser::ExprContext* c) {
    return chain(c, [this](auto* t) { return concat(static_cast<DinParser::ConcatContext*>(t)); });
  }
  Node concat(DinParser::ConcatContext* c) {
    return chain(c, [this](auto* t) { return orExpr(static_cast<DinParser::OrExprContext*>(t)); });
  }
  Node orExpr(DinParser::OrExprContext* c) {
    return chain(c, [this](auto* t) { return xorExpr(static_cast<DinParser::XorExprContext*>(t)); });
  }
  Node xorExpr(DinParser::XorExprContext* c) {
    return chain(c, [this](auto* t) { return andExpr(static_cast<DinParser::AndExprContext*>(t)); });
  }
  Node andExpr(DinParser::AndExprContext* c) {
    return chain(c, [this](auto* t) { return bOr(static_cast<DinParser::BOrExprContext*>(t)); });
  }
  Node bOr(DinParser::BOrExprContext* c) {
    return chain(c, [this](auto* t) { return bXor(static_cast<DinParser::BXorExprContext*>(t)); });
  }
  Node bXor(DinParser::BXorExprContext* c) {
    return chain(c, [this](auto* t) { return bAnd(static_cast<DinParser::BAndExprContext*>(t)); });
  }
  Node bAnd(DinParser::BAndExprContext* c) {
    return chain(c, [this](auto* t) { return additive(static_cast<DinParser::AdditiveContext*>(t)); });
  }
  Node additive(DinParser::AdditiveContext* c) {
    return chain(c, [this](auto* t) {
      return multiplicative(static_cast<DinParser::MultiplicativeContext*>(t));
    });
  }
  Node multiplicative(DinParser::MultiplicativeContext* c) {
    return chain(c, [this](auto* t) { return unary(static_cast<DinParser::UnaryContext*>(t)); });
  }

  Node unary(DinParser::UnaryContext* c) {
    if (!c->op) return primary(c->primary());
    DinParser::UnaryContext* inner = c->unary();
    const size_t type = c->op->getType();
    // A sign directly before a number is part of the literal, as in a word value (X=-1.5).
    if ((type == DinLexer::PLUS || type == DinLexer::MINUS) && !inner->op &&
        inner->primary()->NUMBER())
      return literal(inner->primary()->NUMBER()->getSymbol(), 0, c->op);
    Node operand = unary(inner);
    ast::Expr e;
    e.kind = Kind::Unary;
    e.op = type == DinLexer::MINUS  ? ast::Op::Minus
           : type == DinLexer::PLUS ? ast::Op::Plus
           : type == DinLexer::NOT  ? ast::Op::Not
                                    : ast::Op::BNot;
    e.loc = at(c->op);
    e.args.push_back(std::move(operand.expr));
    return node(std::move(e), operand.depth + 1);
  }

  Node primary(DinParser::PrimaryContext* c) {
    if (auto* n = c->NUMBER()) return literal(n->getSymbol(), 0, nullptr);
    if (auto* s = c->STRING()) return Node{stringLiteral(s->getSymbol()), 1};
    if (c->LPAREN() && c->expr()) {
      Node inner = expr(c->expr());
      ast::Expr e;
      e.kind = Kind::Bracket;
      e.loc = at(c->LPAREN());
      e.args.push_back(std::move(inner.expr));
      return node(std::move(e), inner.depth + 1);
    }
    if (c->LPAREN()) return function(c->IDENT()->getSymbol(), c->arguments());
    DinParser::NameContext* n = c->name();
    std::string_view text = upper(n->getStart());
    if (n->expr().empty() && (text == "TRUE" || text == "FALSE"))
      return Node{ast::Expr::literal(text == "TRUE" ? 1.0 : 0.0, false, at(n->getStart())), 1};
    ast::Expr e = target(n);
    int depth = 1;
    for (const ast::Expr& a : e.args) depth = std::max(depth, exprDepth(a) + 1);
    return node(std::move(e), depth);
  }

  static int exprDepth(const ast::Expr& e) {
    int d = 0;
    for (const ast::Expr& a : e.args) d = std::max(d, exprDepth(a));
    return d + 1;
  }

  Node function(const Token* t, DinParser::ArgumentsContext* args) {
    std::string_view fn = upper(t);
    const DinFunction* found = nullptr;
    for (const DinFunction& f : kFunctions)
      if (fn == f.name) found = &f;
    if (!found) notYet(at(t), absl::StrCat("function '", str(fn), "'"));
    ast::Expr e;
    e.kind = Kind::Call;
    e.op = found->op;
    e.loc = at(t);
    e.args = arguments(args);
    for (const ast::Expr& a : e.args)
      if (a.kind == Kind::Vacant && !found->omissions)
        fail(codes::kArity, a.loc, absl::StrCat("'", str(fn), "': an argument is missing"));
    if (e.args.size() < found->min_args || e.args.size() > found->max_args) {
      const std::string count =
          found->min_args == found->max_args
              ? absl::StrCat(found->min_args, found->min_args == 1 ? " argument" : " arguments")
          : found->max_args == kManyArguments
              ? absl::StrCat(found->min_args, " to ", kManyArguments, " arguments")
                                   : absl::StrCat(found->min_args, " or ", found->max_args, " arguments");
      fail(codes::kArity, at(t), absl::StrCat("function '", str(fn), "' takes ", count));
    }
    int depth = 1;
    for (const ast::Expr& a : e.args) depth = std::max(depth, exprDepth(a) + 1);
    return node(std::move(e), depth);
  }

};

// The program header a Sinumerik file starts with, `%_N_NAME_MPF` or `%_N_NAME_SPF` (the
// cycles notes §2: `%_N_MYKONTUR_SPF`), or a bare `%`: a tape mark block with the header kept
// as its comment. Anything else after a '%' is left to the parser, which refuses it.
bool readHeader(std::string_view text, SourceLocation start, ast::Block& out) {
  size_t i = 0;
  while (i < text.size() && isBlank(text[i])) ++i;
  if (i == text.size() || text[i] != '%') return false;
  size_t end = text.size();
  while (end > i && isBlank(text[end - 1])) --end;
  const std::string_view header = text.substr(i + 1, end - i - 1);
  const bool bare = header.empty();
  const bool named = header.size() > 7 && header.substr(0, 3) == "_N_" &&
                     std::all_of(header.begin(), header.end(), [](char c) {
                       return isLetter(c) || isDigit(c) || c == '_';
                     });
  if (!bare && !named) return false;
  out.loc = start;
  out.language = Language::Din;
  out.percent = true;
  if (named) out.comments.emplace_back(header);
  return true;
}

}  // namespace

struct DinBlockParser::Engine : AntlrEngine<DinLexer, DinParser> {};

DinBlockParser::DinBlockParser() : engine_(std::make_unique<Engine>()) {}
DinBlockParser::~DinBlockParser() = default;

bool DinBlockParser::parse(std::string_view text, SourceLocation start, DiagnosticEngine& diags,
                           ast::Block& out) {
  out = ast::Block{};
  if (readHeader(text, start, out)) return true;
  Engine& e = *engine_;
  const std::vector<Token*> tokens = e.lex(text);
  Builder builder(text, e.upper, start, diags);
  bool ok = true;
  try {
    builder.checkTokens(tokens);
    Token* offending = nullptr;
    DinParser::BlockContext* tree = e.parse(offending);
    if (!tree) builder.failAt(offending);
    builder.block(tree, out);
  } catch (const BlockRejected&) {
    ok = false;
  }
  e.reset();
  return ok;
}

}  // namespace ncc::frontend
