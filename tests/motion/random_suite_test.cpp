// A seeded random program suite: 10 um G01 chains, zigzag reversals, tight arcs, helices,
// tangent line-arc chains, linear and non-linear rapids, exact stops and dwells, G64 polylines with corners (blended
// within the corner tolerance), and tessellated arcs (smooth chains), exact or rounded to
// 0.1 um as a CAM system writes them. On the sampled setpoints, per axis,
// finite differences must stay within the axis velocity, acceleration and jerk limits, and
// every stop must land exactly on its programmed point. Plus the pinned determinism hash.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "gtest/gtest.h"
#include "motion_test_util.h"

namespace ncc::motion_test {
namespace {

// Axes with different limits, so projections matter.
MachineConfig testMachine() {
  MachineConfig m = defaultMachine();
  m.axes[0].max_velocity = 12000.0;
  m.axes[0].rapid_velocity = 24000.0;
  m.axes[1].max_velocity = 10000.0;
  m.axes[1].rapid_velocity = 20000.0;
  m.axes[1].max_acceleration = 3000.0;
  m.axes[1].max_jerk = 80000.0;
  m.axes[2].max_velocity = 6000.0;
  m.axes[2].rapid_velocity = 12000.0;
  m.axes[2].max_acceleration = 1500.0;
  m.axes[2].max_jerk = 30000.0;
  return m;
}

class Generator {
 public:
  explicit Generator(uint64_t seed) : rng_(seed) {}

  std::vector<MotionPrimitive> program(int pieces) {
    prog_.clear();
    for (int i = 0; i < pieces; ++i) {
      switch (rng_.below(9)) {
        case 7: polyline(); break;
        case 8: tessellatedArc(); break;
        case 0: chain(false); break;
        case 1: chain(true); break;
        case 2: tightArc(); break;
        case 3: helix(); break;
        case 4: tangentLineArc(); break;
        case 5: {
          MotionPrimitive r = rapid(pos_, target());
          r.per_axis = rng_.below(2) == 0;  // non-linear positioning
          emit(r);
          break;
        }
        default: stopOrDwell(); break;
      }
    }
    return prog_;
  }

