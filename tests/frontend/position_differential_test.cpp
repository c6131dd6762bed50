// Positions on real programs: every program of tests/corpus and examples is read straight
// through, recording each block's position; then a sample of positions is sought back to and
// the block read there must be the same (printed text and locations). The program index must
// find the same labels the reader reads, in the control's search order.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "absl/strings/str_cat.h"
#include "ncc/frontend/program_index.h"

namespace ncc::frontend {
namespace {

struct ReadBlock {
  std::string text;  // printed, with locations
  BlockPosition at;
  std::optional<int64_t> sequence;
  bool closes_record = false;  // a '%' after the first block
};

std::string describe(const ast::Block& b) {
  std::string out = printBlock(b);
  absl::StrAppend(&out, " @", b.loc.line, ":", b.loc.column);
  for (const ast::Word& w : b.words) absl::StrAppend(&out, " ", w.loc.line, ":", w.loc.column);
  return out;
}

std::vector<std::filesystem::path> programFiles() {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path root = NCC_SOURCE_DIR;
  for (const char* dir : {"tests/corpus", "examples"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root / dir)) {
      if (!entry.is_regular_file()) continue;
      const std::string ext = entry.path().extension().string();
      if (ext == ".py" || ext == ".md" || ext == ".txt" || ext == ".toml" || ext == ".cpp")
        continue;
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Every k-th index of n, at most about `count` of them, and the last one.
std::vector<size_t> sample(size_t n, size_t count) {
  std::vector<size_t> out;
  if (n == 0) return out;
  const size_t step = std::max<size_t>(1, n / count);
  for (size_t i = 0; i < n; i += step) out.push_back(i);
  if (out.back() != n - 1) out.push_back(n - 1);
  return out;
}

TEST(PositionDifferential, SeekingBackReadsTheSameBlocksInEveryProgram) {
  const std::vector<std::filesystem::path> files = programFiles();
  ASSERT_GT(files.size(), 100u);
  SourceManager sm;
  uint64_t seeks = 0, lookups = 0;
  for (const std::filesystem::path& path : files) {
    const uint32_t file = sm.addFile(path);
    for (bool semicolon_ends_block : {true, false}) {
      ReaderOptions options;
      options.semicolon_ends_block = semicolon_ends_block;
      SCOPED_TRACE(absl::StrCat(path.string(), " semicolon_ends_block=", semicolon_ends_block));
      DiagnosticEngine diags(&sm);
      diags.setErrorLimit(1'000'000);
      BlockReader reader(sm, file, diags, options);
      std::vector<ReadBlock> blocks;
      bool seen = false;
      while (auto b = reader.next()) {
        blocks.push_back(ReadBlock{describe(*b), reader.lastPosition(), b->sequence,
                                   b->percent && seen});
        seen = seen || !b->empty();
      }
      const bool had_errors = reader.stats().rejected_blocks > 0;

      // Seek back (last to first, so each seek is a jump) and compare.
      std::vector<size_t> picks = sample(blocks.size(), 150);
      std::reverse(picks.begin(), picks.end());
      for (size_t i : picks) {
        reader.seek(blocks[i].at);
        auto b = reader.next();
        ASSERT_TRUE(b) << "block " << i;
        ASSERT_EQ(describe(*b), blocks[i].text) << "block " << i;
        ++seeks;
      }

      // Labels: where the index finds N n from a block, compared with the reader's blocks.
      // Files with rejected blocks are left out (the index does not parse, so it sees labels
      // of blocks the reader refused).
      if (had_errors) continue;
      size_t end = blocks.size();
      for (size_t i = 0; i < blocks.size(); ++i)
        if (blocks[i].closes_record) {
          end = i;
          break;
        }
      ProgramIndex index(sm, file, options);
      for (size_t label_at : sample(end, 12)) {
        if (!blocks[label_at].sequence) continue;
        const int64_t n = *blocks[label_at].sequence;
        for (size_t from : sample(end, 4)) {
          // Expected: the first block with N n after `from`, cyclically.
          std::optional<BlockPosition> expected;
          for (size_t k = 1; k <= end && !expected; ++k) {
            const size_t j = (from + k) % end;
            if (blocks[j].sequence == n) expected = blocks[j].at;
          }
          ASSERT_EQ(index.findSequence(n, blocks[from].at, SequenceSearch::ForwardThenFromStart),
                    expected)
              << "N" << n << " from block " << from;
          ++lookups;
        }
      }
    }
  }
  EXPECT_GT(seeks, 10'000u);
  EXPECT_GT(lookups, 500u);
}

}  // namespace
}  // namespace ncc::frontend
