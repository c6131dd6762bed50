#include "ncc/vm/run_limits.h"

#include <algorithm>
#include <cmath>

#include "ncc/machine/travel.h"

namespace ncc::vm {

double topPathSpeed(const MachineConfig& machine) {
  double sum = 0.0;
  for (const AxisConfig& a : machine.axes) {
    const double v = std::max(a.rapid_velocity, a.max_velocity) / 60.0;
    sum += v * v;
  }
  return std::sqrt(sum);
}

double minimumSeconds(const MotionPrimitive& m, const MachineConfig& machine,
                      double max_feed_override, double spindle_rpm) {
  using Kind = MotionPrimitive::Kind;
  if (m.kind == Kind::Dwell) return m.revolutions ? 0.0 : std::max(m.seconds, 0.0);
  const int n = std::min(machine.axisCount(), kMaxAxes);
  double off_plane = 0.0;  // squared travel of the axes outside the arc's plane (all for a line)
  for (int i = 0; i < n; ++i) {
    if (m.kind == Kind::Arc && (i == m.axis1 || i == m.axis2)) continue;
    const double d = m.to[i] - m.from[i];
    off_plane += d * d;
  }
  double plane = 0.0;
  if (m.kind == Kind::Arc) {
    const ArcMove arc{m.from, m.to, m.axis1, m.axis2, m.center[m.axis1], m.center[m.axis2],
                      m.cw, m.extra_turns};
    const double r0 = std::hypot(m.from[m.axis1] - arc.center1, m.from[m.axis2] - arc.center2);
    const double r1 = std::hypot(m.to[m.axis1] - arc.center1, m.to[m.axis2] - arc.center2);
    const double sweep = arcSweep(arc);
    if (sweep == 0.0) {  // a degenerate arc runs as a line
      const double d1 = m.to[m.axis1] - m.from[m.axis1], d2 = m.to[m.axis2] - m.from[m.axis2];
      plane = std::hypot(d1, d2);
    } else {
      plane = std::min(r0, r1) * std::abs(sweep);
    }
  }
  const double length = std::sqrt(plane * plane + off_plane);
  double speed = topPathSpeed(machine);
  const double per_minute = m.feed_per_rev ? m.feed * spindle_rpm : m.feed;  // mm/min
  if (m.kind != Kind::Rapid && per_minute > 0.0)
    speed = std::min(speed, per_minute / 60.0 * std::max(max_feed_override, 1.0));
  if (!(speed > 0.0)) return 0.0;
  const double seconds = length / speed;
  return std::isfinite(seconds) ? seconds : 0.0;
}

}  // namespace ncc::vm
