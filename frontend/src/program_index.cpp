#include "ncc/frontend/program_index.h"

#include <algorithm>

#include "block_cursor.h"
#include "block_start.h"
#include "language_switch.h"

namespace ncc::frontend {

namespace {

// Lookups cached per index, at most: a computed GOTO (`GOTO #1`) over many values must not
// grow memory without bound. Past it the cache starts again.
constexpr size_t kMaxCachedLookups = 1 << 16;

size_t mix(size_t h, uint64_t v) { return h ^ (std::hash<uint64_t>{}(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2)); }

// The start of a file: the first block that is not blank, and the program number it carries.
struct Head {
  std::optional<BlockPosition> first_content;  // the opening '%' counts (a later '%' closes)
  std::optional<int64_t> program_number;
};

Head readHead(BlockCursor& cursor, bool semicolon_ends_block, Language language) {
  Head head;
  BlockCursor::Segment s;
  while (cursor.next(s, semicolon_ends_block)) {
    s.at.language = language;  // nothing before the first content can switch it
    const BlockStart start = blockStart(s.text);
    if (start.kind == BlockStart::Kind::Blank) continue;
    if (start.kind == BlockStart::Kind::Percent) {
      if (head.first_content) break;  // a second '%' closes an empty record
      head.first_content = s.at;      // the opening '%'
      continue;
    }
    if (!head.first_content) head.first_content = s.at;
    if (start.kind == BlockStart::Kind::Program) head.program_number = start.number;
    break;
  }
  return head;
}

bool semicolonEndsBlock(const ReaderOptions& options) {
  return options.semicolon_ends_block && options.initial_language == Language::Iso;
}

}  // namespace

size_t ProgramIndex::KeyHash::operator()(const Key& k) const {
  size_t h = std::hash<int64_t>{}(k.n) ^ std::hash<std::string>{}(k.label);
  h = mix(h, k.from_offset);
  h = mix(h, (uint64_t{k.from_column} << 8) | (static_cast<uint64_t>(k.order) << 1) | k.has_range);
  if (k.has_range) {
    h = mix(h, k.first.offset);
    h = mix(h, k.first.column);
    h = mix(h, k.end.offset);
    h = mix(h, k.end.column);
  }
  return h;
}

ProgramIndex::ProgramIndex(const SourceManager& sources, uint32_t file, ReaderOptions options)
    : sources_(sources),
      file_(file),
      semicolon_ends_block_(semicolonEndsBlock(options)),
      initial_language_(startLanguage(sources, file, options)),
      language_switch_(options.language_switch) {}

Language ProgramIndex::languageAfterSegment(std::string_view text, Language now) const {
  return language_switch_ ? languageAfterText(text, now) : now;
}

std::optional<int64_t> ProgramIndex::firstProgramNumberOf(const std::filesystem::path& path,
                                                          ReaderOptions options) {
  BlockCursor cursor(path);
  return readHead(cursor, semicolonEndsBlock(options), options.initial_language).program_number;
}

void ProgramIndex::scanHead() {
  if (head_scanned_) return;
  head_scanned_ = true;
  BlockCursor cursor(sources_, file_);
  ++stats_.scans;
  const Head head = readHead(cursor, semicolon_ends_block_, initial_language_);
  first_content_ = head.first_content;
  first_program_number_ = head.program_number;
  stats_.lines += cursor.linesRead();
}

std::optional<BlockPosition> ProgramIndex::scanFor(Target target, BlockPosition start,
                                                   std::optional<BlockPosition> after,
                                                   std::optional<BlockPosition> through,
                                                   std::optional<BlockPosition> end, bool last) {
  scanHead();
  BlockCursor cursor(sources_, file_);
  ++stats_.scans;
  cursor.seek(start);
  std::optional<BlockPosition> found;
  BlockCursor::Segment s;
  for (Language now = languageAt(start, initial_language_);
       cursor.next(s, semicolon_ends_block_);
       now = languageAfterSegment(s.text, now)) {
    s.at.language = now;
    if (end && !(s.at < *end)) break;
    if (through && *through < s.at) break;
    const BlockStart b = blockStart(s.text);
    if (b.kind == BlockStart::Kind::Percent && first_content_ && *first_content_ < s.at)
      break;  // the end of the record
    if (target.label.empty()) {
      if (b.kind != BlockStart::Kind::Sequence || b.number != target.n) continue;
    } else if (now != Language::Din || !sameLabel(blockLabel(s.text), target.label)) {
      continue;
    }
    if (after && s.at <= *after) continue;
    found = s.at;
    if (!last) break;
  }
  stats_.lines += cursor.linesRead();
  return found;
}

std::optional<BlockPosition> ProgramIndex::findSequence(int64_t n, BlockPosition from,
                                                        SequenceSearch order,
                                                        std::optional<BlockRange> within) {
  return find(Target{n, {}}, from, order, within);
}

std::optional<BlockPosition> ProgramIndex::findLabel(std::string_view label, BlockPosition from,
                                                     SequenceSearch order,
                                                     std::optional<BlockRange> within) {
  if (label.empty()) return std::nullopt;
  return find(Target{0, label}, from, order, within);
}

std::optional<BlockPosition> ProgramIndex::find(Target target, BlockPosition from,
                                                SequenceSearch order,
                                                std::optional<BlockRange> within) {
  const Key key{target.n,
                std::string(target.label),
                from.offset,
                from.column,
                order,
                within.has_value(),
                within ? within->first : BlockPosition{},
                within ? within->second : BlockPosition{}};
  if (auto it = sequences_.find(key); it != sequences_.end()) return it->second;

  const BlockPosition begin = within ? within->first : BlockPosition{};
  const std::optional<BlockPosition> end =
      within ? std::optional<BlockPosition>(within->second) : std::nullopt;
  std::optional<BlockPosition> found;
  switch (order) {
    case SequenceSearch::ForwardThenFromStart:
    case SequenceSearch::Forward:
      // After `from` to the end; `from` is a block of the file, so reading can start there.
      found = scanFor(target, begin < from ? from : begin, from, std::nullopt, end);
      if (!found && order == SequenceSearch::ForwardThenFromStart)
        found = scanFor(target, begin, std::nullopt, from, end);  // then up to `from`
      break;
    case SequenceSearch::Backward:
      found = scanFor(target, begin, std::nullopt, from, end, /*last=*/true);
      break;
    case SequenceSearch::FromStart:
      found = scanFor(target, begin, std::nullopt, std::nullopt, end);
      break;
  }
  if (sequences_.size() >= kMaxCachedLookups) sequences_.clear();
  sequences_.emplace(key, found);
  return found;
}

void ProgramIndex::scanPrograms() {
  if (programs_scanned_) return;
  programs_scanned_ = true;
  scanHead();
  BlockCursor cursor(sources_, file_);
  ++stats_.scans;
  BlockCursor::Segment s;
  bool closed = false;
  Language now = initial_language_;
  for (; cursor.next(s, semicolon_ends_block_); now = languageAfterSegment(s.text, now)) {
    s.at.language = now;
    const BlockStart b = blockStart(s.text);
    if (b.kind == BlockStart::Kind::Percent && first_content_ && *first_content_ < s.at) {
      record_end_ = s.at;
      closed = true;
      break;
    }
    // DIN has no O numbers: its `:n` is a main block's number (docs/din.md).
    if (b.kind == BlockStart::Kind::Program && now == Language::Iso)
      programs_.push_back(ProgramBlock{b.number, s.at});
  }
  if (!closed) {
    record_end_ = cursor.position();
    record_end_.language = now;
  }
  stats_.lines += cursor.linesRead();
}

std::optional<BlockPosition> ProgramIndex::findProgram(int64_t n) {
  scanPrograms();
  for (const ProgramBlock& p : programs_)
    if (p.number == n) return p.at;
  return std::nullopt;
}

BlockPosition ProgramIndex::programEnd(BlockPosition start) {
  scanPrograms();
  auto next = std::upper_bound(programs_.begin(), programs_.end(), start,
                               [](const BlockPosition& s, const ProgramBlock& p) { return s < p.at; });
  return next != programs_.end() ? next->at : record_end_;
}

std::vector<ProgramIndex::Label> ProgramIndex::labels() {
  scanHead();
  BlockCursor cursor(sources_, file_);
  ++stats_.scans;
  std::vector<Label> out;
  BlockCursor::Segment s;
  for (Language now = initial_language_; cursor.next(s, semicolon_ends_block_);
       now = languageAfterSegment(s.text, now)) {
    s.at.language = now;
    const BlockStart b = blockStart(s.text);
    if (b.kind == BlockStart::Kind::Percent && first_content_ && *first_content_ < s.at) break;
    if (b.kind == BlockStart::Kind::Sequence || b.kind == BlockStart::Kind::Program)
      out.push_back(Label{b.kind == BlockStart::Kind::Program, b.number, s.at});
  }
  stats_.lines += cursor.linesRead();
  return out;
}

BlockPosition ProgramIndex::recordEnd() {
  scanPrograms();
  return record_end_;
}

std::optional<int64_t> ProgramIndex::firstProgramNumber() {
  scanHead();
  return first_program_number_;
}

}  // namespace ncc::frontend
