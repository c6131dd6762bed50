// docs/machine-file.md cannot drift from the registry: its parameter table is the registry
// rendered by renderParameterTable(). To regenerate it after changing params.cpp, run
//   NCC_UPDATE_DOCS=1 ./machine_tests --gtest_filter=MachineDocs.*
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "gtest/gtest.h"
#include "ncc/machine/params.h"

namespace ncc {
namespace {

constexpr const char* kBegin = "<!-- parameter table: generated from the registry -->\n";
constexpr const char* kEnd = "<!-- end of parameter table -->\n";

std::string cell(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '|')
      out += "\\|";
    else
      out += c;
  }
  return out;
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string renderParameterTable() {
  std::string out = "| key | type | default | dialects | meaning |\n|---|---|---|---|---|\n";
  for (const ParamSpec& s : parameterRegistry()) {
    std::string meaning(s.meaning);
    if (!s.choices.empty()) {
      meaning += ". Values: ";
      for (size_t i = 0; i < s.choices.size(); ++i)
        meaning += (i ? ", \"" : "\"") + std::string(s.choices[i]) + "\"";
    }
    const bool bounded_below = s.min_value > -1e300, bounded_above = s.max_value < 1e300;
    if (bounded_below && bounded_above)
      meaning += ". Range " + number(s.min_value) + " to " + number(s.max_value);
    else if (bounded_below)
      meaning += ". At least " + number(s.min_value);
    if (s.max_items) meaning += ". At most " + std::to_string(s.max_items) + " entries";
    if (s.applied_in.empty())
      meaning += ". Read and checked, not applied yet (warning NCC0307)";
    else if (s.applied_in != "all")
      meaning += ". Applied in " + std::string(s.applied_in) + " only (else warning NCC0307)";
    out += "| `" + std::string(s.key) + "` | " + cell(paramTypeDescription(s.type)) + " | " +
           cell(s.default_text) + " | " + cell(s.dialects) + " | " + cell(meaning) + " |\n";
  }
  return out;
}

TEST(MachineDocs, ParameterTableIsTheRegistry) {
  const std::string path = std::string(NCC_DOCS_DIR) + "/machine-file.md";
  std::string doc;
  {
    std::ifstream in(path);
    ASSERT_TRUE(in) << "cannot read " << path;
    std::ostringstream s;
    s << in.rdbuf();
    doc = s.str();
  }
  const size_t begin = doc.find(kBegin);
  const size_t end = doc.find(kEnd);
  ASSERT_NE(begin, std::string::npos) << "marker missing: " << kBegin;
  ASSERT_NE(end, std::string::npos) << "marker missing: " << kEnd;
  ASSERT_LT(begin, end);
  const size_t body = begin + std::string(kBegin).size();
  const std::string expected = renderParameterTable();
  const char* update = std::getenv("NCC_UPDATE_DOCS");
  if (update && std::string(update) == "1") {
    doc.replace(body, end - body, expected);
    std::ofstream(path) << doc;
    return;
  }
  EXPECT_EQ(doc.substr(body, end - body), expected)
      << "docs/machine-file.md is out of date; regenerate it with NCC_UPDATE_DOCS=1";
  // Every key appears in the table, whatever the rendering.
  for (const ParamSpec& s : parameterRegistry())
    EXPECT_NE(doc.find("| `" + std::string(s.key) + "` |"), std::string::npos) << s.key;
}

}  // namespace
}  // namespace ncc
