#pragma once
// Deep comparison of syntax trees and block stores for tests: the first difference as text
// ("" when equal), so a failed round trip says where it went wrong. Doubles compare by bit
// pattern (-0.0 is not 0.0).
#include <bit>
#include <string>
#include <type_traits>

#include "absl/strings/str_cat.h"
#include "ncc/eval/block_store.h"

namespace ncc::eval::test {

inline std::string locText(const SourceLocation& l) {
  return absl::StrCat(l.file, ":", l.line, ":", l.column);
}
inline std::string posText(const frontend::BlockPosition& p) {
  return absl::StrCat("@", p.offset, "/", p.line, ":", p.column);
}

// The first member that differs, walking the syntax tree by its schema (ast.h): a member added
// to a node's schema is compared without a line here.
template <class T>
std::string diffValue(const T& a, const T& b, const std::string& at) {
  if constexpr (ast::SchemaNode<T>) {
    std::string d;
    ast::forEachField<T>([&](const auto& f) {
      if (d.empty()) d = diffValue(a.*f.member, b.*f.member, absl::StrCat(at, ".", f.name));
    });
    return d;
  } else if constexpr (ast::kIsBox<T> || ast::kIsOptional<T>) {
    if (!a != !b) return at + ": presence";
    return a ? diffValue(*a, *b, at) : "";
  } else if constexpr (ast::kIsList<T>) {
    if (a.size() != b.size()) return absl::StrCat(at, ": ", a.size(), " vs ", b.size(), " items");
    for (size_t i = 0; i < a.size(); ++i)
      if (std::string d = diffValue(a[i], b[i], absl::StrCat(at, "[", i, "]")); !d.empty()) return d;
    return "";
  } else if constexpr (std::is_same_v<T, double>) {
    if (std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b)) return "";
    return absl::StrCat(at, ": ", a, " vs ", b);
  } else if constexpr (std::is_same_v<T, SourceLocation>) {
    return a == b ? "" : at + ": " + locText(a) + " vs " + locText(b);
  } else if constexpr (std::is_enum_v<T>) {
    return a == b ? "" : absl::StrCat(at, ": ", static_cast<int>(a), " vs ", static_cast<int>(b));
  } else if constexpr (ast::kIsInline<T>) {
    return a == b ? "" : absl::StrCat(at, ": ", a.c_str(), " vs ", b.c_str());
  } else {
    return a == b ? "" : absl::StrCat(at, ": ", a, " vs ", b);
  }
}

inline std::string diffBlock(const ast::Block& a, const ast::Block& b, const std::string& at) {
  return diffValue(a, b, at);
}

inline std::string diffStore(const BlockStore& a, const BlockStore& b) {
  if (a.main_file != b.main_file) return "main_file";
  if (a.ahead_blocks != b.ahead_blocks) return "ahead_blocks";
  if (!(a.limits == b.limits)) return "limits";
  if (a.saved_variables.size() != b.saved_variables.size()) return "saved_variables size";
  for (auto i = a.saved_variables.begin(), j = b.saved_variables.begin();
       i != a.saved_variables.end(); ++i, ++j)
    if (i->first != j->first ||
        std::bit_cast<uint64_t>(i->second) != std::bit_cast<uint64_t>(j->second))
      return absl::StrCat("saved variable #", i->first);
  if (a.folder_programs != b.folder_programs) return "folder_programs";
  if (a.named_programs != b.named_programs) return "named_programs";
  if (a.files.size() != b.files.size()) return "file count";
  for (size_t f = 0; f < a.files.size(); ++f) {
    const StoredFile& x = a.files[f];
    const StoredFile& y = b.files[f];
    const std::string at = absl::StrCat("file ", x.id);
    if (x.id != y.id || x.name != y.name) return at + ": header";
    if (!(x.record_end == y.record_end)) return at + ": record_end";
    if (x.blocks.size() != y.blocks.size()) return at + ": block count";
    for (size_t i = 0; i < x.blocks.size(); ++i) {
      const std::string bt = absl::StrCat(at, " block ", i);
      if (!(x.blocks[i].position == y.blocks[i].position))
        return bt + ": position " + posText(x.blocks[i].position) + " vs " + posText(y.blocks[i].position);
      if (x.blocks[i].start != y.blocks[i].start) return bt + ": start";
      if (std::string d = diffBlock(x.blocks[i].block, y.blocks[i].block, bt); !d.empty()) return d;
    }
  }
  return "";
}

}  // namespace ncc::eval::test
