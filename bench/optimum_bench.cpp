// Program time of the planner against an offline reference, on a set of contours (figures,
// not pass/fail):   build/bench/optimum_bench
//
// The reference for a contour is its time-optimal run, planned offline with the whole program
// known and the machine's full axis limits A and J (no share kept for junctions):
// - lines along one axis (the G61 square's sides): the rest-to-rest S-curve, which is the
//   optimum of that 1-D problem;
// - circles (as one arc, or written as 0.01 mm chords 1.25 nm off the circle): the per-axis
//   optimum of circle_optimum.h, which uses the limits as they are at each point of the
//   circle. On these circles it is within 0.3 % of the S-curve at A and J over the whole
//   length, because the run-up happens where the tangent is nearly along Y and the
//   centripetal part along X, each axis with its own limit;
// - line - arc - line at F600: the S-curve over the whole length (the arc's 4 mm/s^2 of
//   centripetal acceleration left out: a lower bound, tight to 0.1 %).
// A planner must also keep within the limits at the worst orientation of a curve it has not
// reached yet, and between runs; the ratio shows what that costs. Ratio = ncc / reference.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "ncc/machine/machine_config.h"
#include "ncc/vm/events.h"
#include "ncc/vm/motion/planner.h"
#include "ncc/vm/motion/scurve.h"
#include "circle_optimum.h"
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
      c.reference = ncc::bench::CircleOptimum(r, feed / 60.0, A, J).seconds();
      contours.push_back(c);
    }
  }
  // The same circles as one G2/G3 (the path is the circle itself: no polygon wiggle).
  for (double r : {10.0, 25.0}) {
    Contour c{"circle r" + std::to_string(static_cast<int>(r)) + " as one arc, F6000", {}, 0.0};
    c.program.push_back(arc(xy(r, 0), xy(r, 0), 0.0, 0.0, false, 6000.0));
    c.reference = ncc::bench::CircleOptimum(r, 100.0, A, J).seconds();
    contours.push_back(c);
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

  // The circle solver on a straight line (r = 1e7 mm): its run-up and slow-down must cost
  // what the closed-form S-curve's do.
  {
    const double r = 1e7, v = 100.0, length = 2.0 * std::numbers::pi * r;
    const double solver = ncc::bench::CircleOptimum(r, v, A, J).seconds() - length / v;
    const double closed = restToRest(length, v, A, J) - length / v;
    std::printf("reference check: ramps of a straight line at F6000, solver %.5f s, closed form "
                "%.5f s\n\n",
                solver, closed);
  }
  std::printf("%-48s %10s %10s %8s\n", "contour", "ncc s", "ref s", "ratio");
  for (const Contour& c : contours) {
    const double t = plannerSeconds(m, c.program);
    std::printf("%-48s %10.3f %10.3f %7.3fx\n", c.name.c_str(), t, c.reference, t / c.reference);
  }
  return 0;
}
