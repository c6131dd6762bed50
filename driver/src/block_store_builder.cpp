#include "block_store_builder.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <deque>
#include <set>
#include <vector>

#include "absl/strings/str_cat.h"

namespace ncc::driver {

namespace {

// A block too deeply nested for the block store's decoder (kMaxStoredNesting).
constexpr const char* kNestedTooDeep = "NCC0060";

std::optional<double> literal(const ast::Expr& e) {
  if (!e.isLiteral()) return std::nullopt;
  return e.number;
}

// The program numbers a block calls with literal words: M98 P, G65 P, G66 P, G66.1 P.
std::vector<int64_t> callTargets(const ast::Block& block, int program_number_digits) {
  bool m98 = false, macro = false;
  std::optional<double> p;
  for (const ast::Word& w : block.words) {
    const std::optional<double> v = literal(w.value);
    if (!v) continue;
    if (w.address == "M" && *v == 98) m98 = true;
    if (w.address == "G" && (*v == 65 || *v == 66 || std::abs(*v - 66.1) < 1e-9)) macro = true;
    if (w.address == "P") p = *v;
  }
  std::vector<int64_t> out;
  if ((!m98 && !macro) || !p || *p < 0 || *p > 1e15 || *p != std::floor(*p)) return out;
  const int64_t number = static_cast<int64_t>(*p);
  out.push_back(number);
  if (m98 && program_number_digits > 0) {
    int64_t scale = 1;
    for (int i = 0; i < std::min(program_number_digits, 18); ++i) scale *= 10;
    if (number >= scale) out.push_back(number % scale);  // P30021: O21, three times
  }
  return out;
}

std::string fileName(const SourceManager& sources, uint32_t file) {
  const std::filesystem::path& path = sources.path(file);
  return path.empty() ? sources.displayName(file) : path.filename().string();
}

// Stores `block`, read at `at`, unless it is too deeply nested to store (reported).
void keep(ast::Block block, frontend::BlockPosition at, DiagnosticEngine& diags,
           eval::StoredFile& out) {
  if (eval::blockNesting(block) > eval::kMaxStoredNesting) {
    diags.error(kNestedTooDeep, block.loc,
                absl::StrCat("expressions nested deeper than ", eval::kMaxStoredNesting,
                             " levels cannot be kept for preparation at run time"));
    return;
  }
  out.blocks.push_back(eval::StoredBlock{at, eval::StoredBlock::Start::Other, std::move(block)});
}

// Reads blocks from where `reader` stands up to `end` (exclusive) into `out`.
void readBlocks(frontend::BlockReader& reader, frontend::BlockPosition end, DiagnosticEngine& diags,
                eval::StoredFile& out) {
  while (std::optional<ast::Block> block = reader.next()) {
    const frontend::BlockPosition at = reader.lastPosition();
    if (!(at < end)) break;
    keep(std::move(*block), at, diags, out);
  }
}

// The one block starting at `at` (the end block, the closing '%'), if it parses; the reader
// then stands just after it.
void readOneBlock(frontend::BlockReader& reader, frontend::BlockPosition at, DiagnosticEngine& diags,
                  eval::StoredFile& out) {
  reader.seek(at);
  std::optional<ast::Block> block = reader.next();
  if (block && reader.lastPosition() == at) keep(std::move(*block), at, diags, out);
}

// Where the main program ends when the compile stopped before it did (the rest is prepared at
// run time): its first block, before the next program, that programs M02 or M30 as a literal.
// A program that jumps over that block and runs on into the text after it is not expected;
// that text is kept where it parses (see readFile).
}  // namespace

std::optional<eval::ProgramPoint> writtenMainEnd(SourceProgramStore& store, uint32_t file) {
  DiagnosticEngine scratch;
  frontend::BlockReader reader(store.sources(), file, scratch, store.readerOptions());
  bool in_program = false;  // past the leading '%' and O blocks
  while (std::optional<ast::Block> block = reader.next()) {
    if (block->program_number && in_program) break;  // a subprogram stored after it
    in_program |= !block->program_number && !block->percent && !block->empty();
    for (const ast::Word& w : block->words)
      if (w.address == "M" && w.value.isLiteral() && (w.value.number == 2 || w.value.number == 30))
        return eval::ProgramPoint{file, reader.lastPosition()};
  }
  return std::nullopt;
}

namespace {

// The blocks of `file` up to the end of its record, each marked as the text scan of the
// file's ProgramIndex sees its start. `quiet_after`: the block where the main program ended
// (M02/M30); the text after it, up to the next program, is never executed and the compile
// does not parse it (docs/cli.md, The end of a program): what parses there is kept, what does
// not is left out without a diagnostic.
eval::StoredFile readFile(SourceProgramStore& store, uint32_t file,
                          std::optional<frontend::BlockPosition> quiet_after,
                          DiagnosticEngine& diags) {
  frontend::ProgramIndex& index = store.index(file);
  eval::StoredFile out;
  out.id = file;
  out.name = fileName(store.sources(), file);
  out.record_end = index.recordEnd();
  const frontend::ReaderOptions& options = store.readerOptions();
  frontend::BlockReader reader(store.sources(), file, diags, options);
  DiagnosticEngine scratch;
  frontend::BlockReader quiet(store.sources(), file, scratch, options);
  bool quiet_to_record_end = false;
  if (quiet_after && *quiet_after < out.record_end) {
    readBlocks(reader, *quiet_after, diags, out);
    readOneBlock(reader, *quiet_after, diags, out);  // M02/M30
    const frontend::BlockPosition next_program = index.programEnd(*quiet_after);
    quiet.seek(reader.position());
    readBlocks(quiet, next_program, scratch, out);
    quiet_to_record_end = next_program == out.record_end;
    reader.seek(next_program);
  }
  readBlocks(reader, out.record_end, diags, out);
  // The closing '%' (when the record has one: else record_end is the end of the file).
  if (quiet_to_record_end)
    readOneBlock(quiet, out.record_end, scratch, out);
  else
    readOneBlock(reader, out.record_end, diags, out);
  for (const frontend::ProgramIndex::Label& label : index.labels()) {
    auto it = std::lower_bound(out.blocks.begin(), out.blocks.end(), label.at,
                               [](const eval::StoredBlock& b, const frontend::BlockPosition& p) {
                                 return b.position < p;
                               });
    if (it == out.blocks.end() || !(it->position == label.at)) continue;  // rejected: reported
    if (label.program && it->block.program_number == label.number)
      it->start = eval::StoredBlock::Start::Program;
    else if (!label.program && it->block.sequence == label.number)
      it->start = eval::StoredBlock::Start::Sequence;
  }
  return out;
}

// The programs a file holds (its O blocks): calls to them stay in the file.
std::set<int64_t> programsOf(const eval::StoredFile& file) {
  std::set<int64_t> out;
  for (const eval::StoredBlock& b : file.blocks)
    if (b.start == eval::StoredBlock::Start::Program) out.insert(*b.block.program_number);
  return out;
}

}  // namespace

eval::BlockStore buildBlockStore(SourceProgramStore& store, uint32_t main_file,
                                 const BlockStoreTargets& targets, DiagnosticEngine& diags) {
  eval::BlockStore out;
  out.main_file = main_file;

  std::set<uint32_t> queued;
  std::deque<uint32_t> work;
  const auto want = [&](uint32_t file) {
    if (file != 0 && queued.insert(file).second) work.push_back(file);
  };
  std::set<int64_t> looked_up;
  const auto inFolder = [&](int64_t number) {
    if (!looked_up.insert(number).second) return;
    if (std::optional<eval::ProgramPoint> found = store.findInFolder(number)) {
      out.folder_programs[number] = *found;
      want(found->file);
    }
  };

  want(main_file);
  for (uint32_t file : store.openedFiles()) want(file);
  for (int64_t number : store.folderNumbers()) inFolder(number);
  for (const auto& [code, program] : targets.code_macros) {
    int64_t number = 0;
    auto [end, ec] = std::from_chars(program.data(), program.data() + program.size(), number);
    if (ec == std::errc() && end == program.data() + program.size()) {
      inFolder(number);
    } else if (std::optional<eval::ProgramPoint> found = store.findProgramNamed(program)) {
      want(found->file);
    }
  }
  // After the lookups above: findProgramNamed records what it finds.
  for (const auto& [name, point] : store.namedPrograms()) {
    out.named_programs[name] = point;
    want(point.file);
  }

  while (!work.empty()) {
    const uint32_t file = work.front();
    work.pop_front();
    std::optional<frontend::BlockPosition> quiet_after;
    std::optional<eval::ProgramPoint> main_end = targets.main_end;
    if (!main_end && file == main_file) main_end = writtenMainEnd(store, file);
    if (main_end && main_end->file == file) quiet_after = main_end->position;
    eval::StoredFile stored = readFile(store, file, quiet_after, diags);
    const std::set<int64_t> local = programsOf(stored);
    for (const eval::StoredBlock& b : stored.blocks)
      for (int64_t number : callTargets(b.block, targets.program_number_digits))
        if (!local.count(number)) inFolder(number);
    out.files.push_back(std::move(stored));
  }
  return out;
}

}  // namespace ncc::driver