 private:
  double feed() { return rng_.uniform(200.0, 8000.0); }
  AxisValues target() {
    // One draw per statement: the evaluation order of function arguments is unspecified (GCC
    // and clang differ), and the suite must generate the same programs on every compiler.
    const double x = rng_.uniform(-50, 50);
    const double y = rng_.uniform(-50, 50);
    const double z = rng_.uniform(-20, 20);
    return xyz(x, y, z);
  }
  void emit(MotionPrimitive m) {
    prog_.push_back(m);
    pos_ = m.to;
  }
  // Collinear 10 um chain (or a zigzag: reversal after every segment).
  void chain(bool zigzag) {
    const int n = 20 + rng_.below(300);
    const double th = rng_.uniform(0, 2 * std::numbers::pi), ph = rng_.uniform(-0.5, 0.5);
    const AxisValues d = xyz(std::cos(th) * std::cos(ph), std::sin(th) * std::cos(ph), std::sin(ph));
    const AxisValues base = pos_;
    const double f = feed();
    for (int i = 1; i <= n; ++i) {
      const double s = zigzag ? 0.01 * (i % 2) : 0.01 * i;
      emit(line(pos_, xyz(base[0] + d[0] * s, base[1] + d[1] * s, base[2] + d[2] * s), f));
    }
  }
  void tightArc() {
    const int plane = rng_.below(3);
    const int a1 = plane == 0 ? 0 : plane == 1 ? 2 : 1, a2 = plane == 0 ? 1 : plane == 1 ? 0 : 2;
    const double r = rng_.uniform(0.1, 2.0);
    const double th0 = rng_.uniform(0, 2 * std::numbers::pi);
    const double c1 = pos_[a1] - r * std::cos(th0), c2 = pos_[a2] - r * std::sin(th0);
    const double th1 = th0 + rng_.uniform(-6.0, 6.0);
    AxisValues to = pos_;
    to[a1] = c1 + r * std::cos(th1);
    to[a2] = c2 + r * std::sin(th1);
    const bool cw = rng_.below(2) == 0;
    const double f = feed();
    emit(arc(pos_, to, a1, a2, c1, c2, cw, f));
  }
  void helix() {
    const double r = rng_.uniform(0.3, 8.0);
    const double c1 = pos_[0] - r, c2 = pos_[1];
    const double th1 = rng_.uniform(0.5, 6.0);
    const double dz = rng_.uniform(-3, 3);
    AxisValues to = xyz(c1 + r * std::cos(th1), c2 + r * std::sin(th1), pos_[2] + dz);
    const bool cw = rng_.below(2) == 0;
    const double f = feed();
    const int turns = rng_.below(3);
    emit(arc(pos_, to, 0, 1, c1, c2, cw, f, turns));
  }
  // Line, tangent quarter arc, tangent line: junctions pass without stopping.
  void tangentLineArc() {
    const double f = feed(), r = rng_.uniform(0.5, 10.0), L = rng_.uniform(0.1, 10.0);
    const AxisValues p1 = xyz(pos_[0] + L, pos_[1], pos_[2]);
    emit(line(pos_, p1, f));
    const AxisValues p2 = xyz(p1[0] + r, p1[1] + r, p1[2]);
    emit(arc(p1, p2, 0, 1, p1[0], p1[1] + r, false, f));
    emit(line(p2, xyz(p2[0], p2[1] + L, p2[2]), f));
  }
  // G01 corners: lengths 10 um .. 10 mm, turns up to 170 degrees, in the XY plane or 3-D.
  void polyline() {
    const int n = 3 + rng_.below(15);
    const double f = feed();
    double heading = rng_.uniform(0, 2 * std::numbers::pi);
    const double climb = rng_.below(2) == 0 ? 0.0 : rng_.uniform(-0.5, 0.5);
    for (int i = 0; i < n; ++i) {
      const double len = std::exp(rng_.uniform(std::log(0.01), std::log(10.0)));
      heading += rng_.uniform(-170.0, 170.0) * std::numbers::pi / 180.0;
      const double dz = i % 2 == 0 ? climb : -climb;
      emit(line(pos_, xyz(pos_[0] + len * std::cos(heading), pos_[1] + len * std::sin(heading),
                          pos_[2] + len * dz), f));
    }
  }
  // An arc of radius 0.5..30 mm written as chords of 2 um .. 0.5 mm, exact or rounded to
  // 0.1 um; some with a slow Z ramp (a tessellated helix).
  void tessellatedArc() {
    const double r = rng_.uniform(0.5, 30.0);
    const double chord = std::exp(rng_.uniform(std::log(0.002), std::log(0.5)));
    const double sweep = rng_.uniform(0.3, 7.0) * (rng_.below(2) == 0 ? 1.0 : -1.0);
    const bool rounded = rng_.below(2) == 0;
    const double dz = rng_.below(3) == 0 ? rng_.uniform(-2.0, 2.0) : 0.0;
    const double th0 = rng_.uniform(0, 2 * std::numbers::pi);
    const double cx = pos_[0] - r * std::cos(th0), cy = pos_[1] - r * std::sin(th0);
    const double z0 = pos_[2];
    const int n = std::min(3000, std::max(2, static_cast<int>(std::abs(sweep) * r / chord)));
    const double f = feed();
    for (int i = 1; i <= n; ++i) {
      const double th = th0 + sweep * i / n;
      AxisValues q = xyz(cx + r * std::cos(th), cy + r * std::sin(th), z0 + dz * i / n);
      if (rounded)
        for (int k = 0; k < 3; ++k) q[k] = std::round(q[k] * 1e4) / 1e4;
      if (q == pos_) continue;
      emit(line(pos_, q, f));
    }
  }
  void stopOrDwell() {
    if (prog_.empty()) return;
    if (rng_.below(2) == 0) prog_.back().exact_stop = true;
    else emit(dwell(pos_, rng_.uniform(0.0, 0.05)));
  }

