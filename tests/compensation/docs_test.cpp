// The drawings of docs/compensation.md are the golden cases (golden_cases.cpp) drawn by
// svg_drawing.cpp; this test fails when a committed drawing differs from what would be drawn.
// Regenerate them with
//   NCC_UPDATE_DOCS=1 ./compensation_tests --gtest_filter=CompensationDocs.*
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "golden_cases.h"
#include "gtest/gtest.h"
#include "svg_drawing.h"

namespace ncc::passes::testing {
namespace {

namespace fs = std::filesystem;

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(CompensationDocs, TheDrawingsAreTheGoldenCases) {
  const fs::path dir = fs::path(NCC_DOCS_DIR) / "compensation";
  const char* update = std::getenv("NCC_UPDATE_DOCS");
  const bool write = update && std::string(update) == "1";
  if (write) fs::create_directories(dir);
  std::set<std::string> names;
  for (const GoldenCase& g : goldenCases()) {
    CompProgram p = g.build();
    const std::string svg = drawSvg(g.title, p.input(), p.runBlocks());
    const fs::path path = dir / (g.name + ".svg");
    names.insert(path.filename().string());
    if (write) {
      std::ofstream(path, std::ios::binary) << svg;
      continue;
    }
    ASSERT_TRUE(fs::exists(path)) << path << " is missing; regenerate with NCC_UPDATE_DOCS=1";
    EXPECT_EQ(readFile(path), svg)
        << path << " is out of date; regenerate it with NCC_UPDATE_DOCS=1";
  }
  // No drawing is left of a case that is gone.
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".svg") {
      EXPECT_TRUE(names.count(entry.path().filename().string()))
          << entry.path() << " is no golden case's drawing";
    }
}

}  // namespace
}  // namespace ncc::passes::testing
