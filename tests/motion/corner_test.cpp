// G64 corners through the planner: a corner stops without a tolerance and is blended within
// it otherwise; a smooth chain of short lines (a tessellated circle) runs at the programmed
// feed; random polylines keep every axis limit and never leave the corner tolerance.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "gtest/gtest.h"
#include "motion_test_util.h"

namespace ncc::vm::motion {
namespace {

using namespace motion_test;

std::vector<MotionPrimitive> square(double feed) {
  return {line(xyz(0, 0, 0), xyz(10, 0, 0), feed), line(xyz(10, 0, 0), xyz(10, 10, 0), feed),
          line(xyz(10, 10, 0), xyz(0, 10, 0), feed), line(xyz(0, 10, 0), xyz(0, 0, 0), feed)};
}

TEST(Corners, StopWithoutCornerTolerance) {
  MachineConfig m = defaultMachine();
  m.corner_tolerance = 0.0;
  const std::vector<MotionPrimitive> prog = square(3000.0);
  const Trace t = run(m, prog);
  for (std::size_t i = 0; i + 1 < prog.size(); ++i)
    EXPECT_NE(std::find(t.points.begin(), t.points.end(), prog[i].to), t.points.end()) << i;
  EXPECT_LE(worstDeviation(t, prog), 1e-12);
}

// Lines of 10 mm turning by `turn_deg` alternately left and right.
std::vector<MotionPrimitive> zigzag(double turn_deg, double feed) {
  std::vector<MotionPrimitive> prog;
  AxisValues p = xyz(0, 0, 0);
  double heading = 0.0;
  for (int i = 0; i < 8; ++i) {
    const AxisValues q = xyz(p[0] + 10.0 * std::cos(heading), p[1] + 10.0 * std::sin(heading), 0);
    prog.push_back(line(p, q, feed));
    p = q;
    heading += (i % 2 == 0 ? 1.0 : -1.0) * turn_deg * std::numbers::pi / 180.0;
  }
  return prog;
}

TEST(Corners, BlendStaysWithinToleranceKeepsLimitsAndSavesTime) {
  MachineConfig stop = defaultMachine();
  stop.corner_tolerance = 0.0;
  const std::vector<MotionPrimitive> prog = zigzag(30.0, 6000.0);
  const uint64_t stop_ticks = run(stop, prog).ticks();
  uint64_t previous = stop_ticks;
  // 0.01 mm: passing a 30 degree blend that tight is slower than stopping (default jerk).
  MachineConfig tight = defaultMachine();
  tight.corner_tolerance = 0.01;
  EXPECT_LE(run(tight, prog).ticks(), stop_ticks);
  // 0.1 mm: each blend is faster than a stop whose moves keep 10 % of the jerk for their
  // junctions, which is what the decision at one corner compares with (it cannot know yet
  // whether the next corner stops too). Stopping at every corner makes every line a move
  // between stops, with the whole jerk: 1.2 % faster here. The blends are taken, within 2 %.
  {
    MachineConfig m = defaultMachine();
    m.corner_tolerance = 0.1;
    const Trace t = run(m, prog);
    EXPECT_GT(worstDeviation(t, prog), 0.03);
    EXPECT_LE(worstDeviation(t, prog), 0.1 * (1.0 + 1e-9));
    expectWithinLimits(m, t);
    EXPECT_LT(static_cast<double>(t.ticks()), 1.02 * static_cast<double>(stop_ticks));
  }
  for (double tol : {0.3, 1.0}) {
    MachineConfig m = defaultMachine();
    m.corner_tolerance = tol;
    const Trace t = run(m, prog);
    const double dev = worstDeviation(t, prog);
    EXPECT_LE(dev, tol * (1.0 + 1e-9)) << tol;
    EXPECT_GT(dev, 0.3 * tol) << tol;  // the corners are really cut
    const Worst w = check(m, t);
    EXPECT_LE(w.velocity, 1.0 + kTolerance) << tol;
    EXPECT_LE(w.acceleration, 1.0 + kTolerance) << tol;
    EXPECT_LE(w.jerk, 1.0 + kTolerance) << tol;
    EXPECT_EQ(t.points.back(), prog.back().to);
    // Never at rest between the start and the end: the corners are passed moving.
    for (std::size_t k = 5; k + 5 < t.ticks(); ++k) EXPECT_NE(t.points[k], t.points[k - 1]) << k;
    // A larger tolerance passes the corners faster.
    EXPECT_LT(t.ticks(), previous) << tol;
    previous = t.ticks();
  }
}

TEST(Corners, BlendIsChosenOnlyWhenFasterThanStopping) {
  // 90 degree corners at F6000 with the default jerk: a blend within these tolerances is
  // passed so slowly that stopping is quicker; the planner's cost estimate must see that.
  MachineConfig stop = defaultMachine();
  stop.corner_tolerance = 0.0;
  const std::vector<MotionPrimitive> prog = square(6000.0);
  const uint64_t stop_ticks = run(stop, prog).ticks();
  for (double tol : {0.001, 0.01, 0.1, 1.0, 5.0}) {
    MachineConfig m = defaultMachine();
    m.corner_tolerance = tol;
    const Trace t = run(m, prog);
    EXPECT_LE(t.ticks(), stop_ticks) << tol;
    EXPECT_LE(worstDeviation(t, prog), tol * (1.0 + 1e-9)) << tol;
  }
}

TEST(Corners, BlendTooTightForTheAxesStops) {
  // A 0.22 um line along X, whose jerk limit is 35 mm/s^3, then a turn of 90 degrees into Y
  // and Z (review fuzz, extreme axis-limit ratios). The largest blend (half the short line)
  // has so much curvature that X's jerk caps its speed at 0.004 mm/s, below the slowest speed
  // anything is planned with (1 mm/min). Passed at that floor it reached 4.9x X's jerk limit;
  // the corner must stop, like with no corner tolerance.
  MachineConfig m = defaultMachine();
  m.corner_tolerance = 0.01;
  auto set = [&](int i, double v, double a, double j) {
    m.axes[i].max_velocity = m.axes[i].rapid_velocity = v * 60.0;
    m.axes[i].max_acceleration = a;
    m.axes[i].max_jerk = j;
  };
  set(0, 9321.05, 26412.2, 35.3085);
  set(1, 365.246, 2.21014, 3.18667e6);
  set(2, 3.40538, 2.16001, 105.447);
  const AxisValues a = xyz(-188.789978, 404.67095, 213.275792);
  const AxisValues b = xyz(-188.789755, 404.67095, 213.275792);
  const AxisValues c = xyz(-188.789755, 275.281984, 188.417888);
  const std::vector<MotionPrimitive> prog = {line(a, b, 3229.25), line(b, c, 1667.03)};
  const Trace t = run(m, prog);
  expectWithinLimits(m, t);
  EXPECT_EQ(t.points.back(), c);
  EXPECT_NE(std::find(t.points.begin(), t.points.end(), b), t.points.end());  // it stops at b
}

TEST(Corners, KinkInsideARunLeavesRoomForItsAccelerationStep) {
  // A line along X, then one turned by 0.008 rad that ends at rest: a kink, passed while
  // moving, and the two lines' limits are within 1 %, so they share a run, which brakes at
  // X's full acceleration through the kink. The kink steps X's velocity by v (1 - cos theta)
  // within a cycle, v (1 - cos theta) / T in X's sampled acceleration on top of the path's:
  // the run's acceleration must leave room for it (without, 1.0066x X's limit; review fuzz).
  MachineConfig m = defaultMachine();
  setAxisLimits(m, 0, 50.0, 25000.0);
  m.axes[1].max_jerk = 5e6;  // the kink's step across the path: within Y's junction share
  m.corner_tolerance = 0.0;
  const double theta = 0.008;
  const AxisValues a = xyz(0, 0, 0), b = xyz(20.0, 0, 0);
  const AxisValues c = xyz(20.0 + 2.0 * std::cos(theta), 2.0 * std::sin(theta), 0);
  const std::vector<MotionPrimitive> prog = {line(a, b, 1500.0), line(b, c, 1500.0)};
  const Trace t = run(m, prog);
  expectWithinLimits(m, t);
  EXPECT_EQ(t.points.back(), c);
  // The path does not stop at the kink.
  for (std::size_t k = 1; k + 1 < t.ticks(); ++k) EXPECT_GT(t.infos[k].velocity, 0.0) << k;
}

TEST(Corners, KinkStaysWithinTheAccelerationOfAnAxisOfHugeJerk) {
  // Y's jerk is 10^5 times its acceleration per second: the kink rule's jerk share lets a
  // 0.009 rad kink pass at 55 mm/s, a step of v |dt_y| / T = 500 mm/s^2 in Y's sampled
  // acceleration, 5x its limit (review). The kink's acceleration step has its own share.
  MachineConfig m = defaultMachine();
  m.corner_tolerance = 0.0;
  setAxisLimits(m, 1, 100.0, 1e7);
  const double theta = 0.009;
  const std::vector<MotionPrimitive> prog = {
      line(xyz(0, 0, 0), xyz(10, 0, 0), 6000.0),
      line(xyz(10, 0, 0), xyz(20, 10 * std::tan(theta), 0), 6000.0)};
  const Trace t = run(m, prog);
  expectWithinLimits(m, t);
  EXPECT_EQ(t.points.back(), prog.back().to);
}

TEST(Corners, KinkLeavesRoomOnBothSidesWhenTheJerkIsHuge) {
  // Y of 1.348 mm/s^2 and 2.5e6 mm/s^3: the path's acceleration changes within a microsecond.
  // A line tilted from Y towards Z by 0.0032 rad accelerates at Y's full acceleration into a
  // kink onto Y (which raises Y's velocity by v (1 - cos) within a cycle), and the line after
  // it (another F: another run) accelerates on. The runs meet at a = 0, but a sample across the vertex sees nearly all of
  // both runs' acceleration next to the kink's velocity step: the move before the kink keeps
  // room for it too (1.0007x Y's limit here without; review fuzz: 1.015x).
  MachineConfig m = defaultMachine();
  m.corner_tolerance = 0.0;
  setAxisLimits(m, 1, 1.348, 2.5e6);
  setAxisLimits(m, 2, 133.0, 4e6);
  const double tilt = 0.0032;
  const AxisValues a = xyz(0, 0, 0), b = xyz(0, 0.63 * std::cos(tilt), 0.63 * std::sin(tilt));
  const AxisValues c = xyz(0, b[1] + 2.0, b[2]);
  const std::vector<MotionPrimitive> prog = {line(a, b, 1378.0), line(b, c, 600.0)};
  const Trace t = run(m, prog);
  expectWithinLimits(m, t);
  EXPECT_EQ(t.points.back(), c);
}

TEST(Corners, CircleOfKinksCountsThemLikeItsCurvature) {
  // R 50 mm in 2.5 um chords at F15000 (a realistic machine: A 1000, J 3e5): every vertex turns
  // by 5e-5 rad, little enough for the kink rule at that speed, but 1.7 vertices fall within
  // each cycle and their steps add up to v^2 / R = 1250 mm/s^2. Kinks closer than v T count
  // like a curvature |dt| / L, so the polygon is planned as the curve it is (it took 1.69x
  // the acceleration limit; review).
  MachineConfig m = defaultMachine();
  m.corner_tolerance = 0.0;
  for (int i = 0; i < 3; ++i) setAxisLimits(m, i, 1000.0, 3e5);
  const double r = 50.0, chord = 2.5e-3;
  std::vector<MotionPrimitive> prog;
  AxisValues p = xyz(r, 0, 0);
  for (int i = 1; i <= 40000; ++i) {
    const AxisValues q = xyz(r * std::cos(i * chord / r), r * std::sin(i * chord / r), 0);
    prog.push_back(line(p, q, 15000.0));
    p = q;
  }
  const Trace t = run(m, prog, 100000);
  expectWithinLimits(m, t);
  EXPECT_EQ(t.points.back(), prog.back().to);
}

TEST(Corners, KinksWithinOneCycleAddUp) {
  // 100 chords of 1 um at F6000 on the default machine, each turning by 90 % of what the kink
  // rule allows one kink: 1.7 of them fall within each cycle, and their jerk added up to
  // 2.9x the limit (review).
  MachineConfig m = defaultMachine();
  m.corner_tolerance = 0.0;
  const double v = 100.0, T = m.ipo_cycle_seconds;
  const double turn = 0.9 * std::min(0.05 * 2000.0 * T / v, 0.05 * 50000.0 * T * T / v);
  std::vector<MotionPrimitive> prog;
  AxisValues p = xyz(0, 0, 0);
  double heading = 0.0;
  auto go = [&](double length) {
    const AxisValues q = xyz(p[0] + length * std::cos(heading), p[1] + length * std::sin(heading), 0);
    prog.push_back(line(p, q, 6000.0));
    p = q;
  };
  go(50.0);
  for (int i = 0; i < 100; ++i) {
    heading += turn;
    go(1e-3);
  }
  heading += turn;
  go(20.0);
  const Trace t = run(m, prog);
  expectWithinLimits(m, t);
  EXPECT_EQ(t.points.back(), prog.back().to);
}

TEST(Corners, CollinearSplitHasNoSlowdown) {
  const MachineConfig m = defaultMachine();
  const Trace straight = run(m, {line(xyz(0, 0, 0), xyz(10, 0, 0), 3000.0),
                                 line(xyz(10, 0, 0), xyz(20, 0, 0), 3000.0)});
  double slowest_mid = 1e9;
  for (std::size_t k = 0; k < straight.ticks(); ++k) {
    const double x = straight.points[k][0];
    if (x > 5.0 && x < 15.0) slowest_mid = std::min(slowest_mid, straight.infos[k].velocity);
  }
  EXPECT_EQ(slowest_mid, 50.0);
}

class TessellatedCircle : public ::testing::TestWithParam<double> {};

TEST_P(TessellatedCircle, RunsAtFeedLikeTheCircle) {
  // R 10 mm in 0.01 mm chords from rest to rest: a smooth chain, its chords bowed. It must run
  // like the arc: the programmed feed (within the bows' speed bound, 1 + 2.5e-7), within 3 %
  // of the arc's time (on the polygon, whose vertices' wiggle took a tenth of the jerk, it
  // was 2 % slower at F6000), and within every axis limit. At F6000 this needs the chain's
  // first and last lines bowed to a parabola where the path rests (else their curvature
  // swings from twice the chain's to minus it), and the last one of the same limits as the
  // others (else the braking ends at a = 0 before it and it is a profile of its own).
  const MachineConfig m = defaultMachine();
  const double r = 10.0, feed = GetParam();
  const int n = static_cast<int>(std::lround(2.0 * std::numbers::pi * r / 0.01));
  const std::vector<MotionPrimitive> prog = polygonCircle(r, n, feed);
  // A window of 4096 segments: braking from 100 mm/s takes about 6.7 mm, 670 of these chords.
  const Trace t = run(m, prog, 4096);
  const Trace arc_trace = run(m, {arc(xyz(r, 0, 0), xyz(r, 0, 0), 0, 1, 0.0, 0.0, false, feed)});
  double top = 0.0;
  for (const auto& info : t.infos) top = std::max(top, info.velocity);
  EXPECT_NEAR(top, feed / 60.0, 1e-6 * feed / 60.0);
  EXPECT_LT(static_cast<double>(t.ticks()), 1.01 * static_cast<double>(arc_trace.ticks()));
  expectWithinAxisLimits(m, t);
  EXPECT_EQ(t.points.back(), prog.back().to);
  // The bows leave the chords by at most their sagitta, c^2 / 8 r = 1.25 nm.
  EXPECT_LE(worstDeviation(t, prog), 1.26e-6);
}

INSTANTIATE_TEST_SUITE_P(Corners, TessellatedCircle, ::testing::Values(3000.0, 6000.0));

TEST(Corners, ZeroLengthRapidDoesNotEndAChainAtRest) {
  // A chain followed by a rapid that does not move and then a line: nothing stops between
  // them, so the chain's last line must keep its curvature-step limit (a chain's end is only
  // free of it where the path is at rest). With the chain ended as if at rest the sampled
  // jerk was 14.9 x the limit.
  const MachineConfig m = defaultMachine();
  const double r = 10.0;
  const int n = static_cast<int>(std::lround(std::numbers::pi * r / 0.01));
  std::vector<MotionPrimitive> prog;
  AxisValues p = xyz(r, 0, 0);
  for (int i = 1; i <= n; ++i) {
    const double a = std::numbers::pi * i / n;
    const AxisValues q = xyz(r * std::cos(a), r * std::sin(a), 0);
    prog.push_back(line(p, q, 6000.0));
    p = q;
  }
  // The line goes on exactly along the last chord: no kink to slow the junction.
  const AxisValues& before = prog.back().from;
  const AxisValues on = xyz(p[0] + 500.0 * (p[0] - before[0]), p[1] + 500.0 * (p[1] - before[1]), 0);
  prog.push_back(rapid(p, p));
  prog.push_back(line(p, on, 6000.0));
  const Trace t = run(m, prog, 4096);
  const Worst w = check(m, t);
  EXPECT_LE(w.acceleration, 1.0 + kTolerance);
  EXPECT_LE(w.jerk, 1.0 + kTolerance);
  EXPECT_EQ(t.points.back(), prog.back().to);
}

TEST(Corners, ChainNextToAStopTakesNoWiggleFromTheAxesBeyondIt) {
  // A line through X, Y and a slow Z reverses (a stop) into a gently curving chain in XY
  // whose polygon deviates from its curve by 0.3 um: more than Z's whole smooth jerk share
  // (0.9 J T^3 / 4 = 1.5e-7 mm) but within X's and Y's wiggle budget. Z does not move on
  // the chain, and its first vertex is a stop, so Z takes no wiggle there. Counting the line
  // before the stop as the chain's neighbour gave the first chain line negative acceleration
  // and jerk limits: it crept at 1 mm/min after a 0.22 um step, 27.6 x the jerk limit
  // (review fuzz seed 179).
  MachineConfig m = defaultMachine();
  setAxisLimits(m, 0, 1862.0, 15529.0);
  setAxisLimits(m, 1, 1872.0, 165963.0);
  setAxisLimits(m, 2, 55.5, 679.5);
  const double chord = 0.01, feed = 3000.0;
  const double turn = 8.0 * 3e-7 / chord;  // sagitta c * turn / 8 = 0.3 um
  std::vector<MotionPrimitive> prog;
  AxisValues p = xyz(0.05, 0.02, 0.002);
  prog.push_back(line(xyz(0, 0, 0), p, feed));
  double heading = std::numbers::pi;  // back along -X: a reversal, so a stop
  for (int i = 0; i < 200; ++i) {
    heading += turn;
    const AxisValues q = xyz(p[0] + chord * std::cos(heading), p[1] + chord * std::sin(heading), p[2]);
    prog.push_back(line(p, q, feed));
    p = q;
  }
  const Trace t = run(m, prog, 64);
  expectWithinLimits(m, t);
  EXPECT_EQ(t.points.back(), prog.back().to);
  // No creep: 2 mm of chain at up to 50 mm/s, limited by the 64-segment window (0.64 mm),
  // takes well under a second; creeping through one 10 um line at 1 mm/min alone took 0.6 s.
  EXPECT_LT(t.ticks(), 400u);
}

// Random 3-D polylines: segment lengths from 5 um to 20 mm, turns from 0 to 175 degrees,
// feeds 100..8000 mm/min, on a machine with unequal axes.
TEST(Corners, RandomPolylinesKeepLimitsAndTolerance) {
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    Random rng(seed);
    MachineConfig m = defaultMachine();
    m.axes[1].max_acceleration = 3000.0;
    m.axes[2].max_jerk = 30000.0;
    m.corner_tolerance = seed % 3 == 0 ? 0.002 : seed % 3 == 1 ? 0.02 : 0.2;
    std::vector<MotionPrimitive> prog;
    AxisValues p{};
    AxisValues dir = xyz(1, 0, 0);
    for (int i = 0; i < 60; ++i) {
      const double len = std::exp(rng.uniform(std::log(0.005), std::log(20.0)));
      const double turn = rng.below(4) == 0 ? 0.0 : rng.uniform(0.0, 175.0) * std::numbers::pi / 180.0;
      const double phase = rng.uniform(0.0, 2.0 * std::numbers::pi);
      // Rotate dir by `turn` towards a random perpendicular.
      AxisValues a = std::abs(dir[2]) < 0.9 ? xyz(0, 0, 1) : xyz(1, 0, 0);
      AxisValues e1 = xyz(dir[1] * a[2] - dir[2] * a[1], dir[2] * a[0] - dir[0] * a[2],
                          dir[0] * a[1] - dir[1] * a[0]);
      const double n1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
      for (int k = 0; k < 3; ++k) e1[k] /= n1;
      const AxisValues e2 = xyz(dir[1] * e1[2] - dir[2] * e1[1], dir[2] * e1[0] - dir[0] * e1[2],
                                dir[0] * e1[1] - dir[1] * e1[0]);
      AxisValues nd{};
      for (int k = 0; k < 3; ++k)
        nd[k] = std::cos(turn) * dir[k] +
                std::sin(turn) * (std::cos(phase) * e1[k] + std::sin(phase) * e2[k]);
      dir = nd;
      const AxisValues q = xyz(p[0] + len * dir[0], p[1] + len * dir[1], p[2] + len * dir[2]);
      const double feed = rng.uniform(100.0, 8000.0);
      prog.push_back(line(p, q, feed));
      p = q;
    }
    const Trace t = run(m, prog);
    const Worst w = check(m, t);
    EXPECT_LE(w.velocity, 1.0 + kTolerance) << "seed " << seed;
    EXPECT_LE(w.acceleration, 1.0 + kTolerance) << "seed " << seed;
    EXPECT_LE(w.jerk, 1.0 + kTolerance) << "seed " << seed;
    EXPECT_LE(worstDeviation(t, prog), m.corner_tolerance * (1.0 + 1e-9)) << "seed " << seed;
    EXPECT_EQ(t.points.back(), prog.back().to) << "seed " << seed;
  }
}

}  // namespace
}  // namespace ncc::vm::motion
