#include "language_switch.h"

#include "ncc/support/diagnostics.h"

namespace ncc::frontend {

namespace {

bool isLiteralG(const ast::Word& w, double code) {
  return w.address.is('G') && w.value.kind == ast::Expr::Kind::Number && w.value.number == code &&
         !w.value.has_point;
}

bool isPlainDin(const ast::Block& b) {
  if (!b.statements.empty() || !b.comments.empty() || b.program_number || b.percent) return false;
  for (const ast::Word& w : b.words)
    if (w.address.size() != 1) return false;  // `,C`: an ISO corner word
  return true;
}

}  // namespace

bool readPlainDin(IsoBlockParser& parser, std::string_view text, SourceLocation start,
                  ast::Block& out) {
  DiagnosticEngine scratch;
  bool fast = false;
  if (!parser.parse(text, start, scratch, ParserChoice::Auto, out, &fast) || !fast ||
      !isPlainDin(out))
    return false;
  out.language = Language::Din;
  return true;
}

bool readDin(IsoBlockParser& iso, DinBlockParser& din, std::string_view text,
             SourceLocation start, DiagnosticEngine& diags, ast::Block& out) {
  return readPlainDin(iso, text, start, out) || din.parse(text, start, diags, out);
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
  thread_local DinBlockParser din;
  DiagnosticEngine scratch;
  ast::Block b;
  const bool read = now == Language::Iso
                        ? parser.parse(text, SourceLocation{}, scratch, ParserChoice::Auto, b)
                        : readDin(parser, din, text, SourceLocation{}, scratch, b);
  return read ? languageAfter(b, now) : now;  // a block the reader skips switches nothing
}

}  // namespace ncc::frontend
