#pragma once
// A program store over blocks held in memory, as a run-time user of the evaluator (the VM)
// would hand them over: one "file" per list of blocks; a block's position is its index
// (offset) and line. No parser: the tests that parse text turn it into blocks first.
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "ncc/eval/program_store.h"

namespace ncc::eval::test {

class MemoryStore final : public ProgramStore {
 public:
  // Adds a file; returns its id (1, 2, ...).
  uint32_t add(std::vector<ast::Block> blocks) {
    files_.push_back(std::move(blocks));
    return static_cast<uint32_t>(files_.size());
  }
  // The id add() gives the next file.
  uint32_t nextFile() const { return static_cast<uint32_t>(files_.size()) + 1; }

  class Cursor final : public BlockCursor {
   public:
    Cursor(const std::vector<ast::Block>& blocks, uint32_t file) : blocks_(blocks), file_(file) {}
    const ast::Block* next() override {
      if (i_ >= blocks_.size()) return nullptr;
      last_ = i_;
      return &blocks_[i_++];
    }
    ProgramPoint lastPoint() const override { return point(file_, last_); }
    void seek(const ProgramPoint& p) override { i_ = p.position.offset; }
    uint64_t rejectedBlocks() const override { return 0; }
    uint32_t file() const override { return file_; }

   private:
    const std::vector<ast::Block>& blocks_;
    uint32_t file_;
    size_t i_ = 0, last_ = 0;
  };

  std::unique_ptr<BlockCursor> open(uint32_t file) override {
    return std::make_unique<Cursor>(files_[file - 1], file);
  }
  std::optional<ProgramPoint> findProgram(int64_t number, uint32_t) override {
    for (uint32_t f = 1; f <= files_.size(); ++f)
      for (size_t i = 0; i < files_[f - 1].size(); ++i)
        if (files_[f - 1][i].program_number == number) return point(f, i);
    return std::nullopt;
  }
  std::optional<ProgramPoint> findProgramNamed(std::string_view) override { return std::nullopt; }
  std::optional<ProgramPoint> findSequence(int64_t n, const ProgramPoint& from, SequenceSearch order,
                                           const ProgramPoint& begin,
                                           const ProgramPoint& end) override {
    return find([n](const ast::Block& b) { return b.sequence == n; }, from, order, begin, end);
  }
  std::optional<ProgramPoint> findLabel(std::string_view label, const ProgramPoint& from,
                                        SequenceSearch order, const ProgramPoint& begin,
                                        const ProgramPoint& end) override {
    return find(
        [label](const ast::Block& b) {
          for (const ast::Statement& st : b.statements)
            if (st.kind == ast::Statement::Kind::Label && st.target.text && *st.target.text == label)
              return true;
          return false;
        },
        from, order, begin, end);
  }
  ProgramPoint programEnd(const ProgramPoint& start) override {
    const std::vector<ast::Block>& b = files_[start.file - 1];
    for (size_t i = start.position.offset + 1; i < b.size(); ++i)
      if (b[i].program_number) return point(start.file, i);
    return point(start.file, b.size());
  }

 private:
  template <class Match>
  std::optional<ProgramPoint> find(Match match, const ProgramPoint& from, SequenceSearch order,
                                   const ProgramPoint& begin, const ProgramPoint& end) {
    const std::vector<ast::Block>& b = files_[from.file - 1];
    const size_t first = begin.position.offset, last = end.position.offset;
    std::vector<size_t> order_of;
    switch (order) {
      case SequenceSearch::ForwardThenFromStart:
      case SequenceSearch::Forward:
        for (size_t i = from.position.offset + 1; i < last; ++i) order_of.push_back(i);
        if (order == SequenceSearch::ForwardThenFromStart)
          for (size_t i = first; i <= from.position.offset; ++i) order_of.push_back(i);
        break;
      case SequenceSearch::Backward:
        for (size_t i = from.position.offset + 1; i-- > first;) order_of.push_back(i);
        break;
      case SequenceSearch::FromStart:
        for (size_t i = first; i < last; ++i) order_of.push_back(i);
        break;
    }
    for (size_t i : order_of)
      if (i < b.size() && match(b[i])) return point(from.file, i);
    return std::nullopt;
  }
  static ProgramPoint point(uint32_t file, size_t i) {
    return ProgramPoint{file, frontend::BlockPosition{i, static_cast<uint32_t>(i + 1), 1}};
  }
  std::vector<std::vector<ast::Block>> files_;
};

}  // namespace ncc::eval::test
