#include "language_switch.h"

#include "ncc/frontend/block_reader.h"
#include "ncc/support/diagnostics.h"

namespace ncc::frontend {

namespace {

bool isLiteralG(const ast::Word& w, double code) {
  return w.address.is('G') && w.value.kind == ast::Expr::Kind::Number && w.value.number == code &&
         !w.value.has_point;
}

}  // namespace

bool isG291Only(const ast::Block& b) {
  return b.statements.empty() && b.words.size() == 1 && isLiteralG(b.words[0], 291.0);
}

Language languageAfter(const ast::Block& b, Language now) {
  const double code = now == Language::Iso ? 290.0 : 291.0;
  for (const ast::Word& w : b.words)
    if (isLiteralG(w, code)) return now == Language::Iso ? Language::Din : Language::Iso;
  return now;
}

Language languageAfterText(std::string_view text, Language now) {
  if (text.find("29") == std::string_view::npos) return now;
  DiagnosticEngine scratch;
  std::optional<ast::Block> b = parseIsoBlock(text, 0, 1, scratch);
  if (!b || (now == Language::Din && !isG291Only(*b))) return now;  // the reader skips it
  return languageAfter(*b, now);
}

}  // namespace ncc::frontend
