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
#include <cmath>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "ncc/frontend/block_reader.h"
#include "number_text.h"

namespace ncc::frontend {

namespace {

std::string print(const ast::Expr& e);

// An expression without the brackets a binary operation would get at top level.
std::string bare(const ast::Expr& e) {
  if (e.kind != ast::Expr::Kind::Binary || e.args.size() != 2) return print(e);
  const char* space = ast::isWordOperator(e.op) ? " " : "";
  return absl::StrCat(print(e.args[0]), space, ast::opText(e.op), space, print(e.args[1]));
}

std::string print(const ast::Expr& e) {
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
    case K::Unary:
      return absl::StrCat(ast::opText(e.op), e.args.empty() ? "" : print(e.args[0]));
    case K::Binary:
      return absl::StrCat("[", bare(e), "]");
    case K::Call: {
      std::vector<std::string> args;
      for (const ast::Expr& a : e.args) args.push_back(bare(a));
      return absl::StrCat(ast::opText(e.op), "[", absl::StrJoin(args, ","), "]");
    }
    case K::Bracket:
      return absl::StrCat("[", e.args.empty() ? "" : bare(e.args[0]), "]");
    case K::Vacant:
      return "";
  }
  return "";
}

std::string print(const ast::Statement& s) {
  using K = ast::Statement::Kind;
  switch (s.kind) {
    case K::Assign:
      return absl::StrCat(print(s.target), "=", print(s.value));
    case K::Goto:
      return absl::StrCat("GOTO ", print(s.target));
    case K::IfGoto:
      return absl::StrCat("IF [", bare(s.value), "] GOTO ", print(s.target));
    case K::IfThen:
      return absl::StrCat("IF [", bare(s.value), "] THEN ",
                          s.then_assign ? print(*s.then_assign) : "");
    case K::While:
      return absl::StrCat("WHILE [", bare(s.value), "] DO ", s.loop_id);
    case K::End:
      return absl::StrCat("END ", s.loop_id);
  }
  return "";
}

}  // namespace

std::string printBlock(const ast::Block& block) {
  std::vector<std::string> parts;
  if (block.skip_level >= 0) parts.push_back(absl::StrCat("/", block.skip_level));
  if (block.percent) parts.push_back("%");
  if (block.program_number) parts.push_back(absl::StrCat("O", *block.program_number));
  if (block.sequence) parts.push_back(absl::StrCat("N", *block.sequence));
  for (const ast::Word& w : block.words) parts.push_back(absl::StrCat(w.address.c_str(), print(w.value)));
  for (const ast::Statement& s : block.statements) parts.push_back(print(s));
  for (const std::string& c : block.comments) parts.push_back(absl::StrCat("(", c, ")"));
  return absl::StrJoin(parts, " ");
}

}  // namespace ncc::frontend
