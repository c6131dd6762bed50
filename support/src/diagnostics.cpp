#include "ncc/support/diagnostics.h"

#include <string_view>
#include <vector>

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
  if (severity == Severity::Error && error_count_ >= error_limit_) {
    ++error_count_;  // counted, not stored (nor remembered)
    return;
  }
  // A block run again (a loop, a repeated subprogram) reports its fault once.
  if (!reported_
           .insert(absl::StrCat(static_cast<int>(severity), "|", code, "|", where.file, ":",
                                where.line, ":", where.column, "|", message))
           .second)
    return;
  if (severity == Severity::Error) {
    ++error_count_;
    if (error_count_ > error_limit_) return;
    if (error_count_ == error_limit_) {
      message += absl::StrCat(" (error limit of ", error_limit_, " reached; further errors are not shown)");
    }
  }
  diagnostics_.push_back(Diagnostic{severity, std::move(code), std::move(message), where});
}

namespace {
// UTF-8 continuation bytes (10xxxxxx) do not start a character.
bool startsCharacter(char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }

// The 1-based character (code point) column of a 1-based byte column in `line`. Columns past
// the end of the line (an error at the end of a block) count one character per byte.
uint32_t characterColumn(std::string_view line, uint32_t byte_column) {
  if (byte_column == 0) return 0;
  size_t bytes = byte_column - 1;
  uint32_t chars = 0;
  for (size_t i = 0; i < bytes && i < line.size(); ++i) chars += startsCharacter(line[i]);
  if (bytes > line.size()) chars += static_cast<uint32_t>(bytes - line.size());
  return chars + 1;
}

// At most this many characters of a source line are quoted: a line of a megabyte quoted once
// per diagnostic on it would flood the terminal.
constexpr size_t kQuoteWidth = 120;
constexpr std::string_view kElided = "...";
}  // namespace

std::string DiagnosticEngine::format(const Diagnostic& d, std::string_view line) const {
  std::string where;
  uint32_t column = d.location.column;
  if (!line.empty()) column = characterColumn(line, column);
  if (sources_ && d.location.file != 0) {
    where = sources_->displayName(d.location.file);
    if (d.location.line) absl::StrAppend(&where, ":", d.location.line);
    if (column) absl::StrAppend(&where, ":", column);
    where += ": ";
  } else if (d.location.line) {
    where = absl::StrCat("<input>:", d.location.line, ":", column, ": ");
  }
  std::string code = d.code.empty() ? "" : absl::StrCat("[", d.code, "]");
  return absl::StrCat(where, severityName(d.severity), code, ": ", d.message);
}

std::string DiagnosticEngine::format(const Diagnostic& d) const {
  std::string line;
  if (sources_ && d.location.file != 0 && d.location.line != 0)
    line = sources_->lineText(d.location.file, d.location.line);
  return format(d, line);
}

void DiagnosticEngine::print(std::ostream& out) const {
  // Diagnostics of one line usually follow each other: the line is read once for them.
  uint32_t cached_file = 0, cached_line = 0;
  std::string line;
  for (const Diagnostic& d : diagnostics_) {
    bool located = sources_ && d.location.file != 0 && d.location.line != 0;
    if (located && (d.location.file != cached_file || d.location.line != cached_line)) {
      line = sources_->lineText(d.location.file, d.location.line);
      cached_file = d.location.file;
      cached_line = d.location.line;
    }
    std::string_view text = located ? std::string_view(line) : std::string_view();
    out << format(d, text) << '\n';
    if (text.empty()) continue;
    out << quoteLine(text, d.location.column);
  }
}

std::string DiagnosticEngine::quoteLine(std::string_view line, uint32_t byte_column) {
  // Character starts, so that the window and the caret count characters, not bytes.
  std::vector<size_t> starts;
  for (size_t i = 0; i < line.size(); ++i)
    if (startsCharacter(line[i])) starts.push_back(i);
  size_t chars = starts.size();
  auto byteOf = [&](size_t ch) { return ch < chars ? starts[ch] : line.size(); };
  size_t caret = byte_column >= 1 ? characterColumn(line, byte_column) - 1 : 0;
  // The window: kQuoteWidth characters, the caret near its middle, clamped to the line.
  size_t first = 0, last = chars;
  if (chars > kQuoteWidth) {
    first = caret > kQuoteWidth / 2 ? caret - kQuoteWidth / 2 : 0;
    if (first + kQuoteWidth > chars) first = chars - kQuoteWidth;
    last = first + kQuoteWidth;
  }
  std::string shown(line.substr(byteOf(first), byteOf(last) - byteOf(first)));
  // Control bytes (NUL, CR, ESC ...) would garble the terminal; one '?' each keeps the caret
  // in place. Tabs stay, and bytes >= 0x80 stay for UTF-8 comments.
  for (char& c : shown)
    if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7F) c = '?';
  std::string lead = first > 0 ? std::string(kElided) : std::string();
  std::string result = "  " + lead + shown;
  if (last < chars) result += kElided;
  result += '\n';
  if (byte_column >= 1) {
    // One space per character before the caret; tabs stay tabs so the caret lines up under
    // the same glyph.
    std::string pad(lead.size(), ' ');
    for (size_t ch = first; ch < caret; ++ch)
      pad += ch < chars && line[starts[ch]] == '\t' ? '\t' : ' ';
    absl::StrAppend(&result, "  ", pad, "^\n");
  }
  return result;
}

}  // namespace ncc
