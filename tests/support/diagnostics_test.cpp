#include "ncc/support/diagnostics.h"

#include <sstream>

#include "gtest/gtest.h"
#include "ncc/support/source_manager.h"

namespace ncc {
namespace {

TEST(Diagnostics, FormatsFileLineColumnCodeAndCaret) {
  SourceManager sources;
  uint32_t file = sources.addBuffer("part.nc", "N10 G01 X10.\nN20 G02 X5. R1.\n");
  DiagnosticEngine diags(&sources);
  diags.error("818", SourceLocation{file, 2, 5}, "arc radius too small");
  ASSERT_TRUE(diags.hasErrors());
  std::ostringstream out;
  diags.print(out);
  EXPECT_EQ(out.str(),
            "part.nc:2:5: error[818]: arc radius too small\n"
            "  N20 G02 X5. R1.\n"
            "      ^\n");
}

TEST(Diagnostics, WarningsDoNotCountAsErrors) {
  DiagnosticEngine diags;
  diags.warning("NCC0001", SourceLocation{0, 3, 1}, "w");
  EXPECT_FALSE(diags.hasErrors());
  EXPECT_EQ(diags.diagnostics().size(), 1u);
}

TEST(Diagnostics, ErrorLimitStopsStoringButKeepsCounting) {
  DiagnosticEngine diags;
  diags.setErrorLimit(3);
  for (int i = 0; i < 10; ++i) diags.error("E", SourceLocation{0, uint32_t(i + 1), 1}, "x");
  EXPECT_EQ(diags.errorCount(), 10u);
  EXPECT_EQ(diags.diagnostics().size(), 3u);
}

TEST(SourceManager, SameFileRegisteredOnce) {
  SourceManager sources;
  EXPECT_EQ(sources.addFile("a.nc"), sources.addFile("a.nc"));
  EXPECT_NE(sources.addFile("a.nc"), sources.addFile("b.nc"));
}

TEST(SourceManager, LineTextStripsCarriageReturn) {
  SourceManager sources;
  uint32_t f = sources.addBuffer("x", "A\r\nB\r\n");
  EXPECT_EQ(sources.lineText(f, 2), "B");
  EXPECT_EQ(sources.lineText(f, 3), "");
}

}  // namespace
}  // namespace ncc
