#include "ncc/bytecode/writer.h"

#include <algorithm>
#include <array>
#include <limits>

#include "absl/strings/str_cat.h"
#include "bytes.h"
#include "header_layout.h"

namespace ncc::bytecode {

StreamWriter::StreamWriter(std::ostream& out, Header header)
    : out_(out), header_(std::move(header)) {
  start_ = out_.tellp();
  if (start_ == std::ostream::pos_type(-1)) {
    fail("NCC7011", "the output stream is not seekable");
    return;
  }
  if (header_.axes.empty() || header_.axes.size() > static_cast<size_t>(kMaxAxes)) {
    fail("NCC7014", absl::StrCat("cannot write ", header_.axes.size(), " axes (1 to ", kMaxAxes,
                                 " are allowed)"));
    return;
  }
  for (const AxisInfo& axis : header_.axes) {
    if (axis.name.empty() || axis.name.size() > kMaxAxisNameLength) {
      fail("NCC7014", absl::StrCat("axis name '", axis.name, "' must have 1 to ",
                                   kMaxAxisNameLength, " characters"));
      return;
    }
  }
  std::vector<uint8_t> bytes = encodeHeader(header_, SectionTable{});
  header_size_ = static_cast<uint32_t>(bytes.size());
  writeBytes(bytes.data(), bytes.size());
  // The axis table never changes; the fixed header is hashed last, once it is final.
  hash_.update(std::span<const uint8_t>(bytes).subspan(kFixedHeaderSize));
  spool_ = std::tmpfile();  // nullptr: fall back to memory_spool_
}

StreamWriter::~StreamWriter() {
  if (spool_ != nullptr) std::fclose(spool_);
}

void StreamWriter::fail(std::string code, std::string message) {
  if (!error_) error_ = Error{std::move(code), std::move(message)};
}

void StreamWriter::writeHashed(const uint8_t* data, size_t size) {
  hash_.update(std::span<const uint8_t>(data, size));
  writeBytes(data, size);
}

void StreamWriter::writeBytes(const uint8_t* data, size_t size) {
  if (error_) return;
  out_.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out_) fail("NCC7011", "write error on the output stream");
}

uint32_t StreamWriter::emit(const Instruction& instruction) {
  const uint32_t at = code_size_;
  // Encoded straight into the buffer.
  if (code_buffered_ + maxInstructionSize() > code_buffer_.size()) flushCode();
  const uint32_t size = encode(instruction, axisCount(), code_buffer_.data() + code_buffered_);
  if (!codeFits(size)) return at;
  code_buffered_ += size;
  code_size_ += size;
  return at;
}

bool StreamWriter::codeFits(size_t size) {
  // Every offset in the file is a u32: the whole file must stay below 4 GiB.
  if (uint64_t{header_size_} + code_size_ + size <= std::numeric_limits<uint32_t>::max() / 2)
    return true;
  fail("NCC7010", "program too large for the bytecode format (code over 2 GiB)");
  return false;
}

void StreamWriter::emitRaw(const uint8_t* data, size_t size) {
  if (!codeFits(size)) return;
  code_size_ += static_cast<uint32_t>(size);
  if (code_buffered_ + size > code_buffer_.size()) {
    flushCode();
    if (size > code_buffer_.size()) return writeHashed(data, size);
  }
  std::copy_n(data, size, code_buffer_.data() + code_buffered_);
  code_buffered_ += size;
}

void StreamWriter::flushCode() {
  writeHashed(code_buffer_.data(), code_buffered_);
  code_buffered_ = 0;
}

void StreamWriter::addLine(uint32_t file, uint32_t line, uint32_t column) {
  LineEntry entry{code_size_, file, line, column};
  if (last_line_ && last_line_->file == file && last_line_->line == line &&
      last_line_->column == column)
    return;
  spoolLine(entry, last_line_ && last_line_->offset == entry.offset);
  last_line_ = entry;
}

void StreamWriter::spoolLine(const LineEntry& entry, bool replace_last) {
  std::array<uint8_t, kLineEntrySize> record;
  uint8_t* p = record.data();
  bytes::putU32(p, entry.offset);
  bytes::putU32(p, entry.file);
  bytes::putU32(p, entry.line);
  bytes::putU32(p, entry.column);
  if (spool_ == nullptr) {
    if (replace_last) memory_spool_.resize(memory_spool_.size() - kLineEntrySize);
    memory_spool_.append(reinterpret_cast<const char*>(record.data()), record.size());
  } else {
    if (replace_last) std::fseek(spool_, -long{kLineEntrySize}, SEEK_END);
    if (std::fwrite(record.data(), 1, record.size(), spool_) != record.size())
      fail("NCC7012", "cannot write the line table to a temporary file");
  }
  if (!replace_last) ++line_count_;
}