  Random rng_;
  std::vector<MotionPrimitive> prog_;
  AxisValues pos_{};
};

// The suite's checks on one run: every sampled limit (the worst ratios also go into
// `overall`), the program's end point, and every point where the path stops (exact stop,
// dwell) sampled exactly.
void expectLimitsAndExactEnds(const MachineConfig& m, const std::vector<MotionPrimitive>& prog,
                              const Trace& t, uint64_t seed, Worst& overall) {
  const Worst w = check(m, t);
  EXPECT_LE(w.velocity, 1.0 + kTolerance) << "seed " << seed;
  EXPECT_LE(w.acceleration, 1.0 + kTolerance) << "seed " << seed;
  EXPECT_LE(w.jerk, 1.0 + kTolerance) << "seed " << seed;
  overall.velocity = std::max(overall.velocity, w.velocity);
  overall.acceleration = std::max(overall.acceleration, w.acceleration);
  overall.jerk = std::max(overall.jerk, w.jerk);
  EXPECT_EQ(t.points.back(), prog.back().to) << "seed " << seed;
  for (std::size_t i = 0; i < prog.size(); ++i) {
    const bool stops = prog[i].exact_stop || (i + 1 < prog.size() && prog[i + 1].kind == Kind::Dwell);
    if (!stops) continue;
    EXPECT_NE(std::find(t.points.begin(), t.points.end(), prog[i].to), t.points.end())
        << "seed " << seed << " primitive " << i;
  }
}

// A run with the operator at the controls (`knob` before each tick, `setup` once): the same
// setpoints with and without planning ahead, and the suite's checks. Returns the trace.
Trace runOperated(const MachineConfig& m, const std::vector<MotionPrimitive>& prog,
                  std::size_t window, const PlannerHook& knob,
                  const std::function<void(vm::motion::MotionPlanner&)>& setup, uint64_t seed,
                  Worst& overall) {
  const Trace t = run(m, prog, window, 50'000'000, false, knob, setup);
  const Trace ahead = run(m, prog, window, 50'000'000, true, knob, setup);
  EXPECT_GT(t.ticks(), 0u);
  EXPECT_EQ(fnv1a(t, 3), fnv1a(ahead, 3)) << "seed " << seed;
  expectLimitsAndExactEnds(m, prog, t, seed, overall);
  return t;
}

TEST(RandomSuite, NoLimitViolationsAndExactEnds) {
  const MachineConfig m = testMachine();
  Worst overall;
  uint64_t total_ticks = 0;
  for (uint64_t seed = 1; seed <= 24; ++seed) {
    Generator gen(seed);
    const std::vector<MotionPrimitive> prog = gen.program(40);
    const Trace t = run(m, prog);
    ASSERT_GT(t.ticks(), 0u);
    total_ticks += t.ticks();
    expectLimitsAndExactEnds(m, prog, t, seed, overall);
  }
  std::printf("random suite: %llu ticks; worst ratio to axis limit: v %.9f a %.9f j %.9f\n",
              static_cast<unsigned long long>(total_ticks), overall.velocity,
              overall.acceleration, overall.jerk);
}

// The look-ahead reads as far as the plan needs (LookAhead::wantsMore, planner.md "Window by
// braking distance"): each program runs as if the whole of it had been queued before the
// first tick, up to rounding (pieces of an open run end at other points).
TEST(RandomSuite, TheWindowReadsAsFarAsThePlanNeeds) {
  const MachineConfig m = testMachine();
  for (uint64_t seed = 1; seed <= 24; ++seed) {
    Generator gen(seed);
    const std::vector<MotionPrimitive> prog = gen.program(40);
    const Trace windowed = run(m, prog, 1 << 14);
    const Trace whole = runWholeQueued(m, prog);
    ASSERT_EQ(windowed.ticks(), whole.ticks()) << seed;
    double worst = 0.0;
    for (uint64_t k = 0; k < whole.ticks(); ++k)
      for (int i = 0; i < 3; ++i)
        worst = std::max(worst, std::abs(windowed.points[k][i] - whole.points[k][i]));
    EXPECT_LT(worst, 1e-12) << seed;
  }
}

TEST(RandomSuite, DeterministicHash) {
  const MachineConfig m = testMachine();
  Generator gen(7);
  const std::vector<MotionPrimitive> prog = gen.program(30);
  const Trace a = run(m, prog);
  const Trace b = run(m, prog);
  const uint64_t h = fnv1a(a, 3);
  EXPECT_EQ(h, fnv1a(b, 3));
  std::printf("determinism: %llu ticks, FNV-1a 0x%016llx\n",
              static_cast<unsigned long long>(a.ticks()), static_cast<unsigned long long>(h));
  // Pinned: changes only when the planner's arithmetic changes on purpose (update it then).
  EXPECT_EQ(h, 0xe21a6a4717ce9d38ULL);
}

// The operator turns the feed override knob during the run (MotionPlanner::setFeedOverride):
// at seeded random ticks (every 15 or every 120 ticks on average), to random values from 5 %
// up to the maximum the run was planned for (100 %, or 200 % on odd seeds), with a full or a
// 48-segment look-ahead. Every sampled limit still holds, every stop still lands on
// its point, planning ahead still changes no setpoint, and the knob really acts (the program
// time changes).
TEST(RandomSuite, LiveFeedOverrideKeepsEveryLimit) {
  const MachineConfig m = testMachine();
  Worst overall;
  int slower = 0;
  constexpr uint64_t kSeeds = 16;
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    Generator gen(seed);
    const std::vector<MotionPrimitive> prog = gen.program(30);
    const double top = seed % 2 == 1 ? 2.0 : 1.0;
    const int every = seed % 3 == 0 ? 15 : 120;
    const std::size_t window = seed % 4 == 0 ? 48 : 1024;
    auto knob = [seed, top, every](uint64_t k, vm::motion::MotionPlanner& planner) {
      // The same turns for the same tick whatever ran before: a hash of (seed, k).
      Random r(seed * 1000003 + k);
      if (r.below(every) == 0) planner.setFeedOverride(r.uniform(0.05, top));
    };
    auto setup = [top](vm::motion::MotionPlanner& planner) { planner.setOverrides(1.0, 1.0, top); };
    const Trace t = runOperated(m, prog, window, knob, setup, seed, overall);
    if (t.ticks() > run(m, prog, window).ticks()) ++slower;
  }
  // Turned mostly below 100 % (and planned for 200 % on odd seeds): most runs take longer.
  EXPECT_GE(slower, static_cast<int>(kSeeds) / 2);
  std::printf("live feed override: worst ratio to axis limit: v %.9f a %.9f j %.9f; %d of %llu "
              "runs slower\n",
              overall.velocity, overall.acceleration, overall.jerk, slower,
              static_cast<unsigned long long>(kSeeds));
}

// The operator turns the rapid override at seeded random ticks (from a start of 100 % or
// 25 %): every sampled limit holds, every stop lands, planning ahead changes no setpoint.
TEST(RandomSuite, LiveRapidOverrideKeepsEveryLimit) {
  const MachineConfig m = testMachine();
  Worst overall;
  int changed = 0;
  constexpr uint64_t kSeeds = 12;
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    Generator gen(200 + seed);
    const std::vector<MotionPrimitive> prog = gen.program(30);
    const int every = seed % 3 == 0 ? 15 : 120;
    const std::size_t window = seed % 4 == 0 ? 48 : 1024;
    auto knob = [seed, every](uint64_t k, vm::motion::MotionPlanner& planner) {
      Random r(seed * 1000003 + k);
      if (r.below(every) == 0) planner.setRapidOverride(r.uniform(0.05, 1.0));
    };
    const double start = seed % 2 == 0 ? 0.25 : 1.0;
    auto setup = [start](vm::motion::MotionPlanner& planner) { planner.setOverrides(1.0, start); };
    const Trace t = runOperated(m, prog, window, knob, setup, seed, overall);
    if (t.ticks() != run(m, prog, window).ticks()) ++changed;
  }
  // Most programs have rapids: the knob changes their time.
  EXPECT_GE(changed, static_cast<int>(kSeeds) / 2);
  std::printf("live rapid override: worst ratio to axis limit: v %.9f a %.9f j %.9f; %d of %llu "
              "runs changed\n",
              overall.velocity, overall.acceleration, overall.jerk, changed,
              static_cast<unsigned long long>(kSeeds));
}

