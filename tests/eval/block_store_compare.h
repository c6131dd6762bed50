#pragma once
// Deep comparison of syntax trees and block stores for tests: the first difference as text
// ("" when equal), so a failed round trip says where it went wrong. Doubles compare by bit
// pattern (-0.0 is not 0.0).
#include <bit>
#include <string>

#include "absl/strings/str_cat.h"
#include "ncc/eval/block_store.h"

namespace ncc::eval::test {

inline std::string locText(const SourceLocation& l) {
  return absl::StrCat(l.file, ":", l.line, ":", l.column);
}
inline std::string posText(const frontend::BlockPosition& p) {
  return absl::StrCat("@", p.offset, "/", p.line, ":", p.column);
}

inline std::string diffExpr(const ast::Expr& a, const ast::Expr& b, const std::string& at) {
  if (a.kind != b.kind) return at + ": kind";
  if (std::bit_cast<uint64_t>(a.number) != std::bit_cast<uint64_t>(b.number))
    return absl::StrCat(at, ": number ", a.number, " vs ", b.number);
  if (a.has_point != b.has_point) return at + ": has_point";
  if (a.digits != b.digits) return at + ": digits";
  if (a.op != b.op) return absl::StrCat(at, ": op ", ast::opText(a.op), " vs ", ast::opText(b.op));
  if (!(a.loc == b.loc)) return at + ": loc " + locText(a.loc) + " vs " + locText(b.loc);
  if (a.args.size() != b.args.size()) return at + ": argument count";
  for (size_t i = 0; i < a.args.size(); ++i)
    if (std::string d = diffExpr(a.args[i], b.args[i], absl::StrCat(at, ".arg", i)); !d.empty())
      return d;
  return "";
}

inline std::string diffStatement(const ast::Statement& a, const ast::Statement& b,
                                 const std::string& at) {
  if (a.kind != b.kind) return at + ": kind";
  if (a.loop_id != b.loop_id) return at + ": loop_id";
  if (!(a.loc == b.loc)) return at + ": loc";
  if (std::string d = diffExpr(a.target, b.target, at + ".target"); !d.empty()) return d;
  if (std::string d = diffExpr(a.value, b.value, at + ".value"); !d.empty()) return d;
  if (!a.then_assign != !b.then_assign) return at + ": then_assign presence";
  if (a.then_assign) return diffStatement(*a.then_assign, *b.then_assign, at + ".then");
  return "";
}

inline std::string diffBlock(const ast::Block& a, const ast::Block& b, const std::string& at) {
  if (!(a.loc == b.loc)) return at + ": loc " + locText(a.loc) + " vs " + locText(b.loc);
  if (a.skip_level != b.skip_level) return at + ": skip_level";
  if (a.sequence != b.sequence) return at + ": sequence";
  if (a.program_number != b.program_number) return at + ": program_number";
  if (a.percent != b.percent) return at + ": percent";
  if (a.comments != b.comments) return at + ": comments";
  if (a.words.size() != b.words.size()) return at + ": word count";
  for (size_t i = 0; i < a.words.size(); ++i) {
    const std::string w = absl::StrCat(at, ".word", i);
    if (a.words[i].address != b.words[i].address) return w + ": address";
    if (!(a.words[i].loc == b.words[i].loc)) return w + ": loc";
    if (std::string d = diffExpr(a.words[i].value, b.words[i].value, w); !d.empty()) return d;
  }
  if (a.statements.size() != b.statements.size()) return at + ": statement count";
  for (size_t i = 0; i < a.statements.size(); ++i)
    if (std::string d = diffStatement(a.statements[i], b.statements[i], absl::StrCat(at, ".stmt", i));
        !d.empty())
      return d;
  return "";
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
    if (x.id != y.id || x.name != y.name || x.language != y.language) return at + ": header";
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
