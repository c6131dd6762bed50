// The per-dialect macro rules hold the values the manuals state.
#include "ncc/eval/macro_rules.h"

#include <gtest/gtest.h>

#include <set>

namespace ncc::eval {
namespace {

constexpr Dialect kAll[] = {Dialect::FanucM, Dialect::FanucT, Dialect::MazakM,
                            Dialect::SiemensIsoM, Dialect::SiemensDin};

TEST(MacroRules, EveryDialectHasACompleteTable) {
  for (Dialect d : kAll) {
    const MacroRules& r = macroRules(d);
    EXPECT_EQ(r.dialect, d);
    ASSERT_EQ(r.alarm_codes.size(), static_cast<size_t>(EvalError::kCount));
    for (size_t i = 0; i < r.alarm_codes.size(); ++i)
      EXPECT_FALSE(r.alarm_codes[i].empty()) << dialectName(d) << " " << i;
    EXPECT_EQ(r.local_count, 33);
    EXPECT_FALSE(r.commons.empty());
    EXPECT_FALSE(r.program_file_names.empty());
    EXPECT_GE(r.max_call_nesting, r.max_macro_nesting);
  }
}

TEST(MacroRules, ArgumentSpecificationOne) {
  // A#1 B#2 C#3 I#4 J#5 K#6 D#7 E#8 F#9 H#11 M#13 Q#17 R#18 S#19 T#20 U#21 V#22 W#23 X#24
  // Y#25 Z#26; G L N O P are not arguments.
  const std::string letters = "ABCIJKDEFHMQRSTUVWXYZ";
  const int numbers[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 13, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26};
  for (Dialect d : kAll) {
    const auto& spec = macroRules(d).argument_spec1;
    for (size_t i = 0; i < letters.size(); ++i)
      EXPECT_EQ(spec[letters[i] - 'A'], numbers[i]) << letters[i];
    for (char c : std::string("GLNOP")) EXPECT_EQ(spec[c - 'A'], 0) << c;
  }
}

TEST(MacroRules, MazakValuesOfTheManual) {
  const MacroRules& r = macroRules(Dialect::MazakM);
  EXPECT_EQ(r.alarm(EvalError::Domain), "860");
  EXPECT_EQ(r.alarm(EvalError::GotoTarget), "843");
  EXPECT_EQ(r.alarm(EvalError::ProgramNotFound), "844");
  EXPECT_EQ(r.alarm(EvalError::CallNesting), "842");
  EXPECT_EQ(r.alarm(EvalError::ModalCallCancel), "857");
  EXPECT_EQ(r.alarm(EvalError::VariableNumber), "NCC2400");  // unnumbered in the manual
  EXPECT_EQ(r.max_bracket_depth, 5);
  EXPECT_EQ(r.max_do_id, 127);
  EXPECT_EQ(r.max_do_nesting, 27);
  EXPECT_EQ(r.max_call_nesting, 8);
  EXPECT_EQ(r.max_macro_nesting, 4);
  EXPECT_EQ(r.repeat, RepeatEncoding::LAddress);
  EXPECT_EQ(r.program_number_digits, 8);
  EXPECT_EQ(r.goto_search, SequenceSearch::ForwardThenFromStart);
  EXPECT_EQ(r.persistent_first, 100);
}

TEST(MacroRules, MazakUserAlarms) {
  // §13-9-4 7.: 1-20 -> n + 979; 21-6999 -> n + 3000.
  const MacroRules& r = macroRules(Dialect::MazakM);
  EXPECT_EQ(r.userAlarmNumber(1), 980);
  EXPECT_EQ(r.userAlarmNumber(20), 999);
  EXPECT_EQ(r.userAlarmNumber(21), 3021);
  EXPECT_EQ(r.userAlarmNumber(25), 3025);  // conformance alarm-3025-user-alarm-through-3000
  EXPECT_EQ(r.userAlarmNumber(6999), 9999);
  EXPECT_FALSE(r.userAlarmNumber(0));
  EXPECT_FALSE(r.userAlarmNumber(7000));
  EXPECT_EQ(macroRules(Dialect::FanucM).userAlarmNumber(5), 3005);
}

TEST(MacroRules, MazakCommonVariableSets) {
  const MacroRules& r = macroRules(Dialect::MazakM);
  auto contains = [](std::span<const VariableRange> ranges, int64_t n) {
    for (const VariableRange& v : ranges)
      if (v.contains(n)) return true;
    return false;
  };
  // Default A: #100-149 + #500-549.
  EXPECT_TRUE(contains(r.commons, 149));
  EXPECT_FALSE(contains(r.commons, 150));
  EXPECT_TRUE(contains(r.commons, 549));
  EXPECT_FALSE(contains(r.commons, 550));
  const auto* b = r.commonSet("B");
  ASSERT_NE(b, nullptr);
  EXPECT_TRUE(contains(b->ranges, 199));
  EXPECT_TRUE(contains(b->ranges, 580));  // conformance macro-trig-sqrt-abs-functions
  EXPECT_FALSE(contains(b->ranges, 600));
  const auto* d = r.commonSet("D");
  ASSERT_NE(d, nullptr);
  EXPECT_TRUE(contains(d->ranges, 999));
  EXPECT_EQ(r.commonSet("E"), nullptr);
  EXPECT_EQ(macroRules(Dialect::FanucM).commonSet("A"), nullptr);
}

TEST(MacroRules, FanucAndSiemensCalls) {
  const MacroRules& f = macroRules(Dialect::FanucM);
  EXPECT_EQ(f.repeat, RepeatEncoding::HighDigitsOfP);  // lathe §6.2: no L in the native format
  EXPECT_EQ(f.program_number_digits, 4);
  EXPECT_EQ(f.program_file_names[0], "O{:04}.nc");
  const MacroRules& s = macroRules(Dialect::SiemensIsoM);
  EXPECT_EQ(s.max_call_nesting, 4);  // §4.3
  EXPECT_EQ(s.repeat, RepeatEncoding::HighDigitsOfP);
  EXPECT_EQ(s.return_search, SequenceSearch::ForwardThenFromStart);
  std::set<std::string_view> files(s.program_file_names.begin(), s.program_file_names.end());
  EXPECT_TRUE(files.count("{:04}.spf"));
  EXPECT_TRUE(files.count("{}.mpf"));
  EXPECT_EQ(s.program_file_names[0], "{:04}.spf");
}

TEST(MacroRules, ProgramFileCandidates) {
  using V = std::vector<std::string>;
  EXPECT_EQ(macroRules(Dialect::MazakM).programFileCandidates(1234),
            (V{"O1234.nc", "1234.nc"}));
  EXPECT_EQ(macroRules(Dialect::FanucM).programFileCandidates(12),
            (V{"O0012.nc", "O12.nc", "0012.nc", "12.nc"}));
  EXPECT_EQ(macroRules(Dialect::MazakM).programFileCandidates(12345678),
            (V{"O12345678.nc", "12345678.nc"}));
  // siemens-iso-m/m98-repeat-count calls 1234.spf; g65-arguments-type1 calls 0010.spf.
  EXPECT_EQ(macroRules(Dialect::SiemensIsoM).programFileCandidates(10),
            (V{"0010.spf", "10.spf", "0010.mpf", "10.mpf"}));
  EXPECT_EQ(macroRules(Dialect::SiemensIsoM).programFileCandidates(1234)[0], "1234.spf");
  EXPECT_TRUE(macroRules(Dialect::MazakM).programFileCandidates(-1).empty());
}

}  // namespace
}  // namespace ncc::eval
