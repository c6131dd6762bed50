#include "value_rules.h"

#include "gtest/gtest.h"

namespace ncc::passes {
namespace {

ValueRules rules(const std::string& decimal, const std::string& is = "IS-B", bool x10 = false) {
  ParameterSet p;
  p.set("decimal_point", decimal);
  p.set("increment_system", is);
  p.set("input_unit_x10", x10);
  return ValueRules::fromParams(p, "standard");
}

TEST(ValueRules, StandardNotationUsesLeastIncrements) {
  ValueRules r = rules("standard");
  EXPECT_DOUBLE_EQ(r.linear(12345, false, ir::Units::Millimetre), 12.345);
  EXPECT_DOUBLE_EQ(r.linear(123.45, true, ir::Units::Millimetre), 123.45);
  EXPECT_DOUBLE_EQ(r.linear(100, false, ir::Units::Inch), 0.254);
  EXPECT_DOUBLE_EQ(r.rotary(100, false), 0.1);
  EXPECT_DOUBLE_EQ(r.dwellX(5000, false), 5.0);
}

TEST(ValueRules, IncrementSystemC) {
  ValueRules r = rules("standard", "IS-C");
  EXPECT_DOUBLE_EQ(r.linear(12345, false, ir::Units::Millimetre), 1.2345);
  EXPECT_NEAR(r.linear(100000, false, ir::Units::Inch), 25.4, 1e-12);
}

TEST(ValueRules, MazakX10AppliesToCoordinatesNotOffsets) {
  ValueRules r = rules("standard", "IS-B", true);
  EXPECT_DOUBLE_EQ(r.linear(12345, false, ir::Units::Millimetre), 123.45);
  EXPECT_DOUBLE_EQ(r.offset(12345, false, ir::Units::Millimetre), 12.345);
}

TEST(ValueRules, CalculatorNotationTakesWholeUnits) {
  ValueRules r = rules("calculator");
  EXPECT_DOUBLE_EQ(r.linear(10, false, ir::Units::Millimetre), 10.0);
  EXPECT_DOUBLE_EQ(r.linear(1, false, ir::Units::Inch), 25.4);
  EXPECT_DOUBLE_EQ(r.feed(10, true, ir::Units::Inch, ir::FeedMode::PerMinute), 254.0);
}

TEST(ValueRules, FeedRules) {
  ValueRules r = rules("standard");
  EXPECT_DOUBLE_EQ(r.feed(300, false, ir::Units::Millimetre, ir::FeedMode::PerMinute), 300.0);
  EXPECT_DOUBLE_EQ(r.feed(25, false, ir::Units::Millimetre, ir::FeedMode::PerRevolution), 0.25);
  EXPECT_NEAR(r.feed(1000, false, ir::Units::Inch, ir::FeedMode::PerMinute), 254.0, 1e-9);
  EXPECT_DOUBLE_EQ(r.feed(2, false, ir::Units::Millimetre, ir::FeedMode::InverseTime), 2.0);
}

}  // namespace
}  // namespace ncc::passes
