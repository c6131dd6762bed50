#include "iso_block_parser.h"

#include "fast_block_parser.h"

namespace ncc::frontend {

std::optional<ast::Block> IsoBlockParser::parse(std::string_view text, SourceLocation start,
                                                DiagnosticEngine& diags, ParserChoice choice,
                                                bool* fast) {
  if (choice == ParserChoice::Auto) {
    if (std::optional<ast::Block> block = parsePlainBlock(text, start)) {
      if (fast) *fast = true;
      return block;
    }
  }
  if (fast) *fast = false;
  return antlr_.parse(text, start, diags);
}

std::optional<ast::Block> parseIsoBlock(std::string_view text, uint32_t file, uint32_t line,
                                        DiagnosticEngine& diags, uint32_t first_column,
                                        ParserChoice parser) {
  // The ANTLR objects are costly to build: one parser per thread serves every call.
  thread_local IsoBlockParser iso;
  return iso.parse(text, SourceLocation{file, line, first_column}, diags, parser);
}

}  // namespace ncc::frontend
