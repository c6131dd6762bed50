#pragma once
// The ANTLR path: parses any ISO block (words, Macro B expressions and statements) with the
// parser generated from grammar/Iso.g4 and builds its AST. The lexer and parser objects are
// created once and reused for every block (their setup costs more than a parse).
#include <memory>
#include <optional>
#include <string_view>

#include "ncc/frontend/ast.h"
#include "ncc/support/diagnostics.h"

namespace ncc::frontend {

class AntlrBlockParser {
 public:
  AntlrBlockParser();
  ~AntlrBlockParser();
  AntlrBlockParser(const AntlrBlockParser&) = delete;
  AntlrBlockParser& operator=(const AntlrBlockParser&) = delete;

  // `text` is one block without terminator; `start` is where its first character is in the
  // file (columns of diagnostics and nodes count from there). Reports at most one syntax
  // error and then returns nullopt.
  std::optional<ast::Block> parse(std::string_view text, SourceLocation start,
                                  DiagnosticEngine& diags);

 private:
  struct Engine;
  std::unique_ptr<Engine> engine_;
};

}  // namespace ncc::frontend
