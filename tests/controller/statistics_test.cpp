// RunResult statistics against hand computations: program time of a rest-to-rest line (closed form
// of the S-curve), exact path length, following error v/Kv without feed-forward, contour
// error of a straight line (zero) and of a circle (the servo model's radius error).
#include <cmath>
#include <cstdio>
#include <numbers>

#include "controller_test_util.h"
#include "ncc/vm/motion/limits.h"

namespace ncc {
namespace {

using namespace controller_test;
using vm::TickOutput;
using vm::TickStatus;

// No feed-forward, Kv 1 ((m/min)/mm), the default speed-loop time constant, monitoring off.
ServoConfig laggingServo() {
  ServoConfig s;
  s.ffw_mode = FeedForwardMode::None;
  s.contour_tol = 1e6;
  s.standstill_pos_tol = 1e6;
  return s;
}

struct RunResult {
  std::vector<TickOutput> ticks;
  vm::RunStatistics stats;
};

RunResult runProgram(bytecode::Program program, const MachineConfig& m) {
  std::unique_ptr<vm::Controller> ctl = make(std::move(program), m);
  RunResult r;
  TickOutput out;
  while (ctl->tick(out) == TickStatus::Running) r.ticks.push_back(out);
  EXPECT_EQ(ctl->status(), TickStatus::Finished);
  r.stats = ctl->statistics();
  return r;
}

TEST(ControllerStatistics, SingleLineAgainstClosedForms) {
  const MachineConfig m = machineWith(laggingServo());
  const double L = 500.0, F = 6000.0, v = F / 60.0;
  bytecode::Assembler a = assemblerFor(m);
  a.line(xyz(L, 0, 0), F).op(bytecode::Opcode::End);
  const RunResult r = runProgram(a.finish(), m);

  // Rest to rest with v and a reached: D = L/v + v/a + a/j (docs/planner.md), the line's path
  // jerk being the whole axis jerk (kBetweenStopsJerkShare: no junction needs room). Tick k
  // samples t = kT; the end point is held on the first tick after D (the stop sample).
  const double acc = 2000.0, jerk = vm::motion::kBetweenStopsJerkShare * 50000.0, T = 0.001;
  const double D = L / v + v / acc + acc / jerk;  // 5.09 s
  const uint64_t ticks = static_cast<uint64_t>(std::floor(D / T)) + 2;
  EXPECT_EQ(r.stats.ticks, ticks);
  EXPECT_EQ(r.stats.program_time, static_cast<double>(ticks - 1) * T);
  EXPECT_LE(r.stats.program_time - D, 2 * T);
  EXPECT_GE(r.stats.program_time, D);

  // Path length: the chords of a straight line add up to it.
  EXPECT_NEAR(r.stats.path_length, L, 1e-9);
  EXPECT_EQ(r.stats.feed_length, r.stats.path_length);
  EXPECT_EQ(r.stats.rapid_length, 0.0);

  // Constant velocity without feed-forward: e = v/Kv = 100 / 16.67 = 6 mm, exact in the
  // discrete model once the transient (slowest pole -18/s) has died out.
  const double e = v / kvPerSecond(1.0);
  const TickOutput& mid = r.ticks[2500];
  ASSERT_EQ(mid.path_velocity, v);
  EXPECT_NEAR(mid.following_error[0], e, 1e-9);
  EXPECT_NEAR(r.stats.max_following_error[0], e, 1e-9);  // overdamped loop: no overshoot
  EXPECT_EQ(r.stats.max_following_error[1], 0.0);
  // Along X only: the error is along the path, never across it.
  EXPECT_EQ(r.stats.max_contour_error, 0.0);
  EXPECT_EQ(r.stats.limit_violations, 0);
}

TEST(ControllerStatistics, DiagonalLineLagsAlongThePathOnly) {
  const MachineConfig m = machineWith(laggingServo());
  bytecode::Assembler a = assemblerFor(m);
  a.line(xyz(300, 400, 0), 6000.0).op(bytecode::Opcode::End);
  const RunResult r = runProgram(a.finish(), m);
  EXPECT_NEAR(r.stats.path_length, 500.0, 1e-9);
  EXPECT_NEAR(r.stats.max_following_error[0], 0.6 * 6.0, 1e-9);
  EXPECT_NEAR(r.stats.max_following_error[1], 0.8 * 6.0, 1e-9);
  EXPECT_LT(r.stats.max_contour_error, 1e-7);  // rounding of the direction at low speed
}

TEST(ControllerStatistics, RapidAndFeedLengthsAreSeparate) {
  const MachineConfig m = defaultMachine();
  bytecode::Assembler a = assemblerFor(m);
  a.rapid(xyz(10, 0, 0)).line(xyz(10, 20, 0), 1000.0).op(bytecode::Opcode::End);
  const RunResult r = runProgram(a.finish(), m);
  EXPECT_NEAR(r.stats.rapid_length, 10.0, 1e-12);
  EXPECT_NEAR(r.stats.feed_length, 20.0, 1e-12);
  EXPECT_EQ(r.ticks.back().commanded, xyz(10, 20, 0));
}

TEST(ControllerStatistics, CircleContourErrorIsTheRadiusError) {
  // Velocity feed-forward, Kv 1, T_eq 4 ms, F6000 on r = 10 mm: with the setpoint delayed by
  // the speed loop's lag (docs/servo.md) the circle shrinks by 0.0080736 mm (discrete steady
  // state), and the actual position trails the commanded one by about v * T_eq = 0.4 mm along
  // the path. The contour error is measured against the tangent at the commanded point, so it
  // is the shrink plus what that trailing chord adds, r (w T_eq)^2 / 2.
  ServoConfig s;
  s.contour_tol = 1e6;
  s.standstill_pos_tol = 1e6;
  const MachineConfig m = machineWith(s);
  const double r = 10.0;
  bytecode::Assembler a = assemblerFor(m);
  a.line(xyz(r, 0, 0), 6000.0);
  a.arc(xyz(r, 0, 0), 0, 1, 0.0, 0.0, 6000.0, 0, bytecode::ArcPlane::XY, 9);  // 10 turns
  a.op(bytecode::Opcode::End);
  const RunResult run_ = runProgram(a.finish(), m);

  // Over the 9th turn (settled): the radius shrink, and the contour error by hand from the
  // exact tangent (-y, x)/r of the commanded point.
  double shrink = 0.0, grow = 0.0, contour = 0.0;
  const std::size_t n = run_.ticks.size();
  for (std::size_t k = 8 * n / 10; k < 9 * n / 10; ++k) {
    const TickOutput& t = run_.ticks[k];
    const double radius = std::hypot(t.actual[0], t.actual[1]);
    shrink = std::max(shrink, r - radius);
    grow = std::max(grow, radius - r);
    const double ux = -t.commanded[1] / r, uy = t.commanded[0] / r;
    const double ex = t.actual[0] - t.commanded[0], ey = t.actual[1] - t.commanded[1];
    const double along = ex * ux + ey * uy;
    contour = std::max(contour, std::hypot(ex - along * ux, ey - along * uy));
  }
  const double w = 100.0 / r, t_eq = 0.004;
  EXPECT_NEAR(shrink, 0.0080736, 1e-6);
  EXPECT_LE(grow, 0.0);
  EXPECT_NEAR(contour, shrink + r * w * w * t_eq * t_eq / 2.0, 1e-4);
  // The whole run's maximum includes the start of the circle.
  EXPECT_GE(run_.stats.max_contour_error, 0.99 * contour);
  EXPECT_LT(run_.stats.max_contour_error, 1.5 * contour);
  std::printf("circle F6000 r10: shrink %.6f mm, contour (9th turn) %.6f mm, run max "
              "%.6f mm at tick %llu of %zu\n",
              shrink, contour, run_.stats.max_contour_error,
              static_cast<unsigned long long>(run_.stats.max_contour_error_tick), n);
}

}  // namespace
}  // namespace ncc
