#include "ncc/frontend/block_reader.h"

#include "absl/strings/str_cat.h"
#include "diagnostic_codes.h"
#include "iso_block_parser.h"
#include "language_switch.h"
#include "lexical.h"
#include "block_cursor.h"

namespace ncc::frontend {

namespace {

bool isBlankText(std::string_view text) {
  for (char c : text)
    if (!isBlank(c)) return false;
  return true;
}

}  // namespace

struct BlockReader::Impl {
  Impl(const SourceManager& s, uint32_t f, DiagnosticEngine& d, ReaderOptions o)
      : file(f), diags(d), options(o), cursor(s, f) {
    options.initial_language = startLanguage(s, f, o);
    language = options.initial_language;
  }

  // The next block of text: cuts the line at ';' as the current language wants. Returns false
  // at end of input.
  bool nextSegment(BlockCursor::Segment& segment) {
    return cursor.next(segment, language == Language::Iso && options.semicolon_ends_block);
  }


  uint32_t file;
  DiagnosticEngine& diags;
  ReaderOptions options;
  Language language;
  BlockCursor cursor;
  IsoBlockParser parser;
  // Made at the first DIN block: an ISO program does not pay for the DIN grammar's set-up.
  std::unique_ptr<DinBlockParser> din;
  ReaderStats stats;
  BlockPosition last;  // of the block last returned
};

BlockReader::BlockReader(const SourceManager& sources, uint32_t file, DiagnosticEngine& diags,
                         ReaderOptions options)
    : impl_(std::make_unique<Impl>(sources, file, diags, options)) {
  if (!impl_->cursor.ok())
    diags.error(codes::kCannotRead, SourceLocation{file, 0, 0},
                absl::StrCat("cannot read '", sources.displayName(file), "'"));
}

BlockReader::~BlockReader() = default;

std::optional<ast::Block> BlockReader::next() {
  ast::Block block;
  if (!next(block)) return std::nullopt;
  return block;
}

bool BlockReader::next(ast::Block& out) {
  Impl& r = *impl_;
  BlockCursor::Segment s;
  while (r.nextSegment(s)) {
    const std::string_view segment = s.text;
    if (isBlankText(segment) && !s.annotation) continue;  // blank lines are not blocks
    const SourceLocation where{r.file, s.at.line, s.at.column};
    bool fast = false;
    bool read = false;
    if (r.language == Language::Din) {
      if (isBlankText(segment)) continue;  // a DIN comment line
      if (!r.din) r.din = std::make_unique<DinBlockParser>();
      read = readDin(r.parser, *r.din, segment, where, r.diags, r.options.parser, out);
    } else {
      read = r.parser.parse(segment, where, r.diags, r.options.parser, out, &fast);
    }
    if (!read) {
      ++r.stats.rejected_blocks;
      continue;
    }
    if (s.annotation) out.comments.emplace_back(*s.annotation);
    out.language = r.language;
    r.last = s.at;
    r.last.language = r.language;
    if (r.options.language_switch) r.language = languageAfter(out, r.language);
    ++r.stats.blocks;
    if (fast) ++r.stats.fast_path_blocks;
    return true;
  }
  return false;
}

std::optional<BlockReader::Text> BlockReader::nextText() {
  Impl& r = *impl_;
  BlockCursor::Segment s;
  while (r.nextSegment(s)) {
    const std::string_view segment = s.text;
    size_t first = 0;
    while (first < segment.size() && isBlank(segment[first])) ++first;
    if (first == segment.size()) continue;
    r.last = s.at;
    r.last.language = r.language;
    return Text{segment.substr(first),
                SourceLocation{r.file, s.at.line, s.at.column + static_cast<uint32_t>(first)}};
  }
  return std::nullopt;
}

Language BlockReader::language() const { return impl_->language; }
const ReaderStats& BlockReader::stats() const {
  impl_->stats.lines = impl_->cursor.linesRead();
  return impl_->stats;
}

BlockPosition BlockReader::lastPosition() const { return impl_->last; }
BlockPosition BlockReader::position() const {
  BlockPosition p = impl_->cursor.position();
  p.language = impl_->language;
  return p;
}
void BlockReader::seek(BlockPosition p) {
  impl_->cursor.seek(p);
  impl_->language = languageAt(p, impl_->options.initial_language);
}
uint32_t BlockReader::file() const { return impl_->file; }

}  // namespace ncc::frontend
