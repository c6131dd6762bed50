#include "arc_geometry.h"

#include <algorithm>
#include <cmath>

namespace ncc::passes {

double distance(PlanePoint p, PlanePoint q) { return std::hypot(q.a - p.a, q.b - p.b); }

std::optional<PlanePoint> centreFromRadius(PlanePoint start, PlanePoint end, double r,
                                           bool clockwise) {
  double da = end.a - start.a, db = end.b - start.b;
  double chord = std::hypot(da, db);
  double half = chord / 2.0, radius = std::fabs(r);
  // Relative slack for the half circle written with rounded digits (R10. over a 20.000 chord).
  if (half > radius * (1.0 + 1e-9)) return std::nullopt;
  double h = std::sqrt(std::max(0.0, radius * radius - half * half));
  // Unit normal to the right of the chord direction.
  double na = db / chord, nb = -da / chord;
  // The short arc (r > 0) has its centre on the right of the chord when clockwise and on the
  // left when counter-clockwise; the long arc (r < 0) on the other side.
  double side = (clockwise ? 1.0 : -1.0) * (r > 0 ? 1.0 : -1.0);
  return PlanePoint{start.a + da / 2.0 + side * h * na, start.b + db / 2.0 + side * h * nb};
}

}  // namespace ncc::passes
