#pragma once
// One Siemens DIN block from text to AST, with the parser generated from grammar/Din.g4
// (docs/din.md says what is read and what is not yet). The lexer and parser objects are made
// once and reused for every block.
#include <memory>
#include <string_view>

#include "ncc/frontend/ast.h"
#include "ncc/support/diagnostics.h"

namespace ncc::frontend {

class DinBlockParser {
 public:
  DinBlockParser();
  ~DinBlockParser();
  DinBlockParser(const DinBlockParser&) = delete;
  DinBlockParser& operator=(const DinBlockParser&) = delete;

  // `text` is one block without its `;` comment; `start` is where its first character is in
  // the file. Fills `out` (language Din) or reports one error and returns false.
  bool parse(std::string_view text, SourceLocation start, DiagnosticEngine& diags,
             ast::Block& out);

 private:
  struct Engine;
  std::unique_ptr<Engine> engine_;
};

}  // namespace ncc::frontend
