// Values of address words given by expressions: dropped when vacant, whole numbers at the
// integer addresses (rounded per dialect), G to tenths, real values to the least increment.
#include "ncc/eval/address_value.h"

#include <gtest/gtest.h>

namespace ncc::eval {
namespace {

const MacroRules& mazak() { return macroRules(Dialect::MazakM); }
const MacroRules& fanuc() { return macroRules(Dialect::FanucM); }

std::optional<AddressValue> of(double v, AddressShape shape, const MacroRules& rules,
                               AddressLimits limits = {}) {
  Failure f;
  return addressValue(Value::of(v), shape, rules, limits, SourceLocation{1, 3, 5}, f);
}

double val(double v, AddressShape shape, const MacroRules& rules, AddressLimits limits = {}) {
  auto r = of(v, shape, rules, limits);
  if (!r) {
    ADD_FAILURE() << v << " refused";
    return -1e300;
  }
  EXPECT_FALSE(r->dropped);
  return r->value;
}

TEST(AddressValue, VacantDropsTheWord) {
  // Mazak §13-9-3 2. B: "G0 X#1 Y1000." with #1 vacant is "G0 Y1000.".
  for (AddressShape shape : {AddressShape::Real, AddressShape::Integer, AddressShape::GCode}) {
    Failure f;
    auto r = addressValue(Value::none(), shape, mazak(), {}, {}, f);
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->dropped);
  }
  auto zero = of(0.0, AddressShape::Real, mazak());
  ASSERT_TRUE(zero);
  EXPECT_FALSE(zero->dropped);  // 0 is a value: X0
}

TEST(AddressValue, IntegerAddressesPerDialect) {
  // FANUC lathe §4.2.8: #1=2500 then P#1 is P2500.
  EXPECT_EQ(val(2500.0, AddressShape::Integer, fanuc()), 2500.0);
  // FANUC rounds to the address's last digit: M[3.5] is M4; Mazak drops the fraction (§2-3
  // note 6): M3.
  EXPECT_EQ(val(3.5, AddressShape::Integer, fanuc()), 4.0);
  EXPECT_EQ(val(3.5, AddressShape::Integer, mazak()), 3.0);
  EXPECT_EQ(val(3.4, AddressShape::Integer, fanuc()), 3.0);
  EXPECT_EQ(val(12.345, AddressShape::Integer, mazak()), 12.0);  // G04 P12.345 -> 12
  // Binary noise is not a fraction: 0.57*100 is T57 on both.
  EXPECT_EQ(val(0.57 * 100, AddressShape::Integer, mazak()), 57.0);
}

TEST(AddressValue, GCodesHaveOneDecimal) {
  EXPECT_DOUBLE_EQ(val(54.1, AddressShape::GCode, fanuc()), 54.1);
  EXPECT_DOUBLE_EQ(val(1.0, AddressShape::GCode, mazak()), 1.0);
  EXPECT_DOUBLE_EQ(val(54.16, AddressShape::GCode, fanuc()), 54.2);
  EXPECT_DOUBLE_EQ(val(54.16, AddressShape::GCode, mazak()), 54.1);
  Failure f;
  EXPECT_FALSE(addressValue(Value::of(-1.0), AddressShape::GCode, fanuc(), {}, {1, 2, 3}, f));
  EXPECT_EQ(f.error, EvalError::AddressValue);
  EXPECT_EQ(f.loc.column, 3u);
  EXPECT_FALSE(addressValue(Value::of(1000.0), AddressShape::GCode, fanuc(), {}, {}, f));
}

TEST(AddressValue, RealValuesRoundToTheLeastIncrement) {
  const AddressLimits mm{.increment = 0.001, .digits = 8};
  EXPECT_NEAR(val(12.3456, AddressShape::Real, fanuc(), mm), 12.346, 1e-12);
  EXPECT_NEAR(val(-12.3454, AddressShape::Real, fanuc(), mm), -12.345, 1e-12);
  EXPECT_NEAR(val(-86.60254, AddressShape::Real, mazak(), mm), -86.603, 1e-12);
  // Without an increment the value is kept.
  EXPECT_EQ(val(12.3456, AddressShape::Real, fanuc()), 12.3456);
}

TEST(AddressValue, DigitLimits) {
  Failure f;
  // 8 digits: P99999999 fits, P123456789 does not (Mazak 809: "more than 8 digits").
  EXPECT_TRUE(addressValue(Value::of(99999999), AddressShape::Integer, mazak(), {}, {}, f));
  EXPECT_FALSE(addressValue(Value::of(123456789), AddressShape::Integer, mazak(), {}, {}, f));
  EXPECT_EQ(f.error, EvalError::AddressValue);
  EXPECT_EQ(mazak().alarm(f.error), "809");
  EXPECT_NE(f.message.find("8 digits"), std::string::npos) << f.message;
  // A coordinate of more than 8 digits of 0.001 (100000 mm).
  const AddressLimits mm{.increment = 0.001, .digits = 8};
  EXPECT_TRUE(addressValue(Value::of(99999.999), AddressShape::Real, mazak(), mm, {}, f));
  EXPECT_FALSE(addressValue(Value::of(100000.0), AddressShape::Real, mazak(), mm, {}, f));
}

TEST(AddressValue, ShapeOfEachLetter) {
  EXPECT_EQ(addressShape("G"), AddressShape::GCode);
  for (const char* a : {"D", "H", "L", "M", "N", "O", "P", "S", "T"})
    EXPECT_EQ(addressShape(a), AddressShape::Integer) << a;
  for (const char* a : {"X", "Y", "Z", "A", "I", "J", "K", "R", "F", "Q", "E", ",R", ",C"})
    EXPECT_EQ(addressShape(a), AddressShape::Real) << a;
}

}  // namespace
}  // namespace ncc::eval
