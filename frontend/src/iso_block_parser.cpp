#include "iso_block_parser.h"

#include "fast_block_parser.h"

namespace ncc::frontend {

bool IsoBlockParser::parse(std::string_view text, SourceLocation start, DiagnosticEngine& diags,
                           ParserChoice choice, ast::Block& out, bool* fast) {
  if (choice == ParserChoice::Auto && parsePlainBlock(text, start, out)) {
    if (fast) *fast = true;
    return true;
  }
  if (fast) *fast = false;
  std::optional<ast::Block> block = antlr_.parse(text, start, diags);
  if (!block) return false;
  out = std::move(*block);
  return true;
}

std::optional<ast::Block> IsoBlockParser::parse(std::string_view text, SourceLocation start,
                                                DiagnosticEngine& diags, ParserChoice choice,
                                                bool* fast) {
  ast::Block block;
  if (!parse(text, start, diags, choice, block, fast)) return std::nullopt;
  return block;
}

std::optional<ast::Block> parseIsoBlock(std::string_view text, uint32_t file, uint32_t line,
                                        DiagnosticEngine& diags, uint32_t first_column,
                                        ParserChoice parser) {
  // The ANTLR objects are costly to build: one parser per thread serves every call.
  thread_local IsoBlockParser iso;
  return iso.parse(text, SourceLocation{file, line, first_column}, diags, parser);
}

}  // namespace ncc::frontend
