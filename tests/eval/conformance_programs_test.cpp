// The Mazak conformance cases made only of assignments (tests/conformance/mazak-m/macro-*),
// run through the evaluator alone: every expected variable of their case.toml must come out.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <toml++/toml.h>

#include "eval_harness.h"

namespace ncc::eval {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string caseDir(std::string_view name) {
  return std::string(NCC_SOURCE_DIR) + "/tests/conformance/mazak-m/" + std::string(name);
}

class AssignmentCase : public ::testing::TestWithParam<const char*> {};

TEST_P(AssignmentCase, ReproducesTheExpectedVariables) {
  const std::string dir = caseDir(GetParam());
  const std::string program = slurp(dir + "/program.nc");
  ASSERT_FALSE(program.empty()) << dir;
  toml::table table = toml::parse_file(dir + "/case.toml");
  const double tolerance = table["expect"]["tolerance"].value_or(0.001);
  const toml::table* vars = table["expect"]["vars"].as_table();
  ASSERT_NE(vars, nullptr);

  test::MapVariables values;
  auto failure = test::runAssignments(program, macroRules(Dialect::MazakM), values);
  ASSERT_FALSE(failure) << "line " << failure->loc.line << ": " << failure->message;
  int checked = 0;
  for (const auto& [key, node] : *vars) {
    const int64_t n = std::stoll(std::string(key.str().substr(1)));  // "#101"
    const Value v = values.get(n);
    ASSERT_FALSE(v.vacant) << key.str();
    EXPECT_NEAR(v.number, node.value_or(0.0), tolerance) << key.str();
    ++checked;
  }
  EXPECT_GE(checked, 3);
}

INSTANTIATE_TEST_SUITE_P(Mazak, AssignmentCase,
                         ::testing::Values("macro-arithmetic-and-logic-operators",
                                           "macro-assignments-take-effect-next-block",
                                           "macro-indirect-variable-numbers",
                                           "macro-round-fix-fup-ln-exp",
                                           "macro-trig-sqrt-abs-functions"));

TEST(AlarmCase, LnOfANegativeNumberIs860AtLine2) {
  // alarm-860-ln-of-negative-number: "#103 = LN[-5]" -> 860 at line 2.
  const std::string program = slurp(caseDir("alarm-860-ln-of-negative-number") + "/program.nc");
  test::MapVariables values;
  const MacroRules& rules = macroRules(Dialect::MazakM);
  auto failure = test::runAssignments(program, rules, values);
  ASSERT_TRUE(failure);
  EXPECT_EQ(rules.alarm(failure->error), "860");
  EXPECT_EQ(failure->loc.line, 2u);
  EXPECT_NEAR(values.get(101).number, 1.609, 0.001);  // line 1 ran
}

}  // namespace
}  // namespace ncc::eval
