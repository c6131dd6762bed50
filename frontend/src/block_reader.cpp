#include "ncc/frontend/block_reader.h"

#include "absl/strings/str_cat.h"
#include "diagnostic_codes.h"
#include "iso_block_parser.h"
#include "lexical.h"
#include "line_source.h"

namespace ncc::frontend {

namespace {

// The first ';' at or after `from` that is not inside a ( ) comment, or npos.
size_t findSemicolon(std::string_view line, size_t from) {
  bool in_comment = false;
  for (size_t i = from; i < line.size(); ++i) {
    const char c = line[i];
    if (in_comment) {
      in_comment = c != ')';
    } else if (c == '(') {
      in_comment = true;
    } else if (c == ';') {
      return i;
    }
  }
  return std::string_view::npos;
}

bool isBlankText(std::string_view text) {
  for (char c : text)
    if (!isBlank(c)) return false;
  return true;
}

// A block that only switches back to ISO mode (`G291`, with an optional N and comments) is
// the same text in both languages, so it is read even in DIN mode.
bool isG291Only(const ast::Block& b) {
  return b.statements.empty() && b.words.size() == 1 && b.words[0].address == "G" &&
         b.words[0].value.isLiteral() && b.words[0].value.number == 291.0 &&
         !b.words[0].value.has_point;
}

}  // namespace

struct BlockReader::Impl {
  Impl(const SourceManager& s, uint32_t f, DiagnosticEngine& d, ReaderOptions o)
      : file(f), diags(d), options(o), language(o.initial_language), lines(s, f) {}

  // The next block of text: cuts `line` at ';' as the current language wants. Returns false
  // at end of input.
  bool nextSegment(std::string_view& segment, std::optional<std::string_view>& annotation,
                   uint32_t& column) {
    if (!pending) {
      if (!lines.next(line)) return false;
      ++line_number;
      ++stats.lines;
      pos = 0;
      pending = true;
    }
    const std::string_view text(line);
    const size_t semi = findSemicolon(text, pos);
    column = static_cast<uint32_t>(pos + 1);
    annotation.reset();
    if (semi == std::string_view::npos) {
      segment = text.substr(pos);
      pending = false;
    } else if (language == Language::Iso && options.semicolon_ends_block) {
      segment = text.substr(pos, semi - pos);  // the rest of the line is the next block
      pos = semi + 1;
      pending = pos < text.size();
    } else {
      segment = text.substr(pos, semi - pos);  // ';' starts an annotation to end of line
      annotation = text.substr(semi + 1);
      pending = false;
    }
    return true;
  }

  std::optional<ast::Block> readDin(std::string_view segment, SourceLocation where) {
    DiagnosticEngine scratch;
    std::optional<ast::Block> b = parser.parse(segment, where, scratch, options.parser);
    if (b && isG291Only(*b)) return b;
    size_t first = 0;
    while (first < segment.size() && isBlank(segment[first])) ++first;
    where.column += static_cast<uint32_t>(first);
    diags.error(codes::kDinNotSupported, where,
                "Siemens DIN blocks (after G290) are not supported yet");
    return std::nullopt;
  }

  uint32_t file;
  DiagnosticEngine& diags;
  ReaderOptions options;
  Language language;
  LineSource lines;
  IsoBlockParser parser;
  ReaderStats stats;

  std::string line;  // the current physical line
  uint32_t line_number = 0;
  size_t pos = 0;        // where the next block of `line` starts
  bool pending = false;  // `line` has text left to read
};

BlockReader::BlockReader(const SourceManager& sources, uint32_t file, DiagnosticEngine& diags,
                         ReaderOptions options)
    : impl_(std::make_unique<Impl>(sources, file, diags, options)) {
  if (!impl_->lines.ok())
    diags.error(codes::kCannotRead, SourceLocation{file, 0, 0},
                absl::StrCat("cannot read '", sources.displayName(file), "'"));
}

BlockReader::~BlockReader() = default;

std::optional<ast::Block> BlockReader::next() {
  Impl& r = *impl_;
  std::string_view segment;
  std::optional<std::string_view> annotation;
  uint32_t column = 1;
  while (r.nextSegment(segment, annotation, column)) {
    if (isBlankText(segment) && !annotation) continue;  // blank lines are not blocks
    const SourceLocation where{r.file, r.line_number, column};
    std::optional<ast::Block> block;
    bool fast = false;
    if (r.language == Language::Din) {
      if (isBlankText(segment)) continue;  // a DIN comment line
      block = r.readDin(segment, where);
    } else {
      block = r.parser.parse(segment, where, r.diags, r.options.parser, &fast);
    }
    if (!block) {
      ++r.stats.rejected_blocks;
      continue;
    }
    if (annotation) block->comments.emplace_back(*annotation);
    ++r.stats.blocks;
    if (fast) ++r.stats.fast_path_blocks;
    return block;
  }
  return std::nullopt;
}

std::optional<BlockReader::Text> BlockReader::nextText() {
  Impl& r = *impl_;
  std::string_view segment;
  std::optional<std::string_view> annotation;
  uint32_t column = 1;
  while (r.nextSegment(segment, annotation, column)) {
    size_t first = 0;
    while (first < segment.size() && isBlank(segment[first])) ++first;
    if (first == segment.size()) continue;
    return Text{segment.substr(first),
                SourceLocation{r.file, r.line_number, column + static_cast<uint32_t>(first)}};
  }
  return std::nullopt;
}

void BlockReader::setLanguage(Language language) { impl_->language = language; }
Language BlockReader::language() const { return impl_->language; }
const ReaderStats& BlockReader::stats() const { return impl_->stats; }

}  // namespace ncc::frontend
