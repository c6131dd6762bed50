#include "ncc/support/diagnostics.h"

#include "absl/strings/str_cat.h"
#include "ncc/support/source_manager.h"

namespace ncc {

namespace {
const char* severityName(Severity s) {
  switch (s) {
    case Severity::Note: return "note";
    case Severity::Warning: return "warning";
    case Severity::Error: return "error";
  }
  return "error";
}
}  // namespace

void DiagnosticEngine::report(Severity severity, std::string code, SourceLocation where,
                              std::string message) {
  if (severity == Severity::Error) {
    ++error_count_;
    if (error_count_ > error_limit_) return;
    if (error_count_ == error_limit_) {
      message += absl::StrCat(" (error limit of ", error_limit_, " reached; further errors are not shown)");
    }
  }
  diagnostics_.push_back(Diagnostic{severity, std::move(code), std::move(message), where});
}

std::string DiagnosticEngine::format(const Diagnostic& d) const {
  std::string where;
  if (sources_ && d.location.file != 0) {
    where = sources_->displayName(d.location.file);
    if (d.location.line) absl::StrAppend(&where, ":", d.location.line);
    if (d.location.column) absl::StrAppend(&where, ":", d.location.column);
    where += ": ";
  } else if (d.location.line) {
    where = absl::StrCat("<input>:", d.location.line, ":", d.location.column, ": ");
  }
  std::string code = d.code.empty() ? "" : absl::StrCat("[", d.code, "]");
  return absl::StrCat(where, severityName(d.severity), code, ": ", d.message);
}

void DiagnosticEngine::print(std::ostream& out) const {
  for (const Diagnostic& d : diagnostics_) {
    out << format(d) << '\n';
    if (!sources_ || d.location.file == 0 || d.location.line == 0) continue;
    std::string line = sources_->lineText(d.location.file, d.location.line);
    if (line.empty()) continue;
    // Control bytes (NUL, CR, ESC ...) would garble the terminal; one '?' each keeps the caret
    // in place. Tabs stay, and bytes >= 0x80 stay for UTF-8 comments.
    for (char& c : line)
      if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7F) c = '?';
    out << "  " << line << '\n';
    if (d.location.column >= 1) {
      std::string caret(d.location.column - 1, ' ');
      // Keep tabs so the caret lines up under the same glyph.
      for (size_t i = 0; i < caret.size() && i < line.size(); ++i)
        if (line[i] == '\t') caret[i] = '\t';
      out << "  " << caret << "^\n";
    }
  }
}

}  // namespace ncc
