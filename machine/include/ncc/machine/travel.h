#pragma once
// Stored stroke limits (software limit switches): the travel range [min_travel, max_travel]
// of each axis, checked before a move starts, as a controller does (FANUC OT0500/OT0501,
// Sinumerik 10720). One implementation for the VM's executor (alarm at run time) and for the
// compiler's checks (diagnostic at compile time): travelViolation() for a move's end point,
// arcTravelViolation() for the whole extent of an arc or helix.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "ncc/machine/axes.h"
#include "ncc/machine/dialect.h"
#include "ncc/machine/machine_config.h"

namespace ncc {

// A position beyond the travel range is this much past the limit (mm or deg) before it counts:
// rounding of offsets and unit conversions, far below any least input increment.
inline constexpr double kTravelTolerance = 1e-6;

struct TravelViolation {
  int axis = 0;           // index into the axes
  bool above = false;     // beyond max_travel (the + direction); else below min_travel
  double position = 0.0;  // the position outside the range (the target or the arc's extreme)
  double limit = 0.0;     // the limit it passes
};

// The first axis (in axis order) of `axes` at which `position` lies outside its travel range;
// nullopt when it is within every range. NaN counts as outside.
std::optional<TravelViolation> travelViolation(std::span<const AxisConfig> axes,
                                               const AxisValues& position);

// An arc or helix as the VM runs it (vm::MotionPrimitive, PathSegment::arc): from `from` to
// `to` around (center1, center2) in the plane of axes axis1/axis2, clockwise or not, with
// `extra_turns` full turns more; the radius changes linearly with the angle (a spiral) when
// the end radius differs; every other axis moves linearly (the helix axis).
struct ArcMove {
  AxisValues from{};
  AxisValues to{};
  int axis1 = 0;
  int axis2 = 1;
  double center1 = 0.0;
  double center2 = 0.0;
  bool cw = false;
  uint32_t extra_turns = 0;
};

// The signed angle the arc sweeps, radians: counter-clockwise in (0, 2 pi], clockwise in
// [-2 pi, 0) (equal start and end angles are a full turn), plus 2 pi per extra turn. 0 when a
// radius is 0 (the VM then runs a line).
double arcSweep(const ArcMove& arc);

// The smallest box (per axis, over the first `axis_count` axes) holding the whole arc: its end
// points and every quadrant point it passes (0, 90, 180, 270 degrees in its plane, at the
// radius it has there), and the helix axes' end points. O(1) whatever the number of turns.
struct AxisBox {
  AxisValues low{};
  AxisValues high{};
};
AxisBox arcExtent(const ArcMove& arc, int axis_count);

// travelViolation() over the arc's extent: the first axis where the box leaves the range
// (the low side first). An arc whose end points are within travel may still bulge past it.
std::optional<TravelViolation> arcTravelViolation(std::span<const AxisConfig> axes,
                                                  const ArcMove& arc);

// The text of a stored-stroke-limit alarm, the same at compile time and at run time:
// "+ overtravel (stored stroke limit): axis X would reach 50, beyond max_travel 10".
std::string travelMessage(const TravelViolation& violation, std::span<const AxisConfig> axes);

// The controller's alarm numbers for a stored stroke limit, per dialect (data, not code):
// FANUC OT0500 (+) / OT0501 (-); Sinumerik 10720 (both directions, the sign in the text);
// Mazak: the EIA/ISO manual gives no number, so ncc's NCC7210.
struct TravelAlarmCodes {
  std::string_view plus;
  std::string_view minus;
};
TravelAlarmCodes travelAlarmCodes(Dialect dialect);

}  // namespace ncc
