#pragma once
// Helpers of the frontend tests: parse one block and look at the AST or the diagnostics.
#include <optional>
#include <string>
#include <string_view>

#include "ncc/frontend/block_reader.h"

namespace ncc::frontend::testing {

struct Parsed {
  std::optional<ast::Block> block;
  DiagnosticEngine diags;
};

inline Parsed parse(std::string_view text, ParserChoice choice = ParserChoice::Auto) {
  Parsed p;
  p.block = parseIsoBlock(text, /*file=*/0, /*line=*/1, p.diags, 1, choice);
  return p;
}

// printBlock of the parse, or "error: <message>" of the first diagnostic.
inline std::string printed(std::string_view text, ParserChoice choice = ParserChoice::Auto) {
  Parsed p = parse(text, choice);
  if (!p.block) {
    return p.diags.diagnostics().empty() ? std::string("no block, no diagnostic")
                                         : "error: " + p.diags.diagnostics()[0].message;
  }
  return printBlock(*p.block);
}

}  // namespace ncc::frontend::testing