// The operator presses and releases feed hold at seeded random ticks (and turns the feed
// override): the path brakes to rest on its path and goes on, every sampled limit holds, every
// stop lands, planning ahead changes no setpoint, and the program ends where it should. (While
// developing, 200 seeds; the first version stood on the last sample before a brake's end
// instead of on its end, a jump the release turned into 1.2x the jerk limit.)
TEST(RandomSuite, FeedHoldKeepsEveryLimit) {
  const MachineConfig m = testMachine();
  Worst overall;
  uint64_t held_ticks = 0;
  constexpr uint64_t kSeeds = 12;
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    Generator gen(100 + seed);
    const std::vector<MotionPrimitive> prog = gen.program(30);
    const int every = seed % 3 == 0 ? 20 : 150;
    const std::size_t window = seed % 4 == 0 ? 48 : 1024;
    auto knob = [seed, every](uint64_t k, vm::motion::MotionPlanner& planner) {
      Random r(seed * 7919 + k);
      const int roll = r.below(every);
      if (roll == 0) planner.setFeedHold(!planner.feedHold());
      if (roll == 1) planner.setFeedOverride(r.uniform(0.05, 1.0));
      if (k > 4'000'000) planner.setFeedHold(false);  // never held for good
    };
    const Trace t = runOperated(m, prog, window, knob, {}, seed, overall);
    for (std::size_t k = 1; k < t.ticks(); ++k)
      if (t.points[k] == t.points[k - 1] && t.infos[k].idle) ++held_ticks;
  }
  EXPECT_GT(held_ticks, 10000u);  // the holds really stopped the path
  std::printf("feed hold: worst ratio to axis limit: v %.9f a %.9f j %.9f; %llu ticks standing\n",
              overall.velocity, overall.acceleration, overall.jerk,
              static_cast<unsigned long long>(held_ticks));
}

// MotionPlanner::planAhead (the next piece planned in the preparation, outside the tick) is a
// pure precomputation: the setpoints are bit-identical with and without it.
TEST(RandomSuite, PlanningAheadChangesNoSetpoint) {
  const MachineConfig m = testMachine();
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    Generator gen(seed);
    const std::vector<MotionPrimitive> prog = gen.program(40);
    const Trace plain = run(m, prog);
    const Trace ahead = run(m, prog, 1024, 50'000'000, true);
    ASSERT_EQ(plain.ticks(), ahead.ticks()) << "seed " << seed;
    EXPECT_EQ(fnv1a(plain, 3), fnv1a(ahead, 3)) << "seed " << seed;
  }
}

}  // namespace
}  // namespace ncc::motion_test
