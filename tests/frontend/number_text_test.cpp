// readNumber's short-number path (an integer over a power of ten) must give exactly the double
// that a correctly rounded conversion gives: checked against std::from_chars on every shape of
// number a program writes and on random ones up to the 15-digit limit and past it.
#include <charconv>
#include <cstdint>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "number_text.h"

namespace ncc::frontend {
namespace {

double reference(const std::string& text) {
  std::string body = text;
  if (body.back() == '.') body.pop_back();
  double v = 0.0;
  std::from_chars(body.data(), body.data() + body.size(), v, std::chars_format::fixed);
  return v;
}

void expectSameAsFromChars(const std::string& text) {
  std::optional<NumberText> n = readNumber(text);
  ASSERT_TRUE(n) << text;
  EXPECT_EQ(n->value, reference(text)) << text;  // bit-exact, not near
  EXPECT_EQ(n->has_point, text.find('.') != std::string::npos) << text;
}

TEST(NumberText, WrittenShapes) {
  for (const char* t : {"0", "0.", ".5", "10", "10.", "1.25", "0.1", "0.3", "1.036", "-0",
                        "123456.789", "999999999999999", "99999999.9999999", ".000000000000001",
                        "0.000", "00012.50", "4503599627370497", "1234567890123456789"}) {
    if (t[0] == '-') continue;
    expectSameAsFromChars(t);
  }
  EXPECT_EQ(readNumber("10.")->digits, 2);
  EXPECT_EQ(readNumber(".5")->digits, 1);
  EXPECT_EQ(readNumber("1.25")->value, 1.25);
}

TEST(NumberText, RandomNumbersMatchCorrectRounding) {
  std::mt19937_64 rng(12345);
  for (int i = 0; i < 200000; ++i) {
    const int digits = 1 + static_cast<int>(rng() % 19);  // past the 15-digit fast path too
    std::string t;
    for (int d = 0; d < digits; ++d) t += static_cast<char>('0' + rng() % 10);
    const int point = static_cast<int>(rng() % (digits + 2));
    if (point <= digits) t.insert(static_cast<size_t>(point), ".");
    expectSameAsFromChars(t);
  }
}

TEST(NumberText, RefusesWhatIsNotANumber) {
  EXPECT_FALSE(readNumber("."));
  EXPECT_FALSE(readNumber(""));
  EXPECT_FALSE(readNumber(std::string(400, '9')));  // does not fit a double
}

}  // namespace
}  // namespace ncc::frontend
