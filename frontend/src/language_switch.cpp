#include "language_switch.h"

#include "block_cursor.h"

#include "lexical.h"
#include "ncc/support/diagnostics.h"

namespace ncc::frontend {

namespace {

bool isLiteralG(const ast::Word& w, double code) {
  return w.address.is('G') && w.value.kind == ast::Expr::Kind::Number && w.value.number == code &&
         !w.value.has_point;
}

// What the DIN parser reads as the ISO fast path did: words of a letter and a number written
// right after it (`G 90` is ISO only), a signed word after a blank (`G0X-1` is a name `G0X` in
// DIN), an N only as the first word.
bool isPlainDin(const ast::Block& b, std::string_view text, SourceLocation start) {
  if (!b.statements.empty() || !b.comments.empty() || b.program_number || b.percent) return false;
  for (const ast::Word& w : b.words) {
    if (w.address.size() != 1) return false;  // `,C`: an ISO corner word
    if (w.value.loc.column != w.loc.column + 1) return false;
    const size_t at = w.loc.column - start.column;
    const bool signed_value = at + 1 < text.size() && (text[at + 1] == '-' || text[at + 1] == '+');
    if (signed_value && at > 0 && at <= text.size() && !isBlank(text[at - 1])) return false;
  }
  if (b.sequence) {
    size_t i = 0;
    while (i < text.size() && (isBlank(text[i]) || text[i] == '/' || isDigit(text[i]))) ++i;
    if (i + 1 >= text.size() || upperAscii(text[i]) != 'N' || !isDigit(text[i + 1])) return false;
  }
  return true;
}

}  // namespace

bool readPlainDin(IsoBlockParser& parser, std::string_view text, SourceLocation start,
                  ast::Block& out) {
  DiagnosticEngine scratch;
  bool fast = false;
  if (!parser.parse(text, start, scratch, ParserChoice::Auto, out, &fast) || !fast ||
      !isPlainDin(out, text, start))
    return false;
  out.language = Language::Din;
  return true;
}

bool readDin(IsoBlockParser& iso, DinBlockParser& din, std::string_view text,
             SourceLocation start, DiagnosticEngine& diags, ParserChoice choice, ast::Block& out) {
  return (choice == ParserChoice::Auto && readPlainDin(iso, text, start, out)) ||
         din.parse(text, start, diags, out);
}

Language languageAfter(const ast::Block& b, Language now) {
  const double code = now == Language::Iso ? kSwitchToDin : kSwitchToIso;
  for (const ast::Word& w : b.words)
    if (isLiteralG(w, code)) return now == Language::Iso ? Language::Din : Language::Iso;
  return now;
}

Language languageAfterText(std::string_view text, Language now) {
  if (text.find("29") == std::string_view::npos) return now;
  thread_local IsoBlockParser parser;
  DiagnosticEngine scratch;
  ast::Block b;
  bool read = false;
  if (now == Language::Iso) {
    read = parser.parse(text, SourceLocation{}, scratch, ParserChoice::Auto, b);
  } else {
    thread_local DinBlockParser din;  // made at the first DIN text
    read = readDin(parser, din, text, SourceLocation{}, scratch, ParserChoice::Auto, b);
  }
  return read ? languageAfter(b, now) : now;  // a block the reader skips switches nothing
}

Language startLanguage(const SourceManager& sources, uint32_t file, const ReaderOptions& options) {
  if (!options.language_switch || options.initial_language == Language::Din)
    return options.initial_language;
  BlockCursor cursor(sources, file);
  BlockCursor::Segment segment;
  // A header longer than this is no header: the file is what the options say.
  for (int n = 0; n < 64 && cursor.next(segment, /*semicolon_ends_block=*/false); ++n) {
    std::string_view t = segment.text;
    while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
    if (t.empty() || t.front() == '%') continue;  // blank, `;` only, the tape mark or header
    if ((t.front() == 'N' || t.front() == 'n') && t.size() > 1 && t[1] >= '0' && t[1] <= '9') {
      t.remove_prefix(1);  // a block number before it
      while (!t.empty() && t.front() >= '0' && t.front() <= '9') t.remove_prefix(1);
      while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
    }
    constexpr std::string_view kProc = "PROC";
    if (t.size() <= kProc.size() || (t[kProc.size()] != ' ' && t[kProc.size()] != '\t'))
      return options.initial_language;
    for (size_t k = 0; k < kProc.size(); ++k)
      if ((t[k] & ~0x20) != kProc[k]) return options.initial_language;
    return Language::Din;
  }
  return options.initial_language;
}

}  // namespace ncc::frontend
