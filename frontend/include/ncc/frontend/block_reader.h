#pragma once
// Reads a program one block at a time. The whole file is never held as a tree: each call to
// next() parses one line (a block ends at LF, or at ';' in the ISO family) and returns its
// AST. Reading may go back or jump ahead with seek() (Macro B GOTO, loops, subprograms). Syntax errors are reported to the DiagnosticEngine with file, line and column; the
// reader then resumes at the next block, so one run reports several errors.
//
// The language of each block is tracked here: a Siemens ISO-mode program switches to DIN at
// the block after G290 and back after G291. Only the ISO grammar exists today; a DIN block
// is reported as not supported (the seam for the DIN grammar is `Language::Din`).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "ncc/frontend/ast.h"
#include "ncc/frontend/language.h"
#include "ncc/frontend/block_position.h"
#include "ncc/support/diagnostics.h"
#include "ncc/support/source_manager.h"

namespace ncc::frontend {

// Which parser reads ISO blocks. Auto tries the hand-written fast path for plain word blocks
// and falls back to the ANTLR parser for anything else; AntlrOnly skips the fast path (the
// differential test compares the two).
enum class ParserChoice : uint8_t { Auto, AntlrOnly };

struct ReaderOptions {
  Language initial_language = Language::Iso;
  bool semicolon_ends_block = true;  // FANUC EOB ';' (Siemens ISO: ';' starts an annotation)
  // G290 / G291 switch the language from the next block (Siemens): the reader switches itself
  // after a block that writes them as literals (`G290`, not `G#1`).
  bool language_switch = false;
  ParserChoice parser = ParserChoice::Auto;
};

// Counters of one reader, for tests and benchmarks.
struct ReaderStats {
  uint64_t lines = 0;           // physical lines read
  uint64_t blocks = 0;          // blocks returned by next()
  uint64_t fast_path_blocks = 0;  // of those, read by the fast path
  uint64_t rejected_blocks = 0;   // blocks skipped because of a syntax error (or DIN)
};

class BlockReader {
 public:
  // Opens `file` (a SourceManager id); a file that cannot be read is reported as an error.
  BlockReader(const SourceManager& sources, uint32_t file, DiagnosticEngine& diags,
              ReaderOptions options = {});
  ~BlockReader();
  BlockReader(const BlockReader&) = delete;
  BlockReader& operator=(const BlockReader&) = delete;

  // The next block, or nullopt at end of input. Blocks with syntax errors are reported and
  // skipped (their words are not returned, so nothing half-parsed reaches semantics).
  std::optional<ast::Block> next();
  // The same into `out`, which a reader of many blocks reuses (a plain block then allocates
  // nothing); false at end of input.
  bool next(ast::Block& out);

  // The next block's text, not parsed (so nothing is reported), and where it starts; nullopt
  // at end of input. For text that is never executed: after the end of the program or the
  // closing '%'. The view is valid until the next call.
  struct Text {
    std::string_view text;
    SourceLocation loc;
  };
  std::optional<Text> nextText();

  // The language the next block is read in: ReaderOptions::initial_language, switched by each
  // G290 (in ISO text) and G291 (in DIN text) read, and by seek() to the position's.
  Language language() const;

  const ReaderStats& stats() const;

  // Positions, for Macro B control flow. A position names a block of this file and the
  // language it is read in.
  // Where the block last returned by next() (or nextText()) starts.
  BlockPosition lastPosition() const;
  // Where reading continues: the next block returned by next() starts here or after blank
  // text (also valid before the first next(); {offset: size, line: last + 1} at the end).
  BlockPosition position() const;
  // Continues reading at `p`, a position this reader or a ProgramIndex of the same file and
  // ReaderOptions returned, in p's language: the next next() returns the block starting
  // there, with the same AST and locations as when read straight through.
  void seek(BlockPosition p);
  // The SourceManager id of the file read.
  uint32_t file() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Parses one line of ISO text (no line terminator) as a block; used by BlockReader, the
// fuzzer and tests. Errors go to `diags` with `line` and columns within `text`, the first
// character of `text` being column `first_column` (a block after a ';' on the same line).
// Reuses one parser per thread.
std::optional<ast::Block> parseIsoBlock(std::string_view text, uint32_t file, uint32_t line,
                                        DiagnosticEngine& diags, uint32_t first_column = 1,
                                        ParserChoice parser = ParserChoice::Auto);

// Prints a block back as canonical text (`ncc compile --emit=ast`): one block per line,
// `N10 G1 X10. Y-5. F100.`, expressions fully bracketed (the form is described in
// src/block_printer.cpp and docs/frontend.md).
std::string printBlock(const ast::Block& block);

}  // namespace ncc::frontend
