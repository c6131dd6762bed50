// The example programs against their hand-computed move lists (tests/golden/*.moves.jsonl)
// and expected diagnostics (tests/golden/bad-*.diag), at the IR level: lowering plus the
// work-to-machine pass. (The golden harness runs the same files through the VM.)
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "lowering_harness.h"
#include "gtest/gtest.h"

namespace ncc::passes::test {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

double field(const std::string& json, const std::string& object, const std::string& key) {
  size_t at = object.empty() ? 0 : json.find("\"" + object + "\": {");
  if (at == std::string::npos) return std::nan("");
  std::smatch m;
  std::string rest = json.substr(at);
  if (!std::regex_search(rest, m, std::regex("\"" + key + "\": (-?[0-9.e+-]+)"))) return std::nan("");
  return std::stod(m[1]);
}

void checkGolden(const std::string& name) {
  std::string program = slurp(std::string(NCC_SOURCE_DIR) + "/examples/" + name + ".nc");
  ASSERT_FALSE(program.empty());
  Lowered r = lower(Dialect::FanucM, program);
  ASSERT_EQ(r.diagText(), "");
  std::istringstream golden(slurp(std::string(NCC_SOURCE_DIR) + "/tests/golden/" + name + ".moves.jsonl"));
  std::string line;
  size_t n = 0;
  for (; std::getline(golden, line); ++n) {
    ASSERT_LT(n, r.moves.size()) << line;
    const Move& m = r.moves[n];
    SCOPED_TRACE(line);
    EXPECT_EQ(m.line, static_cast<int>(field(line, "", "line")));
    std::smatch kind;
    ASSERT_TRUE(std::regex_search(line, kind, std::regex("\"kind\": \"([a-z]+)\"")));
    EXPECT_EQ(m.kind, kind[1]);
    if (m.kind == "dwell") {
      EXPECT_NEAR(m.seconds, field(line, "", "seconds"), 1e-9);
      continue;
    }
    const char* axes[] = {"X", "Y", "Z"};
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(m.to[i], field(line, "to", axes[i]), 1e-9) << axes[i];
    if (m.kind == "arc") {
      for (int i = 0; i < 3; ++i) {
        double c = field(line, "center", axes[i]);
        if (!std::isnan(c) && line.find("\"" + std::string(axes[i]) + "\"", line.find("center")) != std::string::npos) {
          EXPECT_NEAR(m.center[i], c, 1e-9) << "center " << axes[i];
        }
      }
      EXPECT_EQ(m.cw, line.find("\"cw\": true") != std::string::npos);
    }
    if (m.kind != "rapid") {
      EXPECT_NEAR(m.feed, field(line, "", "feed"), 1e-9);
    }
  }
  EXPECT_EQ(n, r.moves.size());
}

TEST(Examples, MotionBasics) { checkGolden("motion-basics"); }
TEST(Examples, Coordinates) { checkGolden("coordinates"); }

TEST(Examples, BadUnsupported) {
  std::string program = slurp(std::string(NCC_SOURCE_DIR) + "/examples/bad-unsupported.nc");
  Lowered r = lower(Dialect::FanucM, program);
  std::string got;
  for (const Diagnostic& d : r.diags)
    got += "bad-unsupported.nc:" + std::to_string(d.location.line) + ":" +
           std::to_string(d.location.column) + ": error[" + d.code + "]\n";
  EXPECT_EQ(got, slurp(std::string(NCC_SOURCE_DIR) + "/tests/golden/bad-unsupported.diag"));
}

}  // namespace
}  // namespace ncc::passes::test
