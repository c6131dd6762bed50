// Every conformance case's [machine] and [start] tables load as a machine file
// (shared/conformance/FORMAT.md: "a conformance case's [machine] table is a valid machine file").
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "ncc/machine/machine_file.h"

namespace ncc {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> caseFiles() {
  std::vector<fs::path> out;
  const fs::path root = fs::path(NCC_SHARED_DIR) / "conformance";
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(root, ec); !ec && it != fs::end(it);
       it.increment(ec))
    if (it->path().filename() == "case.toml") out.push_back(it->path());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(ConformanceMachines, EveryCaseLoads) {
  const std::vector<fs::path> cases = caseFiles();
  ASSERT_GE(cases.size(), 100u) << "conformance cases not found under " << NCC_SHARED_DIR;
  for (const fs::path& path : cases) {
    SourceManager sources;
    DiagnosticEngine diags(&sources);
    auto m = loadMachineFile(path, sources, diags,
                             MachineFileOptions{.ignore_other_top_level_keys = true, .dialect = {}, .default_dialect = {}});
    std::string errors;
    for (const Diagnostic& d : diags.diagnostics()) errors += diags.format(d) + "\n";
    EXPECT_TRUE(m.has_value()) << errors;
    EXPECT_TRUE(errors.empty()) << errors;
  }
}

// Spot checks that values arrive where the cases put them.
TEST(ConformanceMachines, LatheWearAndGeometryCase) {
  for (const fs::path& path : caseFiles()) {
    SourceManager sources;
    DiagnosticEngine diags(&sources);
    auto m = loadMachineFile(path, sources, diags,
                             MachineFileOptions{.ignore_other_top_level_keys = true, .dialect = {}, .default_dialect = {}});
    ASSERT_TRUE(m) << path;
    if (m->lathe_offsets.wear.count(2)) {
      EXPECT_EQ(m->lathe_offsets.wear.at(2), (LatheOffset{0.4, -0.2, 0.0, 0})) << path;
      EXPECT_EQ(m->lathe_offsets.geometry.at(2), (LatheOffset{4.0, 2.0, 0.0, 0})) << path;
      return;
    }
  }
  ADD_FAILURE() << "no case with wear2 found";
}

}  // namespace
}  // namespace ncc
