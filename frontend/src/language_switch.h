#pragma once
// The two languages of a Siemens program (docs/frontend.md, Languages). Where the dialect has
// G290/G291 (ReaderOptions::language_switch), a block that writes G290 in ISO text switches the
// text after it to DIN, and one that writes G291 in DIN text switches back. The reader, which
// parses every block, and the program index, which scans text for labels without parsing,
// decide it here alike, and read a DIN block here alike.
#include <string_view>

#include "din_block_parser.h"
#include "iso_block_parser.h"
#include "ncc/frontend/ast.h"
#include "ncc/frontend/block_reader.h"
#include "ncc/frontend/language.h"

namespace ncc::frontend {

// The fast path of DIN: a block of words of one letter and a number (`N10 G1 X20 Y5 F200`,
// `G291`), the text DIN and ISO write alike and most of a CAM program, read by the ISO fast
// path into the tree the DIN parser makes of it (tests/frontend/din_parser_test.cpp compares
// them). False for anything else, reporting nothing: the DIN parser reads it.
bool readPlainDin(IsoBlockParser& parser, std::string_view text, SourceLocation start,
                  ast::Block& out);

// A DIN block: the fast path (with ParserChoice::Auto), else the DIN parser (which reports
// what it cannot read).
bool readDin(IsoBlockParser& iso, DinBlockParser& din, std::string_view text,
             SourceLocation start, DiagnosticEngine& diags, ParserChoice choice, ast::Block& out);

// The language after `block`, a block read in `now`.
Language languageAfter(const ast::Block& block, Language now);

// The same for a block's text not parsed yet (the program index): the text is parsed only when
// it holds "29", as every G290 / G291 does.
Language languageAfterText(std::string_view text, Language now);

// The language a file starts in: `options.initial_language`, except that where the dialect
// switches languages a file whose first block is `PROC` is DIN from its start (840D ISO mode
// §4.11: a macro body called by G65/M98 or an M-code macro "whose first block is PROC runs in
// the Siemens language"). Blank lines, `;` annotations and a `%` header line before it are
// passed over. Reads the file's first lines (the files are streamed, not held).
Language startLanguage(const SourceManager& sources, uint32_t file, const ReaderOptions& options);

}  // namespace ncc::frontend
