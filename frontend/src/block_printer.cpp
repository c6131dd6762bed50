// printBlock: the canonical text of a block, used by `ncc compile --emit=ast` and by the
// differential test of the two parsers.
//
// Printed form (one line per block, items separated by one space):
//   [/n] [%] [O<n>] [N<n>] words... statements... (comments)...
// - block skip prints as `/1`..`/9` (a bare `/` is level 1), `/0` for Siemens level 0;
// - numbers print their value, with a point exactly when one was written:
//   `G01` -> `G1`, `X10.` -> `X10.`, `X.5` -> `X0.5`, `X-0` -> `X-0`;
// - comma addresses print as `,C10.`; words keep their written order;
// - expressions are fully bracketed: every binary operation is enclosed in `[ ]` once
//   (`#1=1+2*#3` -> `#1=[1+[2*#3]]`), keyword operators are spaced (`[#1 EQ 0]`), a sign is
//   written before its operand (`-#5`), functions print as `SIN[x]`, `ATAN[a,b]`;
//   variables as `#12` or `#[expr]`;
// - statements: `#n=expr`, `GOTO n`, `IF [c] GOTO n`, `IF [c] THEN #n=expr`,
//   `WHILE [c] DO m`, `END m`;
// - comments print as `(text)` after everything else (a Siemens `;` annotation too).
// A DIN block prints in DIN: `( )` for brackets and function arguments, `==` `<>` `<` `>` `<=`
// `>=` for comparisons, `X=expr` for a word whose value is not a number or whose address is
// longer than a letter, names and R parameters as written (`COUNT`, `R[..]`), strings quoted,
// statements `R1=expr`, `DEF INT A=1`, `MA1:`, `IF c GOTOB MA1`, `GOTOF N10`, `NAME(args)`,
// the control structures `IF c`, `WHILE c`, `FOR I=0 TO n`, `UNTIL c`, `CASE c OF 7 GOTOF L1
// DEFAULT GOTOF L2`, `ELSE`, `ENDIF` ... as keywords.
#include <cmath>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "ncc/frontend/block_reader.h"
#include "number_text.h"

namespace ncc::frontend {

namespace {

// Prints the nodes of one block in its language.
class Printer {
 public:
  explicit Printer(Language language) : din_(language == Language::Din) {}

  // An expression without the brackets a binary operation would get at top level.
  std::string bare(const ast::Expr& e) const {
    if (e.kind != ast::Expr::Kind::Binary || e.args.size() != 2) return print(e);
    const bool symbol = din_ && e.op >= ast::Op::Eq && e.op <= ast::Op::Le;  // DIN's `==` `<`
    const char* space = ast::isWordOperator(e.op) && !symbol ? " " : "";
    return absl::StrCat(print(e.args[0]), space, op(e.op), space, print(e.args[1]));
  }

  std::string print(const ast::Expr& e) const {
    using K = ast::Expr::Kind;
    switch (e.kind) {
      case K::Number:
        return formatNumber(e.number, e.has_point);
      case K::Variable: {
        if (e.args.empty()) return "#";
        const ast::Expr& n = e.args[0];
        if (n.kind == K::Number && !std::signbit(n.number)) return absl::StrCat("#", print(n));
        return absl::StrCat("#[", bare(n), "]");
      }
      case K::Unary: {
        const char* space = e.op == ast::Op::Not || e.op == ast::Op::BNot ? " " : "";
        return absl::StrCat(op(e.op), space, e.args.empty() ? "" : print(e.args[0]));
      }
      case K::Binary:
        return absl::StrCat(open(), bare(e), close());
      case K::Call:
        return absl::StrCat(op(e.op), list(e.args, open(), close()));
      case K::Bracket:
        return absl::StrCat(open(), e.args.empty() ? "" : bare(e.args[0]), close());
      case K::Vacant:
        return "";
      case K::Name:
        return absl::StrCat(e.text ? *e.text : "", e.args.empty() ? "" : list(e.args, "[", "]"));
      case K::RParam: {
        if (e.args.empty()) return "R";
        const ast::Expr& n = e.args[0];
        if (n.kind == K::Number && !std::signbit(n.number)) return absl::StrCat("R", print(n));
        return absl::StrCat("R[", bare(n), "]");
      }
      case K::String:
        return absl::StrCat("\"", e.text ? *e.text : "", "\"");
    }
    return "";
  }

  // INT, STRING[20]: a variable's type as written.
  static std::string typeText(const ast::Statement& s) {
    const char* name = ast::kDataTypeNames[static_cast<size_t>(s.type)];
    return s.length > 0 ? absl::StrCat(name, "[", s.length, "]") : std::string(name);
  }

