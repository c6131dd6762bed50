#include "ncc/bytecode/code_view.h"

#include <algorithm>

#include "bytes.h"

namespace ncc::bytecode {

CodeView::Window::Window(const ProgramFile* file, uint64_t base, uint64_t limit)
    : file_(file), base_(base), limit_(limit), buffer_(std::min<uint64_t>(kPageSize, limit)) {}

std::span<const uint8_t> CodeView::Window::bytes(uint64_t begin, std::size_t count) {
  if (begin >= limit_) return {};
  count = static_cast<std::size_t>(std::min<uint64_t>(count, limit_ - begin));
  if (!holds(begin, count)) {
    // A little of what lies before stays in the window: the line lookup looks at the entry
    // before the one that crossed into a new window once more.
    constexpr uint64_t kBehind = 4 * kLineEntrySize;
    start_ = begin >= kBehind ? begin - kBehind : 0;
    const std::size_t want =
        static_cast<std::size_t>(std::min<uint64_t>(buffer_.size(), limit_ - start_));
    filled_ = file_->read(base_ + start_, buffer_.data(), want);
    if (!holds(begin, count)) count = filled_ > begin - start_ ? filled_ - (begin - start_) : 0;
  }
  return std::span<const uint8_t>(buffer_.data() + (begin - start_), count);
}

CodeView::CodeView(const Program& program)
    : program_(program),
      code_size_(program.codeSize()),
      line_count_(program.paged ? program.paged->line_count : program.lines.size()) {
  if (const std::optional<PagedSections>& p = program.paged) {
    code_window_ = Window(p->file.get(), p->code_offset, p->code_size);
    line_window_ = Window(p->file.get(), p->lines_offset,
                          uint64_t{p->line_count} * kLineEntrySize);
  }
}

DecodeStatus CodeView::decode(uint32_t offset, int axis_count, Instruction& out,
                              uint32_t& size) {
  if (!program_.paged) return bytecode::decode(program_.code, offset, axis_count, out, size);
  if (offset >= code_size_) return DecodeStatus::Truncated;
  // The largest instruction fits in any window; the section's end cuts it short as the
  // end of the in-memory code would.
  return bytecode::decode(code_window_.bytes(offset, maxInstructionSize()), 0, axis_count, out,
                          size);
}

uint8_t CodeView::byteAt(uint32_t offset) {
  if (!program_.paged) return offset < program_.code.size() ? program_.code[offset] : 0;
  std::span<const uint8_t> b = code_window_.bytes(offset, 1);
  return b.empty() ? 0 : b[0];
}

std::optional<LineEntry> CodeView::line(std::size_t index) {
  if (index >= line_count_) return std::nullopt;
  if (!program_.paged) return program_.lines[index];
  std::span<const uint8_t> b = line_window_.bytes(uint64_t{index} * kLineEntrySize,
                                                  kLineEntrySize);
  if (b.size() < kLineEntrySize) return std::nullopt;
  const uint8_t* p = b.data();
  return LineEntry{bytes::getU32(p), bytes::getU32(p + 4), bytes::getU32(p + 8),
                   bytes::getU32(p + 12)};
}

std::optional<std::size_t> CodeView::searchLine(uint32_t offset) {
  // Binary search for the last entry at or before `offset`. A paged search first tries the
  // entries already in the window (a loop jumps back a little), so it refills rarely.
  std::size_t lo = 0, hi = line_count_;  // the first entry after `offset` is in [lo, hi]
  if (program_.paged) {
    const std::size_t begin = line_window_.start() / kLineEntrySize;
    const std::size_t end = begin + line_window_.filled() / kLineEntrySize;
    if (end > begin + 1) {
      std::optional<LineEntry> first = line(begin), last = line(end - 1);
      if (first && last && first->offset <= offset && offset < last->offset) {
        lo = begin + 1;
        hi = end - 1;
      }
    }
  }
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    std::optional<LineEntry> e = line(mid);
    if (!e) return std::nullopt;
    if (e->offset <= offset) lo = mid + 1; else hi = mid;
  }
  if (lo == 0) return std::nullopt;
  return lo - 1;
}

std::optional<LineEntry> CodeView::lineFor(uint32_t offset, std::size_t& hint) {
  // Entry i is the answer when it starts at or before `offset` and the next one after it.
  auto answers = [&](std::size_t i) -> std::optional<LineEntry> {
    std::optional<LineEntry> e = line(i);
    if (!e || e->offset > offset) return std::nullopt;
    if (i + 1 < line_count_) {
      std::optional<LineEntry> next = line(i + 1);
      if (!next || offset >= next->offset) return std::nullopt;
    }
    return e;
  };
  if (std::optional<LineEntry> e = answers(hint)) return e;
  if (std::optional<LineEntry> e = answers(hint + 1)) {
    ++hint;
    return e;
  }
  std::optional<std::size_t> found = searchLine(offset);
  if (!found) return std::nullopt;
  hint = *found;
  return line(hint);
}

}  // namespace ncc::bytecode
