#pragma once
// Compares a run's moves with a conformance-style expectation: only the axes named in `to`
// and `center` are compared (named by axis letter in X Y Z order of the test machine).
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "lowering_harness.h"

namespace ncc::passes::test {

struct Expected {
  std::string kind;
  std::map<std::string, double> to;
  std::map<std::string, double> center = {};
  bool cw = false;
  double feed = -1.0;     // < 0: not compared
  double seconds = -1.0;  // dwell
};

// `diags`: the diagnostics the run must report (warnings, e.g. NCC2034), none by default.
inline void expectMoves(const Lowered& run, const std::vector<std::string>& axes,
                        const std::vector<Expected>& expected, double tol = 0.001,
                        const std::string& diags = "") {
  ASSERT_EQ(run.diagText(), diags);
  ASSERT_EQ(run.moves.size(), expected.size()) << "moves differ in number";
  auto index = [&](const std::string& name) {
    for (size_t i = 0; i < axes.size(); ++i)
      if (axes[i] == name) return static_cast<int>(i);
    ADD_FAILURE() << "no axis " << name;
    return 0;
  };
  for (size_t n = 0; n < expected.size(); ++n) {
    const Move& m = run.moves[n];
    const Expected& e = expected[n];
    SCOPED_TRACE(testing::Message() << "move " << n << " (line " << m.line << ")");
    EXPECT_EQ(m.kind, e.kind);
    for (const auto& [axis, v] : e.to) EXPECT_NEAR(m.to[index(axis)], v, tol) << axis;
    for (const auto& [axis, v] : e.center) EXPECT_NEAR(m.center[index(axis)], v, tol) << axis;
    if (e.kind == "arc") {
      EXPECT_EQ(m.cw, e.cw);
    }
    if (e.feed >= 0) {
      EXPECT_NEAR(m.feed, e.feed, tol);
    }
    if (e.seconds >= 0) {
      EXPECT_NEAR(m.seconds, e.seconds, tol);
    }
  }
}

}  // namespace ncc::passes::test
