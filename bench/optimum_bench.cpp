// Program time of the planner against an offline reference, on a set of contours (figures,
// not pass/fail):   build/bench/optimum_bench
//
// The reference for a contour is the time-optimal jerk-limited profile over the contour's
// whole length, planned offline with the whole program known: rest to rest along each stretch
// between unavoidable stops (sharp corners in G61), at the contour's speed cap (the programmed
// F, or the centripetal limit sqrt(A r) on a curve), with the full axis acceleration A and
// jerk J as path limits and nothing else. It ignores what any online planner must also
// respect — the split of the axis limits between tangential and centripetal parts on curves,
// the jerk of a curvature step between a line and an arc, the jerk margin kept for junctions —
// so it is a lower bound for every contour here that moves along one axis or on a circle.
// Ratio = ncc / reference.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "ncc/machine/machine_config.h"
#include "ncc/vm/events.h"
#include "ncc/vm/motion/planner.h"
#include "ncc/vm/motion/scurve.h"
#include "planner_run.h"

namespace {

using ncc::AxisValues;
using ncc::vm::MotionPrimitive;

AxisValues xy(double x, double y) {
  AxisValues v{};
  v[0] = x;
  v[1] = y;
  return v;
}

using ncc::bench::line;

MotionPrimitive arc(const AxisValues& from, const AxisValues& to, double cx, double cy, bool cw,
                    double feed) {
  MotionPrimitive m;
  m.kind = MotionPrimitive::Kind::Arc;
  m.from = from;
  m.to = to;
  m.center = xy(cx, cy);
  m.cw = cw;
  m.feed = feed;
  return m;
}

// Seconds the planner takes (last tick - first tick).
double plannerSeconds(const ncc::MachineConfig& machine, const std::vector<MotionPrimitive>& prog) {
  return static_cast<double>(ncc::bench::runPlanner(machine, prog, 4096) - 1) *
         machine.ipo_cycle_seconds;
}

// Rest-to-rest time over `length` at path limits v, a, j (closed form via the S-curve).
double restToRest(double length, double v, double a, double j) {
  return ncc::vm::motion::planProfile(length, 0.0, 0.0, v, a, j).duration;
}

struct Contour {
  std::string name;
  std::vector<MotionPrimitive> program;
  double reference;
};

}  // namespace

int main() {
  const ncc::MachineConfig m = ncc::defaultMachine();
  const double A = m.axes[0].max_acceleration, J = m.axes[0].max_jerk;
  std::vector<Contour> contours;

  // 90 degree corners, exact stop (G61): four rest-to-rest sides.
  for (double feed : {3000.0, 6000.0}) {
    Contour c{"square 20 mm, 90 deg corners G61, F" + std::to_string(static_cast<int>(feed)), {}, 0.0};
    const AxisValues p[5] = {xy(0, 0), xy(20, 0), xy(20, 20), xy(0, 20), xy(0, 0)};
    for (int i = 0; i < 4; ++i) c.program.push_back(line(p[i], p[i + 1], feed, true));
    c.reference = 4.0 * restToRest(20.0, feed / 60.0, A, J);
    contours.push_back(c);
  }
  // Circles written as 0.01 mm chords (exact coordinates), one turn from rest to rest.
  for (double r : {10.0, 25.0}) {
    for (double feed : {3000.0, 6000.0}) {
      Contour c{"circle r" + std::to_string(static_cast<int>(r)) + " in 0.01 mm chords, F" +
                    std::to_string(static_cast<int>(feed)),
                {}, 0.0};
      const int n = static_cast<int>(std::lround(2.0 * std::numbers::pi * r / 0.01));
      AxisValues prev = xy(r, 0);
      for (int i = 1; i <= n; ++i) {
        const double t = 2.0 * std::numbers::pi * i / n;
        const AxisValues q = i == n ? xy(r, 0) : xy(r * std::cos(t), r * std::sin(t));
        c.program.push_back(line(prev, q, feed, false));
        prev = q;
      }
      const double v = std::min(feed / 60.0, std::sqrt(A * r));
      c.reference = restToRest(2.0 * std::numbers::pi * r, v, A, J);
      contours.push_back(c);
    }
  }
  // Line - tangent arc - line (a slot end): 30 mm, half circle r 25, 30 mm, F600.
  {
    Contour c{"line-arc-line, half circle r25, F600", {}, 0.0};
    const double r = 25.0, feed = 600.0;
    c.program.push_back(line(xy(0, 0), xy(30, 0), feed, false));
    c.program.push_back(arc(xy(30, 0), xy(30, 2 * r), 30, r, false, feed));
    c.program.push_back(line(xy(30, 2 * r), xy(0, 2 * r), feed, false));
    c.reference = restToRest(60.0 + std::numbers::pi * r, feed / 60.0, A, J);
    contours.push_back(c);
  }

  std::printf("%-48s %10s %10s %8s\n", "contour", "ncc s", "ref s", "ratio");
  for (const Contour& c : contours) {
    const double t = plannerSeconds(m, c.program);
    std::printf("%-48s %10.3f %10.3f %7.3fx\n", c.name.c_str(), t, c.reference, t / c.reference);
  }
  return 0;
}
