#include "expr_text.h"

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace ncc::passes {

std::string exprText(const ast::Expr& e) {
  using K = ast::Expr::Kind;
  switch (e.kind) {
    case K::Number: {
      std::string s = absl::StrFormat("%.6g", e.number);
      if (e.has_point && s.find('.') == std::string::npos) s += ".";
      return s;
    }
    case K::Variable: return absl::StrCat("#", e.args.empty() ? "" : exprText(e.args[0]));
    case K::Unary: return absl::StrCat(ast::opText(e.op), e.args.empty() ? "" : exprText(e.args[0]));
    case K::Binary:
      if (e.args.size() != 2) return ast::opText(e.op);
      return absl::StrCat(exprText(e.args[0]), ast::opText(e.op), exprText(e.args[1]));
    case K::Call: {
      std::string s = absl::StrCat(ast::opText(e.op), "[");
      for (size_t i = 0; i < e.args.size(); ++i)
        absl::StrAppend(&s, i ? "," : "", exprText(e.args[i]));
      return s + "]";
    }
    case K::Bracket: return absl::StrCat("[", e.args.empty() ? "" : exprText(e.args[0]), "]");
    case K::Vacant: return "";
    case K::Name: return e.text ? *e.text : "";
    case K::RParam: return absl::StrCat("R", e.args.empty() ? "" : exprText(e.args[0]));
    case K::String: return absl::StrCat("\"", e.text ? *e.text : "", "\"");
  }
  return "";
}

bool foldLiteral(const ast::Expr& e, double& value, bool& has_point) {
  if (e.kind == ast::Expr::Kind::Number) {
    value = e.number;
    has_point = e.has_point;
    return true;
  }
  if (e.kind == ast::Expr::Kind::Unary && e.args.size() == 1 && (e.op == ast::Op::Minus || e.op == ast::Op::Plus) &&
      foldLiteral(e.args[0], value, has_point)) {
    if (e.op == ast::Op::Minus) value = -value;
    return true;
  }
  return false;
}

}  // namespace ncc::passes
