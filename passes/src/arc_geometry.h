#pragma once
// Plane geometry of G02/G03: the centre of an R-programmed arc, and the radius check of an
// I/J/K arc. Plane coordinates (a, b) are the plane's first and second axis (G17 X,Y;
// G18 Z,X; G19 Y,Z), so that clockwise is seen from the positive third axis in every plane.
#include <optional>

namespace ncc::passes {

struct PlanePoint {
  double a = 0.0, b = 0.0;
};

double distance(PlanePoint p, PlanePoint q);

// The centre of the arc from `start` to `end` with signed radius `r` (r > 0: the arc of at
// most 180 degrees, r < 0: the longer one). nullopt when |r| is shorter than half the chord
// (no circle passes through both points); start != end is the caller's precondition.
std::optional<PlanePoint> centreFromRadius(PlanePoint start, PlanePoint end, double r,
                                           bool clockwise);

}  // namespace ncc::passes
