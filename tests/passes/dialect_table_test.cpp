#include "ncc/passes/dialect_table.h"

#include <set>

#include "gtest/gtest.h"

namespace ncc::passes {
namespace {

class DialectTableTest : public testing::TestWithParam<Dialect> {};

TEST_P(DialectTableTest, CodesAreUniqueAndEachGroupHasAtMostOneDefault) {
  const DialectTable* t = dialectTable(GetParam());
  ASSERT_NE(t, nullptr);
  std::set<int> codes;
  std::set<GGroup> defaults;
  for (const GCodeEntry& e : t->gcodes) {
    EXPECT_TRUE(codes.insert(e.code10).second) << gCodeName(e.code10);
    if (e.power_on_default) {
      EXPECT_TRUE(defaults.insert(e.group).second) << gCodeName(e.code10);
    }
    EXPECT_FALSE(e.description.empty());
    if (e.group == GGroup::OneShot) {
      EXPECT_FALSE(e.power_on_default);
    }
  }
  EXPECT_EQ(t->alarm_codes.size(), static_cast<size_t>(Alarm::kCount));
  EXPECT_EQ(t->powerOnDefault(GGroup::Motion)->code10, 0);
  EXPECT_EQ(t->powerOnDefault(GGroup::WorkOffset)->code10, 540);
  EXPECT_EQ(t->findG(810)->action, GAction::HoleCycle);
  EXPECT_EQ(t->findG(870)->action, GAction::HoleCycle);  // G87 back boring
  // Every hole-cycle code has its entry in the dialect's cycle table, and only those.
  ASSERT_NE(t->cycles, nullptr);
  for (const GCodeEntry& e : t->gcodes)
    EXPECT_EQ(e.action == GAction::HoleCycle, t->cycles->find(e.code10) != nullptr)
        << gCodeName(e.code10);
}

INSTANTIATE_TEST_SUITE_P(Iso, DialectTableTest,
                         testing::Values(Dialect::FanucM, Dialect::MazakM, Dialect::SiemensIsoM));

TEST(DialectTable, AlarmNumbersFromTheManuals) {
  EXPECT_EQ(dialectTable(Dialect::MazakM)->alarm(Alarm::FeedMissing), "816");
  EXPECT_EQ(dialectTable(Dialect::MazakM)->alarm(Alarm::ArcRadiusMismatch), "817");
  EXPECT_EQ(dialectTable(Dialect::MazakM)->alarm(Alarm::ArcRadiusTooSmall), "818");
  EXPECT_EQ(dialectTable(Dialect::MazakM)->alarm(Alarm::OffsetNumberOutOfRange), "839");
  EXPECT_EQ(dialectTable(Dialect::FanucM)->alarm(Alarm::FeedMissing), "PS0011");
  EXPECT_EQ(dialectTable(Dialect::FanucM)->alarm(Alarm::ArcRadiusMismatch), "PS0020");
  EXPECT_EQ(dialectTable(Dialect::SiemensIsoM)->alarm(Alarm::FeedMissing), "10860");
  EXPECT_EQ(dialectTable(Dialect::SiemensIsoM)->alarm(Alarm::ArcRadiusMismatch), "14040");
}

TEST(DialectTable, DialectsWithoutIsoMillingLoweringHaveNoTable) {
  EXPECT_EQ(dialectTable(Dialect::FanucT), nullptr);
}

TEST(DialectTable, SiemensDinStartsInDinAndSwitchesToIsoMode) {
  const LanguageTables t = languageTables(Dialect::SiemensDin);
  EXPECT_EQ(t.initial, frontend::Language::Din);
  ASSERT_NE(t.din, nullptr);
  EXPECT_EQ(t.din, dialectTable(Dialect::SiemensDin));
  EXPECT_EQ(t.iso, dialectTable(Dialect::SiemensIsoM));  // after G291
  EXPECT_EQ(languageTables(Dialect::SiemensIsoM).initial, frontend::Language::Iso);
  EXPECT_EQ(languageTables(Dialect::SiemensIsoM).din, t.din);
  EXPECT_EQ(languageTables(Dialect::FanucM).din, nullptr);
}

TEST(DialectTable, GCodeNames) {
  EXPECT_EQ(gCodeName(0), "G00");
  EXPECT_EQ(gCodeName(541), "G54.1");
  EXPECT_EQ(gCodeName(921), "G92.1");
  EXPECT_EQ(gCodeName(2910), "G291");
}

TEST(DialectTable, SiemensHasG54PButNoG541) {
  const DialectTable* s = dialectTable(Dialect::SiemensIsoM);
  EXPECT_EQ(s->findG(541), nullptr);
  EXPECT_TRUE(s->behaviour.extended_offset_is_g54_p);
  EXPECT_EQ(s->behaviour.extended_offset_count, 93);
  EXPECT_EQ(dialectTable(Dialect::MazakM)->findG(921), nullptr);  // no G92.1 on Mazak
}

}  // namespace
}  // namespace ncc::passes
