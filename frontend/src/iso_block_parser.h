#pragma once
// One ISO block from text to AST: the fast path for plain word blocks, the ANTLR parser for
// the rest (and for everything when ParserChoice::AntlrOnly is asked).
#include <optional>
#include <string_view>

#include "antlr_block_parser.h"
#include "ncc/frontend/block_reader.h"

namespace ncc::frontend {

class IsoBlockParser {
 public:
  // `fast` (optional) is set to whether the fast path produced the block.
  std::optional<ast::Block> parse(std::string_view text, SourceLocation start,
                                  DiagnosticEngine& diags, ParserChoice choice,
                                  bool* fast = nullptr);
  // The same into `out` (see parsePlainBlock): false after reporting a syntax error.
  bool parse(std::string_view text, SourceLocation start, DiagnosticEngine& diags,
             ParserChoice choice, ast::Block& out, bool* fast = nullptr);

 private:
  AntlrBlockParser antlr_;
};

}  // namespace ncc::frontend
