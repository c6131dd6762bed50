#pragma once
// G290 / G291: where the dialect has them (ReaderOptions::language_switch), a block that writes
// G290 in ISO text switches the text after it to DIN, and a block that is only G291 in DIN
// text switches back (docs/frontend.md, Languages). The reader, which parses every block, and
// the program index, which scans text for labels without parsing, decide it here alike.
#include <string_view>

#include "ncc/frontend/ast.h"
#include "ncc/frontend/language.h"

namespace ncc::frontend {

// A block that only switches back to ISO mode (`G291`, with an optional N and comments): the
// same text in both languages, so the reader returns it even in DIN mode.
bool isG291Only(const ast::Block& block);

// The language after `block`, a block the reader returned, read in `now`.
Language languageAfter(const ast::Block& block, Language now);

// The same for a block's text not parsed yet (the program index): the text is parsed only when
// it holds "29", as every G290 / G291 does.
Language languageAfterText(std::string_view text, Language now);

}  // namespace ncc::frontend
