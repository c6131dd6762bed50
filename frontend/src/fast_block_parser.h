#pragma once
// The fast path: a hand-written reader for plain word blocks, the bulk of CAM output
// (`N10 G1 X10. Y-5. F100.`, comments, block skip, `%`, comma addresses). Anything else
// (`#`, `[`, keywords, any error) is declined and goes to the ANTLR path, which therefore
// owns every diagnostic. The differential test in tests/frontend checks that a block the
// fast path accepts gets the identical AST (text and locations) from the ANTLR path.
#include <optional>
#include <string_view>

#include "ncc/frontend/ast.h"

namespace ncc::frontend {

// The block, or nullopt when the text is not a plain word block.
std::optional<ast::Block> parsePlainBlock(std::string_view text, SourceLocation start);
// The same into `out`, cleared first: its vectors keep their capacity, so a reader that
// refills one block allocates nothing for a plain block. False (and `out` unspecified) when
// the text is not a plain word block.
bool parsePlainBlock(std::string_view text, SourceLocation start, ast::Block& out);

}  // namespace ncc::frontend