  std::string print(const ast::Statement& s) const {
    using K = ast::Statement::Kind;
    switch (s.kind) {
      case K::Assign:
        return absl::StrCat(print(s.target), "=", din_ ? bare(s.value) : print(s.value));
      case K::Goto:
        return absl::StrCat(jump(s.jump), " ", print(s.target));
      case K::IfGoto:
        if (din_) return absl::StrCat("IF ", bare(s.value), " ", jump(s.jump), " ", print(s.target));
        return absl::StrCat("IF [", bare(s.value), "] GOTO ", print(s.target));
      case K::IfThen:
        return absl::StrCat("IF [", bare(s.value), "] THEN ",
                            s.then_assign ? print(*s.then_assign) : "");
      case K::While:
        if (din_) return absl::StrCat("WHILE ", bare(s.value));
        return absl::StrCat("WHILE [", bare(s.value), "] DO ", s.loop_id);
      case K::End:
        return absl::StrCat("END ", s.loop_id);
      case K::Define:
        return absl::StrCat("DEF ", typeText(s), " ", print(s.target),
                            s.value.kind == ast::Expr::Kind::Vacant ? "" : "=",
                            bare(s.value));
      case K::Label:
        return absl::StrCat(print(s.target), ":");
      case K::Call:
        return absl::StrCat(s.target.text ? *s.target.text : "",
                            s.target.args.empty() ? "" : list(s.target.args, "(", ")"));
      case K::If:
        return absl::StrCat("IF ", bare(s.value));
      case K::Else: return "ELSE";
      case K::EndIf: return "ENDIF";
      case K::EndWhile: return "ENDWHILE";
      case K::For:
        return absl::StrCat("FOR ", s.then_assign ? print(*s.then_assign) : "", " TO ",
                            bare(s.value));
      case K::EndFor: return "ENDFOR";
      case K::Repeat: return "REPEAT";
      case K::Until:
        return absl::StrCat("UNTIL ", bare(s.value));
      case K::Loop: return "LOOP";
      case K::EndLoop: return "ENDLOOP";
      case K::Case:
        return absl::StrCat("CASE ", bare(s.value), " OF");
      case K::Proc:
        return absl::StrCat("PROC ", print(s.target));
      case K::Parameter:
        return absl::StrCat(s.loop_id ? "VAR " : "", typeText(s), " ", print(s.target));
      case K::Return: return "RET";
      case K::RepeatSection:
        return absl::StrCat(s.loop_id ? "REPEATB " : "REPEAT ", s.target.text ? *s.target.text : "",
                            s.target.args.empty() || !s.target.args[0].text
                                ? ""
                                : absl::StrCat(" ", *s.target.args[0].text),
                            s.value.kind == ast::Expr::Kind::Vacant ? "" : " P=", bare(s.value));
      case K::CaseBranch:
        return absl::StrCat(s.value.kind == ast::Expr::Kind::Vacant ? "DEFAULT" : print(s.value),
                            " ", jump(s.jump), " ", print(s.target));
    }
    return "";
  }

  std::string word(const ast::Word& w) const {
    if (din_ && (w.address.size() > 1 || !w.value.isLiteral()))
      return absl::StrCat(w.address.c_str(), "=", bare(w.value));
    return absl::StrCat(w.address.c_str(), print(w.value));
  }

 private:
  const char* open() const { return din_ ? "(" : "["; }
  const char* close() const { return din_ ? ")" : "]"; }

  std::string list(const std::vector<ast::Expr>& args, const char* open, const char* close) const {
    std::vector<std::string> parts;
    for (const ast::Expr& a : args) parts.push_back(bare(a));
    return absl::StrCat(open, absl::StrJoin(parts, ","), close);
  }

  // DIN writes the comparisons as symbols; every other operator has one spelling.
  const char* op(ast::Op o) const {
    if (din_) {
      switch (o) {
        case ast::Op::Eq: return "==";
        case ast::Op::Ne: return "<>";
        case ast::Op::Lt: return "<";
        case ast::Op::Gt: return ">";
        case ast::Op::Le: return "<=";
        case ast::Op::Ge: return ">=";
        default: break;
      }
    }
    return ast::opText(o);
  }

  static const char* jump(ast::Jump j) {
    switch (j) {
      case ast::Jump::Sequence:
      case ast::Jump::Both: return "GOTO";
      case ast::Jump::Forward: return "GOTOF";
      case ast::Jump::Backward: return "GOTOB";
      case ast::Jump::BothQuiet: return "GOTOC";
    }
    return "GOTO";
  }

  bool din_;
};

}  // namespace

std::string printBlock(const ast::Block& block) {
  std::vector<std::string> parts;
  if (block.skip_level >= 0) parts.push_back(absl::StrCat("/", block.skip_level));
  if (block.percent) parts.push_back("%");
  if (block.program_number) parts.push_back(absl::StrCat("O", *block.program_number));
  if (block.sequence) parts.push_back(absl::StrCat("N", *block.sequence));
  const Printer printer(block.language);
  for (const ast::Word& w : block.words) parts.push_back(printer.word(w));
  for (size_t i = 0; i < block.statements.size(); ++i) {
    const ast::Statement& s = block.statements[i];
    if (s.kind != ast::Statement::Kind::Proc) {
      parts.push_back(printer.print(s));
      continue;
    }
    // PROC NAME(REAL A,VAR INT B): the Parameter statements after it, in its brackets.
    std::vector<std::string> params;
    while (i + 1 < block.statements.size() &&
           block.statements[i + 1].kind == ast::Statement::Kind::Parameter)
      params.push_back(printer.print(block.statements[++i]));
    parts.push_back(absl::StrCat(printer.print(s), params.empty() ? "" : "(",
                                 absl::StrJoin(params, ","), params.empty() ? "" : ")"));
  }
  for (const std::string& c : block.comments) parts.push_back(absl::StrCat("(", c, ")"));
  return absl::StrJoin(parts, " ");
}

}  // namespace ncc::frontend
