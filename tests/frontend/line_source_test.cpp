// A source whose read fails is not a short one: the reader throws SourceReadError (the CLI's
// NCC0001) instead of ending the file where the read failed.
#include <filesystem>

#include <gtest/gtest.h>

#include "ncc/frontend/block_reader.h"
#include "ncc/support/source_read_error.h"
#include "temp_dir.h"

namespace ncc::frontend {
namespace {

size_t countBlocks(const std::filesystem::path& path) {
  SourceManager sm;
  DiagnosticEngine diags(&sm);
  BlockReader reader(sm, sm.addFile(path), diags);
  size_t n = 0;
  while (reader.next()) ++n;
  return n;
}

TEST(LineSource, AFileIsReadToItsEnd) {
  testing::TempDir dir;
  EXPECT_EQ(countBlocks(dir.write("a.nc", "G00 X1.\nG01 X2. F100.\nM30")), 3u);
}

TEST(LineSource, AFolderIsAReadErrorNotAnEmptyFile) {
  testing::TempDir dir;
  EXPECT_THROW(countBlocks(dir.path()), SourceReadError);
}

TEST(LineSource, AFileThatOpensButCannotBeReadIsAReadError) {
  // /proc/self/mem opens, and its first read fails (nothing is mapped at address 0).
  if (!std::filesystem::exists("/proc/self/mem")) GTEST_SKIP() << "no /proc";
  try {
    countBlocks("/proc/self/mem");
    FAIL() << "no SourceReadError";
  } catch (const SourceReadError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot read '/proc/self/mem'"), std::string::npos);
  }
}

}  // namespace
}  // namespace ncc::frontend
