// Travel check: motion in machine coordinates against the axes' travel limits.
#include "ncc/passes/travel_check.h"

#include <optional>
#include <utility>
#include <variant>

#include "ncc/ir/visit.h"

namespace ncc::passes {

namespace {

// The machine's indices of an arc plane's two axes (G17: X Y, G18: Z X, G19: Y Z), as the
// backend finds them; -1 where the machine lacks one (the backend reports that).
std::pair<int, int> planeAxes(const MachineConfig& machine, ir::Plane plane) {
  switch (plane) {
    case ir::Plane::XY: return {machine.axisIndex("X"), machine.axisIndex("Y")};
    case ir::Plane::ZX: return {machine.axisIndex("Z"), machine.axisIndex("X")};
    case ir::Plane::YZ: return {machine.axisIndex("Y"), machine.axisIndex("Z")};
  }
  return {-1, -1};
}

}  // namespace

void TravelCheckPass::accept(ir::Block&& block) {
  bool reported = false;  // one diagnostic per block
  for (const ir::Operation& op : block.ops) {
    // The end point of a move and whether the move leaves the travel; nothing for the
    // operations that do not move. One case per IR operation kind and no generic one, so an
    // operation kind added to the IR without its case here does not compile.
    std::optional<TravelViolation> beyond;
    const AxisValues* to = nullptr;
    std::visit(ir::Overloaded{
                   [&](const ir::Rapid& r) {
                     to = &r.to;
                     beyond = travelViolation(machine_.axes, *to);
                   },
                   [&](const ir::Linear& l) {
                     to = &l.to;
                     beyond = travelViolation(machine_.axes, *to);
                   },
                   [&](const ir::Arc& a) {
                     to = &a.to;
                     const auto [axis1, axis2] = planeAxes(machine_, a.plane);
                     if (axis1 >= 0 && axis2 >= 0) {
                       const ArcMove arc{position_,       a.to,
                                         axis1,           axis2,
                                         a.center[axis1], a.center[axis2],
                                         a.clockwise,     a.extra_turns};
                       beyond = arcTravelViolation(machine_.axes, arc);
                     } else {
                       beyond = travelViolation(machine_.axes, *to);
                     }
                   },
                   [&](const ir::Skip& s) {
                     // Where it stops is known at run time; its end point is commanded.
                     to = &s.to;
                     beyond = travelViolation(machine_.axes, *to);
                   },
                   // A reference check checks the position and does not move; a hole cycle
                   // was expanded by the cycles pass before work-to-machine: never seen here.
                   // After a PREPARE the blocks are checked as they run.
                   ir::Leave<ir::ReferenceCheck, ir::HoleCycle>{},
                   ir::NoPoint{},
               },
               op);
    if (beyond && !reported) {
      diags_.error(std::string(beyond->above ? alarms_.plus : alarms_.minus), block.loc,
                   travelMessage(*beyond, machine_.axes));
      reported = true;
    }
    if (to) position_ = *to;
  }
  next_.accept(std::move(block));
}

}  // namespace ncc::passes
