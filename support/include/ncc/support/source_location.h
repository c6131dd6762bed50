#pragma once
// A position in a program source: which file (an index into the SourceManager), which
// 1-based line and 1-based column. Small and trivially copyable: every AST node, IR block
// and bytecode line-table entry carries one.
#include <cstdint>

namespace ncc {

struct SourceLocation {
  uint32_t file = 0;    // SourceManager file id; 0 means "no file" (e.g. a machine file key)
  uint32_t line = 0;    // 1-based; 0 = unknown
  uint32_t column = 0;  // 1-based, in bytes of the line (printed as characters); 0 = whole line

  bool valid() const { return line != 0; }
  friend bool operator==(const SourceLocation&, const SourceLocation&) = default;
};

}  // namespace ncc
