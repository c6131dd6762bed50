// The parameter registry: complete against FORMAT.md, well-formed, typed defaults.
#include "ncc/machine/params.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>
#include <string>

#include "gtest/gtest.h"

namespace ncc {
namespace {

// The key column of FORMAT.md's "Parameter vocabulary" table.
std::set<std::string> formatVocabulary() {
  std::ifstream in(std::string(NCC_SHARED_DIR) + "/conformance/FORMAT.md");
  std::set<std::string> keys;
  std::string line;
  bool in_section = false;
  const std::regex row(R"(^\| `([a-zA-Z0-9_]+)` \|)");
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) in_section = line == "## Parameter vocabulary";
    std::smatch m;
    if (in_section && std::regex_search(line, m, row)) keys.insert(m[1]);
  }
  return keys;
}

TEST(ParameterRegistry, CoversEveryKeyOfTheConformanceVocabulary) {
  std::set<std::string> vocabulary = formatVocabulary();
  ASSERT_GE(vocabulary.size(), 60u) << "FORMAT.md not found or its table changed";
  for (const std::string& key : vocabulary)
    EXPECT_NE(findParameter(key), nullptr) << "FORMAT.md key missing from the registry: " << key;
}

TEST(ParameterRegistry, HasNccsOwnKeys) {
  struct Expected {
    const char* key;
    ParamType type;
  };
  for (const Expected& e : {Expected{"rapid_type", ParamType::String},
                            Expected{"same_group_in_block", ParamType::String},
                            Expected{"reference_point_4", ParamType::AxisTable},
                            Expected{"arc_radius_tolerance", ParamType::Number},
                            Expected{"block_skip_levels", ParamType::IntegerList}}) {
    const ParamSpec* spec = findParameter(e.key);
    ASSERT_NE(spec, nullptr) << e.key;
    EXPECT_EQ(spec->type, e.type) << e.key;
  }
  EXPECT_EQ(findParameter("rapid_type")->choices,
            (std::vector<std::string_view>{"linear", "per_axis"}));
  EXPECT_EQ(findParameter("same_group_in_block")->choices,
            (std::vector<std::string_view>{"error", "last_wins"}));
  for (const char* dialect : {"fanuc-m", "fanuc-t", "mazak-m", "siemens-iso-m"})
    EXPECT_NE(findParameter("arc_radius_tolerance")->dialects.find(dialect), std::string::npos);
}

TEST(ParameterRegistry, IsSortedUniqueAndDocumented) {
  const auto& reg = parameterRegistry();
  for (size_t i = 1; i < reg.size(); ++i) EXPECT_LT(reg[i - 1].key, reg[i].key);
  for (const ParamSpec& s : reg) {
    EXPECT_FALSE(s.meaning.empty()) << s.key;
    EXPECT_FALSE(s.default_text.empty()) << s.key;
    EXPECT_FALSE(s.dialects.empty()) << s.key;
    EXPECT_NE(s.type, ParamType::Any) << s.key;
    EXPECT_EQ(findParameter(s.key), &s);
  }
  EXPECT_EQ(findParameter("no_such_key"), nullptr);
  EXPECT_EQ(findParameter(""), nullptr);
}

// A typed default has the variant alternative its type stores, and a String default is one
// of the choices: consumers can rely on getString(key) etc.
TEST(ParameterRegistry, DefaultsMatchTheirTypes) {
  for (const ParamSpec& s : parameterRegistry()) {
    if (!s.default_value) {
      EXPECT_NE(s.default_text.find(' '), std::string::npos)
          << s.key << ": a key without a typed default explains its default in words";
      continue;
    }
    const ParamValue& v = *s.default_value;
    switch (s.type) {
      case ParamType::Bool:
        EXPECT_TRUE(std::holds_alternative<bool>(v)) << s.key;
        break;
      case ParamType::Number:
      case ParamType::Integer:
        ASSERT_TRUE(std::holds_alternative<double>(v)) << s.key;
        EXPECT_GE(std::get<double>(v), s.min_value) << s.key;
        EXPECT_LE(std::get<double>(v), s.max_value) << s.key;
        break;
      case ParamType::String:
        ASSERT_TRUE(std::holds_alternative<std::string>(v)) << s.key;
        if (!s.choices.empty()) {
          EXPECT_NE(std::find(s.choices.begin(), s.choices.end(), std::get<std::string>(v)),
                    s.choices.end())
              << s.key;
        }
        break;
      case ParamType::NumberList:
      case ParamType::IntegerList:
        EXPECT_TRUE(std::holds_alternative<std::vector<double>>(v)) << s.key;
        break;
      case ParamType::StringList:
      case ParamType::AxisList:
        EXPECT_TRUE(std::holds_alternative<std::vector<std::string>>(v)) << s.key;
        break;
      case ParamType::AxisTable:
        EXPECT_TRUE(std::holds_alternative<ParamAxisTable>(v)) << s.key;
        break;
      case ParamType::AxisNameTable:
      case ParamType::StringTable:
        EXPECT_TRUE(std::holds_alternative<ParamStringTable>(v)) << s.key;
        break;
      case ParamType::AxisRangeTable:
        EXPECT_TRUE(std::holds_alternative<ParamAxisRanges>(v)) << s.key;
        break;
      case ParamType::Any:
        ADD_FAILURE() << s.key;
        break;
    }
  }
}

TEST(ParameterSet, StoredValueThenFallbackOrRegistryDefault) {
  ParameterSet p;
  p.set("peck_return", 2.5);
  p.set("decimal_point", std::string("calculator"));
  p.set("block_skip", true);
  EXPECT_EQ(p.getNumber("peck_return", 9.0), 2.5);
  EXPECT_EQ(p.getNumber("peck_clearance", 9.0), 9.0);  // absent: the caller's fallback
  EXPECT_EQ(p.getNumber("peck_clearance"), 1.0);       // absent: the registry default
  EXPECT_EQ(p.getNumber("decimal_point", 7.0), 7.0);   // other type: fallback
  EXPECT_EQ(p.getString("decimal_point", ""), "calculator");
  EXPECT_EQ(p.getString("increment_system"), "IS-B");
  EXPECT_TRUE(p.getBool("block_skip", false));
  EXPECT_TRUE(p.getBool("interference_check"));  // default true
  EXPECT_EQ(p.getString("reset_plane"), "");     // dialect-dependent: no default
  EXPECT_EQ(p.getString("reset_plane", "G18"), "G18");
  EXPECT_EQ(p.getOrDefault("no_such_key"), nullptr);
  EXPECT_TRUE(p.has("peck_return"));
  EXPECT_FALSE(p.has("peck_clearance"));
  EXPECT_EQ(p.getAxisTable("peck_return"), nullptr);
  EXPECT_EQ(p.getNumberList("block_skip_levels"), nullptr);
}

}  // namespace
}  // namespace ncc