std::optional<Error> StreamWriter::finish(const std::vector<std::string>& strings,
                                          const std::vector<Unit>& units,
                                          std::span<const uint8_t> blocks,
                                          const std::vector<VariableName>& names) {
  if (finished_) return error_;
  finished_ = true;
  for (const VariableName& n : names)
    header_.variable_count = std::max(header_.variable_count, n.number + 1);
  flushCode();
  SectionTable sections;
  uint64_t at = uint64_t{header_size_};
  sections[0] = {static_cast<uint32_t>(at), code_size_};
  at += code_size_;

  // Line table: copied back from the spool in fixed-size chunks.
  const uint64_t line_bytes = line_count_ * kLineEntrySize;
  sections[1] = {static_cast<uint32_t>(at), static_cast<uint32_t>(line_bytes)};
  if (spool_ == nullptr) {
    writeHashed(reinterpret_cast<const uint8_t*>(memory_spool_.data()), memory_spool_.size());
  } else {
    std::fflush(spool_);
    std::rewind(spool_);
    std::array<uint8_t, 64 * kLineEntrySize> chunk;
    uint64_t left = line_bytes;
    while (left > 0 && !error_) {
      size_t want = static_cast<size_t>(std::min<uint64_t>(left, chunk.size()));
      if (std::fread(chunk.data(), 1, want, spool_) != want) {
        fail("NCC7012", "cannot read the line table back from its temporary file");
        break;
      }
      writeHashed(chunk.data(), want);
      left -= want;
    }
  }
  at += line_bytes;

  std::vector<uint8_t> tail;
  auto put32 = [&tail](uint32_t v) {
    for (int i = 0; i < 4; ++i) tail.push_back(static_cast<uint8_t>(v >> (8 * i)));
  };
  put32(static_cast<uint32_t>(strings.size()));
  for (const std::string& s : strings) {
    put32(static_cast<uint32_t>(s.size()));
    tail.insert(tail.end(), s.begin(), s.end());
  }
  sections[2] = {static_cast<uint32_t>(at), static_cast<uint32_t>(tail.size())};
  at += tail.size();
  const size_t strings_end = tail.size();
  put32(static_cast<uint32_t>(units.size()));
  for (const Unit& unit : units) {
    put32(unit.entry);
    put32(unit.name);
  }
  put32(static_cast<uint32_t>(names.size()));
  for (const VariableName& n : names) {
    put32(n.number);
    put32(n.name);
  }
  sections[3] = {static_cast<uint32_t>(at), static_cast<uint32_t>(tail.size() - strings_end)};
  at += tail.size() - strings_end;
  tail.insert(tail.end(), blocks.begin(), blocks.end());
  at += blocks.size();
  if (at > std::numeric_limits<uint32_t>::max()) {
    fail("NCC7010", "program too large for the bytecode format (file over 4 GiB)");
    return error_;
  }
  writeHashed(tail.data(), tail.size());

  // Patch the section table and the checksum now that every byte after the header is known.
  if (!error_) {
    const std::vector<uint8_t> unsealed = encodeHeader(header_, sections);
    hash_.update(std::span<const uint8_t>(unsealed).first(kFixedHeaderSize));
    std::vector<uint8_t> header = encodeHeader(header_, sections, hash_.value());
    std::ostream::pos_type end = out_.tellp();
    out_.seekp(start_);
    writeBytes(header.data(), header.size());
    out_.seekp(end);
    if (!out_) fail("NCC7011", "seek error on the output stream");
  }
  return error_;
}

std::optional<Error> write(const Program& program, std::ostream& out) {
  StreamWriter writer(out, program.header);
  size_t next_line = 0;
  // Interleave line entries with the code in offset order, as a compiler would.
  uint32_t offset = 0;
  const uint32_t size = static_cast<uint32_t>(program.code.size());
  while (offset < size || next_line < program.lines.size()) {
    while (next_line < program.lines.size() && program.lines[next_line].offset <= offset) {
      const LineEntry& e = program.lines[next_line++];
      if (e.offset != offset) {
        return Error{"NCC7013", absl::StrCat("line table entry at code offset ", e.offset,
                                             " is not in order")};
      }
      writer.addLine(e.file, e.line, e.column);
    }
    uint32_t next = next_line < program.lines.size() ? program.lines[next_line].offset : size;
    if (next > size) {
      return Error{"NCC7013",
                   absl::StrCat("line table entry at code offset ", next, " beyond the code")};
    }
    if (next > offset) writer.emitRaw(program.code.data() + offset, next - offset);
    offset = next;
    if (offset == size && next_line >= program.lines.size()) break;
  }
  return writer.finish(program.strings, program.units, program.blocks, program.variable_names);
}

}  // namespace ncc::bytecode
