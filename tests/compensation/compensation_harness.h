#pragma once
// Builds IR blocks with a compensation request by hand and runs them through the compensation
// pass alone, so its rules are tested without the lowering (tests/compensation/).
#include <string>
#include <vector>

#include "ncc/ir/ir.h"
#include "ncc/machine/dialect.h"
#include "ncc/support/diagnostics.h"

namespace ncc::passes::testing {

class CompProgram {
 public:
  explicit CompProgram(Dialect dialect = Dialect::FanucM) : dialect_(dialect) {}
  // The settings every later request carries.
  ir::CutterComp& settings() { return settings_; }
  // G41 (w > 0) / G42 (w < 0) with radius |w| from the next block on; 0: G40.
  CompProgram& side(ir::CutterComp::Side side, double radius);
  CompProgram& cancel() { return side(ir::CutterComp::Side::Off, 0.0); }
  // The next block's special, vector or hole-cycle suspension.
  CompProgram& special(ir::CutterComp::Special s) { next_.special = s; return *this; }
  CompProgram& vector(double i, double j) { next_.vector = std::array<double, 3>{i, j, 0}; return *this; }
  // The next block is a hole cycle's (its moves run on the programmed points).
  CompProgram& suspend() { next_.suspended = true; return *this; }
  // G93/G94/G95 for the blocks after.
  CompProgram& feedMode(ir::FeedMode mode) { feed_mode_ = mode; return *this; }
  CompProgram& rapid(double x, double y, double z = 0.0);
  CompProgram& line(double x, double y, double z = 0.0, double feed = 100.0);
  CompProgram& arc(double x, double y, double cx, double cy, bool clockwise, double z = 0.0);
  CompProgram& still();  // a block without motion (M08)
  // A move in machine space (G28's last leg).
  CompProgram& machineRapid(double x, double y, double z = 0.0);

  // The moves out of the pass, one per line: "R x y", "L x y", "A x y cx cy cw|ccw" (plane
  // coordinates, 3 decimals; an arc's " zZ" if it ends off Z = 0), each prefixed with the
  // source line of its block.
  std::string run();
  const DiagnosticEngine& diagnostics() const { return diags_; }
  std::vector<ir::Block> runBlocks();
  // The blocks built so far (to feed a pass by hand).
  const std::vector<ir::Block>& built() const { return blocks_; }
  // The blocks as programmed (the pass's input).
  const std::vector<ir::Block>& input() const { return blocks_; }

 private:
  ir::Block next(ir::Operation op);
  Dialect dialect_;
  ir::CutterComp settings_;
  ir::CutterComp::Side side_ = ir::CutterComp::Side::Off;
  double radius_ = 0.0;
  bool on_ = false, cancelling_ = false, commanded_ = false;
  struct Next {
    ir::CutterComp::Special special = ir::CutterComp::Special::None;
    std::optional<std::array<double, 3>> vector;
    bool suspended = false;
  } next_;
  ir::FeedMode feed_mode_ = ir::FeedMode::PerMinute;
  std::vector<ir::Block> blocks_;
  DiagnosticEngine diags_;
};

// The moves of `blocks` in the harness's text form.
std::string movesText(const std::vector<ir::Block>& blocks);

}  // namespace ncc::passes::testing
