#pragma once
// Private to the machine-file reader: typed access to toml++ nodes that reports every
// problem as a diagnostic at the node's (or key's) line and column instead of throwing.
#include <toml++/toml.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ncc/support/diagnostics.h"

namespace ncc::machine_file {

// Diagnostic codes of the machine-file reader (docs/machine-file.md).
inline constexpr std::string_view kCannotRead = "NCC0300";
inline constexpr std::string_view kSyntax = "NCC0301";
inline constexpr std::string_view kUnknownKey = "NCC0302";
inline constexpr std::string_view kWrongType = "NCC0303";
inline constexpr std::string_view kUnknownAxis = "NCC0304";
inline constexpr std::string_view kBadAxes = "NCC0305";
inline constexpr std::string_view kBadValue = "NCC0306";
inline constexpr std::string_view kNoEffect = "NCC0307";  // a warning

// "a string", "an integer", "a table", ...: how a TOML value's type is named in messages.
std::string_view tomlTypeName(const toml::node& node);

// A table's entries in the order they appear in the file (toml++ keeps them sorted by key),
// so that checks and their diagnostics follow the file.
std::vector<std::pair<const toml::key*, const toml::node*>> inFileOrder(const toml::table& t);

// Collects the reader's errors and hands them to the DiagnosticEngine sorted by position
// (flush()), so a file's errors read top to bottom whatever order the checks ran in.
class TomlContext {
 public:
  TomlContext(uint32_t file, DiagnosticEngine& diags) : file_(file), diags_(diags) {}
  ~TomlContext() { flush(); }
  TomlContext(const TomlContext&) = delete;
  TomlContext& operator=(const TomlContext&) = delete;

  SourceLocation at(const toml::node& node) const { return at(node.source()); }
  SourceLocation at(const toml::key& key) const { return at(key.source()); }
  SourceLocation at(const toml::source_region& region) const;
  SourceLocation fileOnly() const { return SourceLocation{file_, 0, 0}; }

  void error(std::string_view code, SourceLocation where, std::string message);
  // Reported with the errors, in file order; does not count as an error.
  void warning(std::string_view code, SourceLocation where, std::string message);
  size_t errorCount() const { return errors_; }
  void flush();

  // "unknown key 'foo' in [machine]", at the key.
  void unknownKey(const toml::key& key, std::string_view table_name);
  // "wrong type for 'what': expected <expected>, found <actual>", at the value.
  void wrongType(const toml::node& node, std::string_view what, std::string_view expected);

  // Typed reads; each reports a wrong type (and a non-finite number) itself.
  std::optional<double> number(const toml::node& node, std::string_view what);
  std::optional<int64_t> integer(const toml::node& node, std::string_view what);
  std::optional<std::string> string(const toml::node& node, std::string_view what);
  std::optional<bool> boolean(const toml::node& node, std::string_view what);
  const toml::table* table(const toml::node& node, std::string_view what);
  const toml::array* array(const toml::node& node, std::string_view what);

 private:
  struct Pending {
    std::string code;
    SourceLocation where;
    std::string message;
    bool is_warning = false;
  };
  uint32_t file_;
  size_t errors_ = 0;
  DiagnosticEngine& diags_;
  std::vector<Pending> pending_;
};

}  // namespace ncc::machine_file
