#include "source_program_store.h"

#include <algorithm>

#include "absl/container/flat_hash_map.h"

namespace ncc::driver {

namespace {

// A file's blocks through a BlockReader. Once the cursor has gone back (a loop, a repeat), the
// blocks it reads are kept, parsed, by where they start, so a loop body is parsed once rather
// than on every turn; a cursor that only reads forward keeps nothing. Replaying a kept block
// does not touch the file: the reader is moved (a seek of its stream, a system call) only when
// a block must be read again. The cache is bounded: past kMaxCached blocks it starts again, so
// a multi-million-line program still streams.
class ReaderCursor final : public eval::BlockCursor {
 public:
  ReaderCursor(const SourceManager& sources, uint32_t file, DiagnosticEngine& diags,
               frontend::ReaderOptions options)
      : reader_(sources, file, diags, options) {}

  const ast::Block* next() override {
    if (!replaying_) return reader_.next(current_) ? &current_ : nullptr;
    if (const Cached* hit = find(at_)) {
      last_ = hit->at;
      at_ = hit->after;
      return &hit->block;  // stays until the next call: only a later insert may move it
    }
    syncReader();
    const frontend::BlockPosition from = at_;
    const bool read = reader_.next(current_);
    last_.reset();
    at_ = reader_.position();
    if (!read) return nullptr;
    if (cache_.size() >= kMaxCached) cache_.clear();
    cache_.insert_or_assign(key(from), Cached{from, reader_.lastPosition(), at_, current_});
    return &current_;
  }
  eval::ProgramPoint lastPoint() const override {
    return {reader_.file(), last_ ? *last_ : reader_.lastPosition()};
  }
  void seek(const eval::ProgramPoint& point) override {
    replaying_ = true;
    last_.reset();
    at_ = point.position;
    synced_ = false;
  }
  uint64_t rejectedBlocks() const override { return reader_.stats().rejected_blocks; }
  uint32_t file() const override { return reader_.file(); }

  // The reader, where this cursor stands.
  frontend::BlockReader& reader() {
    if (replaying_) syncReader();
    return reader_;
  }

 private:
  static constexpr size_t kMaxCached = 4096;
  struct Cached {
    frontend::BlockPosition from;   // where reading stood (blank text may precede the block)
    frontend::BlockPosition at;     // where the block starts
    frontend::BlockPosition after;  // where reading goes on
    ast::Block block;
  };
  static uint64_t key(const frontend::BlockPosition& p) { return p.offset * 4096u + p.column; }
  const Cached* find(const frontend::BlockPosition& from) const {
    auto it = cache_.find(key(from));
    // The language is part of a position: text read in another language is another block.
    if (it == cache_.end() || !(it->second.from == from)) return nullptr;
    return &it->second;
  }
  void syncReader() {
    if (synced_) return;
    reader_.seek(at_);
    synced_ = true;
  }

  frontend::BlockReader reader_;
  bool replaying_ = false;
  // While replaying: where the next block starts, and whether the reader stands there.
  frontend::BlockPosition at_;
  bool synced_ = true;
  std::optional<frontend::BlockPosition> last_;  // lastPoint() of a block from the cache
  ast::Block current_;  // the block last read from the file, refilled by each read
  absl::flat_hash_map<uint64_t, Cached> cache_;
};

frontend::SequenceSearch toFrontend(eval::SequenceSearch order) {
  switch (order) {
    case eval::SequenceSearch::ForwardThenFromStart: return frontend::SequenceSearch::ForwardThenFromStart;
    case eval::SequenceSearch::FromStart: return frontend::SequenceSearch::FromStart;
    case eval::SequenceSearch::Forward: return frontend::SequenceSearch::Forward;
    case eval::SequenceSearch::Backward: return frontend::SequenceSearch::Backward;
  }
  return frontend::SequenceSearch::FromStart;
}

}  // namespace

SourceProgramStore::SourceProgramStore(SourceManager& sources, DiagnosticEngine& diags,
                                       std::filesystem::path program_dir,
                                       std::vector<std::string> name_patterns,
                                       frontend::ReaderOptions options)
    : sources_(sources),
      diags_(diags),
      options_(options),
      library_(sources, program_dir, name_patterns, options),
      folder_(std::move(program_dir)) {
  for (const std::string& pattern : name_patterns) {
    const std::string ext = std::filesystem::path(pattern).extension().string();
    if (!ext.empty() && std::find(extensions_.begin(), extensions_.end(), ext) == extensions_.end())
      extensions_.push_back(ext);
  }
}

std::optional<eval::ProgramPoint> SourceProgramStore::findProgramNamed(std::string_view name) {
  if (folder_.empty() || name.empty() || name.find('/') != std::string_view::npos) return std::nullopt;
  std::vector<std::filesystem::path> candidates{folder_ / std::string(name)};
  for (const std::string& ext : extensions_) candidates.push_back(folder_ / (std::string(name) + ext));
  for (const std::filesystem::path& path : candidates) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) continue;
    const eval::ProgramPoint found{sources_.addFile(path.lexically_normal()), {}};
    named_.insert_or_assign(std::string(name), found);
    return found;
  }
  return std::nullopt;
}

std::unique_ptr<eval::BlockCursor> SourceProgramStore::open(uint32_t file) {
  opened_.insert(file);
  return std::make_unique<ReaderCursor>(sources_, file, diags_, options_);
}

std::optional<eval::ProgramPoint> SourceProgramStore::findProgram(int64_t number,
                                                                  uint32_t calling_file) {
  std::optional<frontend::ProgramLibrary::Found> found = library_.find(number, calling_file);
  if (number >= 0 && !library_.index(calling_file).findProgram(number))
    folder_numbers_.insert(number);  // the answer (or none) came from the folder
  if (!found) return std::nullopt;
  return eval::ProgramPoint{found->file, found->start};
}

std::optional<eval::ProgramPoint> SourceProgramStore::findInFolder(int64_t number) {
  std::optional<frontend::ProgramLibrary::Found> found = library_.findInFolder(number);
  if (!found) return std::nullopt;
  return eval::ProgramPoint{found->file, found->start};
}

std::optional<eval::ProgramPoint> SourceProgramStore::findSequence(
    int64_t n, const eval::ProgramPoint& from, eval::SequenceSearch order,
    const eval::ProgramPoint& begin, const eval::ProgramPoint& end) {
  std::optional<frontend::BlockPosition> p = library_.index(from.file).findSequence(
      n, from.position, toFrontend(order), frontend::BlockRange{begin.position, end.position});
  if (!p) return std::nullopt;
  return eval::ProgramPoint{from.file, *p};
}

std::optional<eval::ProgramPoint> SourceProgramStore::findLabel(
    std::string_view label, const eval::ProgramPoint& from, eval::SequenceSearch order,
    const eval::ProgramPoint& begin, const eval::ProgramPoint& end) {
  std::optional<frontend::BlockPosition> p = library_.index(from.file).findLabel(
      label, from.position, toFrontend(order), frontend::BlockRange{begin.position, end.position});
  if (!p) return std::nullopt;
  return eval::ProgramPoint{from.file, *p};
}

eval::ProgramPoint SourceProgramStore::programEnd(const eval::ProgramPoint& start) {
  return {start.file, library_.index(start.file).programEnd(start.position)};
}

frontend::BlockReader& SourceProgramStore::readerOf(eval::BlockCursor& cursor) {
  return static_cast<ReaderCursor&>(cursor).reader();
}

}  // namespace ncc::driver
