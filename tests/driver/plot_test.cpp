// ncc plot with cutter compensation: what the compile reports (Session::compileFacts), the
// compile with compensation off (the programmed path), and the drawing of both paths and of a
// compile alarm's mark (writePlotSvg with PlotOptions::programmed and alarm_at).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "ncc/driver/compile.h"
#include "ncc/driver/plot.h"
#include "ncc/driver/session.h"

namespace ncc::driver {
namespace {

namespace fs = std::filesystem;

// The X Y end points of the feed moves a compile delivers.
struct FeedEnds : ir::BlockSink {
  void accept(ir::Block&& block) override {
    for (const ir::Operation& op : block.ops)
      if (const auto* line = std::get_if<ir::Linear>(&op)) ends.push_back({line->to[0], line->to[1]});
  }
  void finish() override {}
  std::vector<std::pair<double, double>> ends;
};

class CompileFactsTest : public ::testing::Test {
 protected:
  // Opens a session for `program` on a machine whose D1 is 5 mm.
  void open(const std::string& program) {
    // One folder per test: ctest runs the tests of this file side by side.
    dir_ = fs::path(::testing::TempDir()) /
           (std::string("ncc_plot_test_") +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    std::ofstream(dir_ / "part.nc") << program;
    std::ofstream(dir_ / "mill.toml") << "[machine.offsets]\nD1 = 5.0\n";
    SessionOptions options;
    options.machine_file = dir_ / "mill.toml";
    ASSERT_EQ(session_.open(dir_ / "part.nc", options), std::nullopt);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
  Session session_;
};

// A 40 x 30 rectangle, clockwise, G41: the tool centre 5 mm outside it.
constexpr const char* kSquare =
    "G90 G17 G21\nG00 X-20. Y-20.\nG41 G01 X0 Y0 D1 F500.\nY30.\nX40.\nY0\nX0\n"
    "G40 X-20. Y-20.\nM30\n";

TEST_F(CompileFactsTest, ACompensatedProgramIsReportedAndCompilesToBothPaths) {
  open(kSquare);
  FeedEnds centre;
  ASSERT_TRUE(compileToSink(session_, centre));
  EXPECT_TRUE(session_.compileFacts().cutter_comp);
  EXPECT_FALSE(session_.compileFacts().prepared_at_run_time);
  // The rectangle's corners, 5 mm out.
  for (const auto& corner : {std::pair{-5.0, 35.0}, std::pair{45.0, 35.0}, std::pair{45.0, -5.0}})
    EXPECT_NE(std::find(centre.ends.begin(), centre.ends.end(), corner), centre.ends.end())
        << corner.first << " " << corner.second;
  EXPECT_EQ(std::find(centre.ends.begin(), centre.ends.end(), std::pair{40.0, 30.0}),
            centre.ends.end());

  session_.setCompensate(false);
  FeedEnds programmed;
  ASSERT_TRUE(compileToSink(session_, programmed));
  EXPECT_TRUE(session_.compileFacts().cutter_comp);  // still asked for, not applied
  const std::vector<std::pair<double, double>> written = {
      {0, 0}, {0, 30}, {40, 30}, {40, 0}, {0, 0}, {-20, -20}};
  EXPECT_EQ(programmed.ends, written);
}

TEST_F(CompileFactsTest, AProgramWithoutCompensationIsNot) {
  open("G40 G90 G17\nG01 X10. F100.\nM30\n");  // a G40 alone asks for nothing
  FeedEnds ends;
  ASSERT_TRUE(compileToSink(session_, ends));
  EXPECT_FALSE(session_.compileFacts().cutter_comp);
}

TEST_F(CompileFactsTest, BlocksLeftToTheVmAreReported) {
  // Where G31 stopped is known only while the program runs.
  open("G31 X10. F100.\n#1 = #5061\nG01 X#1\nM30\n");
  FeedEnds ends;
  ASSERT_TRUE(compileToSink(session_, ends));
  EXPECT_TRUE(session_.compileFacts().prepared_at_run_time);
}

PlotMove line(double x0, double y0, double x1, double y1, uint32_t source_line) {
  PlotMove m;
  m.motion.kind = vm::MotionPrimitive::Kind::Line;
  m.motion.from = AxisValues{x0, y0, 0.0};
  m.motion.to = AxisValues{x1, y1, 0.0};
  m.motion.where = SourceLocation{1, source_line, 1};
  m.tool = 1;
  return m;
}

std::string draw(const std::vector<PlotMove>& moves, const PlotOptions& options) {
  std::ostringstream out;
  writePlotSvg(out, moves, options);
  return out.str();
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(PlotSvg, TheProgrammedPathIsDrawnUnderTheToolCentresWithBothInTheLegend) {
  PlotOptions options;
  options.views = {PlotView::Top};
  options.file_name = [](uint32_t) { return std::string("part.nc"); };
  options.programmed = std::vector<PlotMove>{line(0, 0, 0, 30, 2), line(0, 30, 40, 30, 3)};
  const std::string svg = draw({line(-5, 0, -5, 35, 2), line(-5, 35, 45, 35, 3)}, options);
  EXPECT_EQ(count(svg, "<path class=\"programmed\""), 2u);
  EXPECT_EQ(count(svg, "<path class=\"feed\""), 2u);
  EXPECT_LT(svg.find("class=\"programmed-path\""), svg.find("class=\"moves\""));
  EXPECT_NE(svg.find("<title>programmed: part.nc:3: G01 X40.000 Y30.000 Z0.000 (T1)</title>"),
            std::string::npos);
  EXPECT_NE(svg.find(">tool centre (G41/G42)</text>"), std::string::npos);
  EXPECT_NE(svg.find(">programmed path</text>"), std::string::npos);
  EXPECT_NE(svg.find("(2 moves; programmed path: 2 moves)"), std::string::npos);
  EXPECT_EQ(svg.find("class=\"alarm\""), std::string::npos);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
}

TEST(PlotSvg, WithoutCompensationNothingOfIt) {
  PlotOptions options;
  const std::string svg = draw({line(0, 0, 10, 0, 1)}, options);
  EXPECT_EQ(svg.find("programmed"), std::string::npos);
  EXPECT_EQ(svg.find("tool centre"), std::string::npos);
  EXPECT_NE(svg.find("(1 moves)"), std::string::npos);
}

TEST(PlotSvg, ACompileAlarmIsMarkedWhereItsBlockEndsOnTheProgrammedPath) {
  PlotOptions options;
  options.views = {PlotView::Top};
  options.file_name = [](uint32_t) { return std::string("part.nc"); };
  const PlotMove into = line(0, 0, 30, 0, 2), down = line(30, 0, 30, -20, 3);
  options.programmed = std::vector<PlotMove>{into, down, line(30, -20, 36, -20, 4)};
  options.alarm = vm::Alarm{"PS0041", "interference", SourceLocation{1, 3, 1}};
  options.alarm_at = down.motion.to;
  const std::string svg = draw({}, options);
  EXPECT_NE(svg.find("<title>alarm PS0041 at part.nc:3: interference</title>"), std::string::npos);
  EXPECT_EQ(svg.find("tool centre"), std::string::npos);  // no tool centre's path
  EXPECT_NE(svg.find(">programmed path</text>"), std::string::npos);
  // The circle is at the end point of the programmed move of line 3.
  const size_t path = svg.find("data-line=\"3\"");
  const size_t d_end = svg.rfind("\" data-line=\"3\"", path + 1);
  const std::string d = svg.substr(svg.rfind(" L", d_end) + 2, d_end - svg.rfind(" L", d_end) - 2);
  const std::string x = d.substr(0, d.find(' ')), y = d.substr(d.find(' ') + 1);
  EXPECT_NE(svg.find("<circle cx=\"" + x + "\" cy=\"" + y + "\" r=\"7\""), std::string::npos) << d;
  // Extents of the programmed path, when there is nothing else.
  EXPECT_NE(svg.find("X 0.000 to 36.000 (36.000)"), std::string::npos);
}

}  // namespace
}  // namespace ncc::driver
