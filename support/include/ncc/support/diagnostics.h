#pragma once
// Compiler-style diagnostics: `part.nc:12:7: error[PS0010]: message`, then the source line
// and a caret. The code is the controller's own alarm number when its manual gives one, else
// an ncc code (`NCC` + number, see docs/diagnostics.md).
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "ncc/support/source_location.h"

namespace ncc {

class SourceManager;

enum class Severity : uint8_t { Note, Warning, Error };

struct Diagnostic {
  Severity severity = Severity::Error;
  std::string code;  // "PS0010", "818", "61003", "NCC1001", ...
  std::string message;
  SourceLocation location;
};

// Collects diagnostics of one run. Errors are counted so that every stage can ask whether
// it may still write output; nothing is printed until print() is called.
class DiagnosticEngine {
 public:
  explicit DiagnosticEngine(const SourceManager* sources = nullptr) : sources_(sources) {}

  // The same diagnostic (severity, code, location, message) twice is reported once.
  void report(Severity severity, std::string code, SourceLocation where, std::string message);
  void error(std::string code, SourceLocation where, std::string message) {
    report(Severity::Error, std::move(code), where, std::move(message));
  }
  void warning(std::string code, SourceLocation where, std::string message) {
    report(Severity::Warning, std::move(code), where, std::move(message));
  }

  // Forgets every diagnostic (a new phase, e.g. the run after a compile, reports afresh).
  void clear() {
    diagnostics_.clear();
    reported_.clear();
    error_count_ = 0;
  }

  bool hasErrors() const { return error_count_ > 0; }
  size_t errorCount() const { return error_count_; }
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

  // After this many errors further ones are counted but not stored (a runaway file must not
  // exhaust memory); the last stored one says so.
  void setErrorLimit(size_t limit) { error_limit_ = limit; }

  // Prints every diagnostic in the order reported, each with its source line (at most 120
  // characters of it around the caret, "..." marking what is cut) and a caret.
  void print(std::ostream& out) const;
  // One diagnostic as text (without the quoted source line): "file:line:col: error[CODE]: msg".
  // Locations store byte columns; the printed column counts characters (UTF-8 code points)
  // of the source line.
  std::string format(const Diagnostic& d) const;
  // The quoted source line and caret lines for a 1-based byte column (0: no caret).
  static std::string quoteLine(std::string_view line, uint32_t byte_column);

 private:
  std::string format(const Diagnostic& d, std::string_view line) const;

  const SourceManager* sources_;
  std::vector<Diagnostic> diagnostics_;
  std::unordered_set<std::string> reported_;  // each diagnostic once (report())
  size_t error_count_ = 0;
  size_t error_limit_ = 200;
};

}  // namespace ncc
