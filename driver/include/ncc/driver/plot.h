#pragma once
// `ncc plot`: the path a program runs (the executor's motion primitives, in machine
// coordinates) drawn as one self-contained SVG: top, front, side and isometric views, rapids
// dashed, feed moves solid, one colour per tool, a <title> with the source line on every move.
// With cutter compensation, the programmed path is drawn too, under the tool centre's.
// Format in docs/cli.md ("ncc plot").
#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "ncc/machine/axes.h"
#include "ncc/vm/controller.h"  // vm::EventObserver
#include "ncc/vm/events.h"

namespace ncc::driver {

// One move to draw: a rapid, line or arc of the run, and the tool in the spindle.
struct PlotMove {
  vm::MotionPrimitive motion;
  int64_t tool = 0;  // T number; 0 before any tool
};

// Collects the moves of a run (dwells are not drawn) and the tool of each. The colour follows
// the tool in the spindle: a T selects, M06 loads the selected tool. A program without any
// M06 (a machine without a changer, or a program that leaves it out) changes tool at T.
class PlotRecorder : public vm::EventObserver {
 public:
  void onEvent(const vm::Event& e) override;
  // The moves with their tools resolved by the rule above; call once, after the run.
  std::vector<PlotMove> finish();

 private:
  struct Recorded {
    vm::MotionPrimitive motion;
    int64_t selected = 0;  // the last T before the move
    int64_t loaded = 0;    // the tool the last M06 loaded
  };
  std::vector<Recorded> moves_;
  int64_t selected_ = 0;
  int64_t loaded_ = 0;
  bool changed_ = false;  // an M06 was seen
};

enum class PlotView { Top, Front, Side, Iso };

// "top", "front", "side", "iso".
const char* plotViewName(PlotView view);

struct PlotOptions {
  std::vector<PlotView> views = {PlotView::Top, PlotView::Iso, PlotView::Front, PlotView::Side};
  int width = 1200;   // px
  int height = 900;   // px
  std::string title;  // the program's name, shown at the top
  // Indices of the X, Y and Z axes in the program's axis order; -1: the machine has none
  // (drawn at 0). Other axes (rotary ones) are not drawn.
  int x_axis = 0, y_axis = 1, z_axis = 2;
  // The work zero marked in every view (machine coordinates) and its label ("G54").
  AxisValues work_zero{};
  std::string work_zero_label = "G54";
  // Cutter compensation (G41/G42): the programmed path (the program compiled with
  // compensation off), drawn thin and dashed in one colour under the moves, which are then
  // the tool centre's path; the legend names both. nullopt: the program has no compensation.
  std::optional<std::vector<PlotMove>> programmed;
  // The run stopped on this alarm: a red mark where the last drawn move ends (or at
  // `start` when none was drawn), titled with its code, place and message.
  std::optional<vm::Alarm> alarm;
  // The mark's place instead, when the compile stopped on a compensation alarm: there is no
  // tool centre's path (no moves), the mark is at the end of the alarm's programmed block.
  std::optional<AxisValues> alarm_at;
  AxisValues start{};  // machine position before the program
  // The name of source file `index` of the program (its string pool), for the titles.
  std::function<std::string(uint32_t index)> file_name;
};

// Writes the SVG document. `moves` in run order.
void writePlotSvg(std::ostream& out, const std::vector<PlotMove>& moves, const PlotOptions& options);

}  // namespace ncc::driver
