#pragma once
// Writes an expression back as the programmer wrote it (`#1`, `[#2+1.]`, `SIN[30.]`), for
// diagnostics that name a word lowering cannot evaluate yet.
#include <string>

#include "ncc/frontend/ast.h"

namespace ncc::passes {

std::string exprText(const ast::Expr& e);

// A literal number, also under unary signs (`-[5.]` is not: brackets make an expression).
// Returns false for anything that needs macro evaluation.
bool foldLiteral(const ast::Expr& e, double& value, bool& has_point);

}  // namespace ncc::passes
