#pragma once
// What the two ANTLR block parsers (ISO: antlr_block_parser.cpp, DIN: din_block_parser.cpp)
// share: the first-error listener, the exception that ends a rejected block, and the depth
// message.
#include <exception>
#include <string>

#include "absl/strings/str_cat.h"
#include "antlr4-runtime.h"
#include "ncc/frontend/ast.h"

namespace ncc::frontend {

// Remembers the first error the parser reports; the message is ours, built from the token.
class FirstErrorListener : public antlr4::BaseErrorListener {
 public:
  void syntaxError(antlr4::Recognizer*, antlr4::Token* offending, size_t, size_t,
                   const std::string&, std::exception_ptr) override {
    if (!seen) offending_token = offending;
    seen = true;
  }
  void clear() {
    seen = false;
    offending_token = nullptr;
  }
  bool seen = false;
  antlr4::Token* offending_token = nullptr;
};

// Thrown by a builder after it has reported a diagnostic; caught where the parse started.
struct BlockRejected {};

// Deeper nesting than this is refused before parsing: the parsers and the AST are recursive,
// and no controller allows more than a handful of bracket levels (FANUC: 5).
inline constexpr int kMaxNesting = 64;

inline std::string tooDeep() {
  return absl::StrCat("expression nested deeper than ", ast::kMaxExprDepth,
                      " levels (each operator, sign, bracket and function is one)");
}

}  // namespace ncc::frontend
