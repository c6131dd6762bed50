#pragma once
// The two languages of a Siemens program (docs/frontend.md, Languages). Where the dialect has
// G290/G291 (ReaderOptions::language_switch), a block that writes G290 in ISO text switches the
// text after it to DIN, and one that writes G291 in DIN text switches back. The reader, which
// parses every block, and the program index, which scans text for labels without parsing,
// decide it here alike, and read a DIN block here alike.
#include <string_view>

#include "iso_block_parser.h"
#include "ncc/frontend/ast.h"
#include "ncc/frontend/language.h"

namespace ncc::frontend {

// A DIN block as far as ncc reads DIN so far: words of one letter and a number
// (`N10 G1 X20 Y5 F200`, `G291`), the text DIN and ISO write alike, read by the ISO fast path.
// False for anything else: DIN statements, expressions and `=` addresses not built yet, and
// ISO forms DIN does not have (`#1`, `[..]`, `(comment)`, `,C`, `O`/`:` numbers). Reports
// nothing: the caller says why a block is not read.
bool readPlainDin(IsoBlockParser& parser, std::string_view text, SourceLocation start,
                  ast::Block& out);

// The language after `block`, a block read in `now`.
Language languageAfter(const ast::Block& block, Language now);

// The same for a block's text not parsed yet (the program index): the text is parsed only when
// it holds "29", as every G290 / G291 does.
Language languageAfterText(std::string_view text, Language now);

}  // namespace ncc::frontend
