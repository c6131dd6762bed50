// Non-linear (per-axis) G00: every axis runs its own rest-to-rest S-curve (axis_rapid.h).
// Closed-form durations, exact ends, finite-difference limits on 1 ms samples, the dog-leg
// shape, monotone axes, standing axes, very short moves, rotary axes, determinism, no
// allocation.
#include "ncc/vm/motion/axis_rapid.h"

#include <algorithm>
#include <cmath>
#include <vector>
#include <cstring>

#include "allocation_counter.h"
#include "gtest/gtest.h"
#include "motion_test_util.h"

namespace ncc::vm::motion {
namespace {

using motion_test::kTolerance;
using motion_test::restToRestTime;
using motion_test::Worst;
using motion_test::xyz;

// Equal limits on three axes: 500 mm/s rapid, 2000 mm/s^2, 50000 mm/s^3 (a per-axis rapid
// runs from rest to rest and uses nearly all of it, kBetweenStopsJerkShare: a^2/j = 80 mm/s,
// below the rapid speed).
AxisLimits equalLimits(int count = 3) {
  AxisLimits l;
  l.count = count;
  for (int i = 0; i < count; ++i) {
    l.feed_velocity[i] = 200.0;
    l.rapid_velocity[i] = 500.0;
    l.acceleration[i] = 2000.0;
    l.jerk[i] = 50000.0;
  }
  return l;
}

// Different limits per axis, including a slow rotary A (deg) whose rapid speed is below
// a^2/j (a_max never reached at full speed).
AxisLimits mixedLimits() {
  AxisLimits l = equalLimits(4);
  l.rapid_velocity[1] = 20000.0 / 60.0;
  l.acceleration[1] = 3000.0;
  l.jerk[1] = 80000.0;
  l.rapid_velocity[2] = 200.0;
  l.acceleration[2] = 1500.0;
  l.jerk[2] = 30000.0;
  l.rapid_velocity[3] = 50.0;   // deg/s
  l.acceleration[3] = 1000.0;   // deg/s^2
  l.jerk[3] = 10000.0;          // deg/s^3 (a^2/j = 100 deg/s > 50)
  return l;
}

AxisValues axes4(double x, double y, double z, double a) {
  AxisValues v = xyz(x, y, z);
  v[3] = a;
  return v;
}

double expectedAxisTime(const AxisLimits& l, int i, double travel) {
  return restToRestTime(std::abs(travel), l.rapid_velocity[i], l.acceleration[i],
                        kBetweenStopsJerkShare * l.jerk[i]);
}

TEST(AxisRapid, DurationIsTheSlowestAxisClosedForm) {
  const AxisLimits l = equalLimits();
  // X 100: a reached, v not; Y 300: v and a reached; Z 1: neither.
  const AxisValues from = xyz(0, 0, 0), to = xyz(100, -300, 1);
  const AxisRapid r = AxisRapid::make(from, to, l);
  ASSERT_TRUE(r.valid());
  const double a = 2000.0, j = kBetweenStopsJerkShare * 50000.0, v = 500.0;
  // The closed forms written out per regime, not only through restToRestTime.
  const double tx = a / j + std::sqrt((a / j) * (a / j) + 4.0 * 100.0 / a);  // a, not v
  const double ty = 300.0 / v + v / a + a / j;                               // v and a
  const double tz = 4.0 * std::cbrt(1.0 / (2.0 * j));                        // neither
  EXPECT_NEAR(r.axisDuration(0), tx, 1e-12 * tx);
  EXPECT_NEAR(r.axisDuration(1), ty, 1e-12 * ty);
  EXPECT_NEAR(r.axisDuration(2), tz, 1e-12 * tz);
  EXPECT_NEAR(tx, restToRestTime(100.0, v, a, j), 1e-12 * tx);
  EXPECT_NEAR(ty, restToRestTime(300.0, v, a, j), 1e-12 * ty);
  EXPECT_NEAR(tz, restToRestTime(1.0, v, a, j), 1e-12 * tz);
  EXPECT_EQ(r.duration(), std::max({r.axisDuration(0), r.axisDuration(1), r.axisDuration(2)}));
  EXPECT_NEAR(r.duration(), ty, 1e-12 * ty);
}

TEST(AxisRapid, FourthRegimeAndPerAxisLimits) {
  const AxisLimits l = mixedLimits();
  // A 90 deg at 50 deg/s: v reached, a not (v < a^2/j).
  const AxisValues from = axes4(10, 20, 30, 0), to = axes4(-40, 25, 31, 90);
  const AxisRapid r = AxisRapid::make(from, to, l);
  ASSERT_TRUE(r.valid());
  const double ja = kBetweenStopsJerkShare * 10000.0;
  const double ta = 90.0 / 50.0 + 2.0 * std::sqrt(50.0 / ja);  // v reached, a not
  EXPECT_NEAR(r.axisDuration(3), ta, 1e-12 * ta);
  double slowest = 0.0;
  for (int i = 0; i < 4; ++i) {
    const double expected = expectedAxisTime(l, i, to[i] - from[i]);
    EXPECT_NEAR(r.axisDuration(i), expected, 1e-12 * expected) << "axis " << i;
    slowest = std::max(slowest, expected);
  }
  EXPECT_NEAR(r.duration(), slowest, 1e-12 * slowest);
  EXPECT_EQ(r.duration(), r.axisDuration(3));
}

TEST(AxisRapid, ExactEndsAtStartAndArrival) {
  const AxisLimits l = mixedLimits();
  // Values that are not exactly representable, so from + (to - from) != to in general.
  const AxisValues from = axes4(0.1, -7.3, 123.456789, 359.9);
  const AxisValues to = axes4(-0.7, 41.17, 123.456788, 0.3);
  const AxisRapid r = AxisRapid::make(from, to, l);
  ASSERT_TRUE(r.valid());
  AxisValues p;
  r.position(0.0, p);
  EXPECT_EQ(p, from);
  r.position(-1.0, p);
  EXPECT_EQ(p, from);
  r.position(r.duration(), p);
  EXPECT_EQ(p, to);
  r.position(r.duration() + 1.0, p);
  EXPECT_EQ(p, to);
  r.position(1e300, p);
  EXPECT_EQ(p, to);
  // Each axis is at its end bit-exactly from its own arrival on.
  for (int i = 0; i < 4; ++i) {
    r.position(r.axisDuration(i), p);
    EXPECT_EQ(p[i], to[i]) << "axis " << i;
    r.position(std::nextafter(r.axisDuration(i), 0.0), p);
    EXPECT_NEAR(p[i], to[i], 1e-12) << "axis " << i;  // continuous into the arrival
  }
  AxisValues v;
  r.velocity(r.duration(), v);
  EXPECT_EQ(v, AxisValues{});
  r.velocity(0.0, v);
  EXPECT_EQ(v, AxisValues{});
  EXPECT_EQ(r.pathSpeed(r.duration()), 0.0);
  EXPECT_EQ(r.pathSpeed(0.0), 0.0);
}

// Samples t = k T - phase (clamped by the rapid: before the start at `from`, after the end at
// `to`, so the standstill on both sides is part of the check) and takes finite differences
// per axis, as random_suite_test.cpp does with the planner's setpoints (less their rounding,
// motion_test::SetpointRounding).
Worst check(const AxisRapid& r, const AxisLimits& l, double phase) {
  const double T = l.ipo_cycle;
  const int n = static_cast<int>(std::ceil(r.duration() / T)) + 6;
  Worst w;
  double largest = 0.0;
  for (int i = 0; i < l.count; ++i)
    largest = std::max({largest, std::abs(r.from()[i]), std::abs(r.to()[i])});
  const motion_test::SetpointRounding rounding(largest, T);
  AxisValues p[4];
  for (int k = 0; k < n; ++k) {
    AxisValues& cur = p[k % 4];
    r.position((k - 2) * T - phase, cur);
    const AxisValues& p1 = p[(k + 3) % 4];
    const AxisValues& p2 = p[(k + 2) % 4];
    const AxisValues& p3 = p[(k + 1) % 4];
    for (int i = 0; i < l.count; ++i) {
      if (k >= 1) {
        const double v = (cur[i] - p1[i]) / T;
        w.velocity = std::max(w.velocity, std::abs(v) / l.rapid_velocity[i]);
      }
      if (k >= 2) {
        const double a = (cur[i] - 2 * p1[i] + p2[i]) / (T * T);
        w.acceleration = std::max(w.acceleration, rounding.acceleration(a) / l.acceleration[i]);
      }
      if (k >= 3) {
        const double j = (cur[i] - 3 * p1[i] + 3 * p2[i] - p3[i]) / (T * T * T);
        w.jerk = std::max(w.jerk, rounding.jerk(j) / l.jerk[i]);
      }
    }
  }
  return w;
}

TEST(AxisRapid, SampledAxisLimitsHold) {
  const AxisLimits limits[] = {equalLimits(), mixedLimits()};
  motion_test::Random rng(42);
  Worst overall;
  int moves = 0;
  for (const AxisLimits& l : limits) {
    for (int m = 0; m < 60; ++m) {
      AxisValues from{}, to{};
      for (int i = 0; i < l.count; ++i) {
        // Mix long, short and tiny travels (and an occasional standing axis).
        const int kind = rng.below(5);
        const double scale = kind == 0 ? 0.0 : kind == 1 ? 0.01 : kind == 2 ? 1.0 : 400.0;
        const double a = rng.uniform(-200, 200);
        const double d = rng.uniform(-scale, scale);
        from[i] = a;
        to[i] = a + d;
      }
      const AxisRapid r = AxisRapid::make(from, to, l);
      ASSERT_TRUE(r.valid());
      const double phase = rng.uniform(0.0, l.ipo_cycle);
      const Worst w = check(r, l, phase);
      EXPECT_LE(w.velocity, 1.0 + kTolerance) << "move " << moves;
      EXPECT_LE(w.acceleration, 1.0 + kTolerance) << "move " << moves;
      EXPECT_LE(w.jerk, 1.0 + kTolerance) << "move " << moves;
      overall.velocity = std::max(overall.velocity, w.velocity);
      overall.acceleration = std::max(overall.acceleration, w.acceleration);
      overall.jerk = std::max(overall.jerk, w.jerk);
      ++moves;
    }
  }
  std::printf("axis rapid: %d moves; worst ratio to axis limit: v %.9f a %.9f j %.9f\n", moves,
              overall.velocity, overall.acceleration, overall.jerk);
  // The long moves do reach the limits: the check is not vacuous. From rest to rest the jerk
  // too is the axis' whole limit (not the 90 % a move passed moving keeps).
  EXPECT_GT(overall.velocity, 0.99);
  EXPECT_GT(overall.acceleration, 0.99);
  EXPECT_GT(overall.jerk, 0.95);
}

// A live rapid override and feed hold (replan) at random ticks: every sampled axis limit
// holds (against the full rapid speed), no axis leaves the box between `from` and `to`, and
// every axis lands exactly on `to` (once released, or under a hold pressed while it was
// already braking to its end).
TEST(AxisRapid, RandomReplansKeepSampledLimitsAndLand) {
  const AxisLimits limits[] = {equalLimits(), mixedLimits()};
  motion_test::Random rng(7);
  Worst overall;
  int replans = 0, holds = 0;
  for (const AxisLimits& l : limits) {
    const double T = l.ipo_cycle;
    for (int m = 0; m < 60; ++m) {
      AxisValues from{}, to{};
      for (int i = 0; i < l.count; ++i) {
        const double scale = rng.below(4) == 0 ? 1.0 : 400.0;
        from[i] = rng.uniform(-200, 200);
        to[i] = from[i] + rng.uniform(-scale, scale);
      }
      AxisRapid r = AxisRapid::make(from, to, l);
      ASSERT_TRUE(r.valid());
      const double phase = rng.uniform(0.0, T);
      const int every = m % 2 == 0 ? 20 : 150;
      bool held = false;
      std::vector<AxisValues> samples;
      for (int k = 0; k < 200000; ++k) {
        const double t = (k - 2) * T - phase;
        AxisValues p;
        r.position(t, p);
        samples.push_back(p);
        if (t > r.duration() + 3 * T) break;
        if (t > 0.0 && rng.below(every) == 0) {
          AxisLimits turned = l;
          const double knob = rng.uniform(0.05, 1.0);
          for (int i = 0; i < l.count; ++i) turned.rapid_velocity[i] *= knob;
          held = !held && rng.below(3) == 0;
          holds += held ? 1 : 0;
          r.replan(t + T, turned, held);
          ++replans;
        }
        // A hold never lasts: released within 300 ticks.
        if (held && rng.below(300) == 0) {
          r.replan(t + T, l, false);
          held = false;
        }
      }
      ASSERT_EQ(samples.back(), to) << "move " << m;
      for (std::size_t k = 0; k < samples.size(); ++k) {
        for (int i = 0; i < l.count; ++i) {
          EXPECT_GE(samples[k][i], std::min(from[i], to[i])) << m;
          EXPECT_LE(samples[k][i], std::max(from[i], to[i])) << m;
          if (k >= 1)
            overall.velocity = std::max(overall.velocity,
                std::abs(samples[k][i] - samples[k - 1][i]) / T / l.rapid_velocity[i]);
          if (k >= 2)
            overall.acceleration = std::max(overall.acceleration,
                std::abs(samples[k][i] - 2 * samples[k - 1][i] + samples[k - 2][i]) / (T * T) /
                    l.acceleration[i]);
          if (k >= 3)
            overall.jerk = std::max(overall.jerk,
                std::abs(samples[k][i] - 3 * samples[k - 1][i] + 3 * samples[k - 2][i] -
                         samples[k - 3][i]) / (T * T * T) / l.jerk[i]);
        }
      }
    }
  }
  std::printf("axis rapid replans: %d (%d holds); worst ratio to axis limit: v %.9f a %.9f j %.9f\n",
              replans, holds, overall.velocity, overall.acceleration, overall.jerk);
  EXPECT_GT(holds, 20);
  EXPECT_LE(overall.velocity, 1.0 + kTolerance);
  EXPECT_LE(overall.acceleration, 1.0 + kTolerance);
  EXPECT_LE(overall.jerk, 1.0 + kTolerance);
}

TEST(AxisRapid, DogLegYFinishesFirstXContinuesAlone) {
  const AxisLimits l = equalLimits();
  const AxisValues from = xyz(0, 0, 0), to = xyz(100, 10, 0);
  const AxisRapid r = AxisRapid::make(from, to, l);
  const double tx = r.axisDuration(0), ty = r.axisDuration(1);
  ASSERT_LT(ty, tx);
  EXPECT_EQ(r.duration(), tx);
  EXPECT_EQ(r.axisDuration(2), 0.0);
  const double mid = 0.5 * (tx + ty);
  AxisValues p, v;
  r.position(mid, p);
  r.velocity(mid, v);
  EXPECT_EQ(p[1], 10.0);  // Y is at its end
  EXPECT_GT(p[0], 0.0);
  EXPECT_LT(p[0], 100.0);  // X is not
  EXPECT_EQ(v[1], 0.0);
  EXPECT_GT(v[0], 0.0);
  EXPECT_EQ(p[2], 0.0);
  EXPECT_NEAR(r.pathSpeed(mid), v[0], 1e-12 * v[0]);
  // Not the straight line: while Y still accelerates (its first half), both axes run the
  // same ramp (equal limits), so the point is on the diagonal, far off the line y = x / 10.
  const double early = 0.25 * ty;
  ASSERT_LT(early, r.axisProfile(1).accel.duration);
  r.position(early, p);
  EXPECT_EQ(p[0], p[1]);
  EXPECT_GT(p[1], 0.1);
  EXPECT_GT(p[1] - p[0] / 10.0, 0.5 * p[1]);
}

TEST(AxisRapid, MonotonePerAxisNoOvershoot) {
  const AxisLimits l = mixedLimits();
  const AxisValues from = axes4(5, 5, 5, 5), to = axes4(-300, 0.002, 5 - 1e-7, 725);
  const AxisRapid r = AxisRapid::make(from, to, l);
  const int n = 200000;
  AxisValues prev = from, p;
  for (int k = 0; k <= n + 10; ++k) {
    r.position(r.duration() * k / n, p);
    for (int i = 0; i < 4; ++i) {
      const double sg = to[i] > from[i] ? 1.0 : -1.0;
      EXPECT_GE(sg * (p[i] - prev[i]), 0.0) << "axis " << i << " k " << k;
      EXPECT_GE(p[i], std::min(from[i], to[i]));
      EXPECT_LE(p[i], std::max(from[i], to[i]));
      if (sg * (p[i] - prev[i]) < 0.0 || p[i] < std::min(from[i], to[i]) ||
          p[i] > std::max(from[i], to[i]))
        return;  // one report is enough
    }
    prev = p;
  }
  EXPECT_EQ(p, to);
}

TEST(AxisRapid, StandingAxesDoNotMove) {
  const AxisLimits l = mixedLimits();
  const AxisValues from = axes4(1.5, -2.25, 0.1, 33.3), to = axes4(1.5, 80.0, 0.1, 33.3);
  const AxisRapid r = AxisRapid::make(from, to, l);
  ASSERT_TRUE(r.valid());
  EXPECT_EQ(r.duration(), r.axisDuration(1));
  AxisValues p, v;
  for (int k = 0; k <= 100; ++k) {
    const double t = r.duration() * k / 100;
    r.position(t, p);
    r.velocity(t, v);
    for (int i : {0, 2, 3}) {
      EXPECT_EQ(p[i], from[i]);
      EXPECT_EQ(v[i], 0.0);
    }
  }
  // Nothing moves at all: duration 0, `to` at once.
  const AxisRapid none = AxisRapid::make(from, from, l);
  EXPECT_TRUE(none.valid());
  EXPECT_EQ(none.duration(), 0.0);
  none.position(0.0, p);
  EXPECT_EQ(p, from);
  EXPECT_EQ(none.pathSpeed(0.0), 0.0);
}

TEST(AxisRapid, VeryShortMovesAreTriangular) {
  const AxisLimits l = equalLimits();
  const double j = kBetweenStopsJerkShare * 50000.0;
  for (double d : {1e-3, 1e-6, 1e-9, 1e-12}) {
    const AxisValues from = xyz(7.0, 0, 0), to = xyz(7.0 + d, 0, 0);
    const AxisRapid r = AxisRapid::make(from, to, l);
    ASSERT_TRUE(r.valid());
    const double travel = to[0] - from[0];
    const double expected = 4.0 * std::cbrt(travel / (2.0 * j));  // neither limit reached
    EXPECT_NEAR(r.duration(), expected, 1e-9 * expected) << d;
    AxisValues p;
    r.position(r.duration(), p);
    EXPECT_EQ(p, to);
    r.position(0.5 * r.duration(), p);
    EXPECT_GE(p[0], from[0]);
    EXPECT_LE(p[0], to[0]);
    const Worst w = check(r, l, 0.3 * l.ipo_cycle);
    EXPECT_LE(w.jerk, 1.0 + kTolerance) << d;
  }
}

TEST(AxisRapid, SingleAxisMatchesTheOneDimensionalProfile) {
  const AxisLimits l = equalLimits();
  const AxisValues from = xyz(0, 50, 0), to = xyz(0, -70, 0);
  const AxisRapid r = AxisRapid::make(from, to, l);
  const SCurveProfile p = planProfile(120.0, 0, 0, 500.0, 2000.0, kBetweenStopsJerkShare * 50000.0);
  EXPECT_EQ(r.duration(), p.duration);
  AxisValues v, a;
  for (int k = 1; k < 100; ++k) {
    const double t = p.duration * k / 100;
    const PathState s = p.at(t);
    const PathState ax = r.axisState(1, t);
    EXPECT_EQ(ax.s, -s.s);
    EXPECT_EQ(ax.v, -s.v);
    EXPECT_EQ(ax.a, -s.a);
    EXPECT_EQ(ax.j, -s.j);
    r.velocity(t, v);
    r.acceleration(t, a);
    EXPECT_EQ(v[1], -s.v);
    EXPECT_EQ(a[1], -s.a);
    const AxisRapidMotion m = r.pathMotion(t);
    EXPECT_NEAR(m.velocity, s.v, 1e-12 * 500.0);
    EXPECT_NEAR(m.acceleration, s.a, 1e-9 * 2000.0);
    EXPECT_NEAR(m.jerk, s.j, 1e-9 * 50000.0);
  }
}

TEST(AxisRapid, PathSpeedIsTheNormOfTheAxisVelocities) {
  const AxisLimits l = mixedLimits();
  const AxisRapid r = AxisRapid::make(axes4(0, 0, 0, 0), axes4(120, -40, 15, 200), l);
  AxisValues v, a;
  for (int k = 1; k < 200; ++k) {
    const double t = r.duration() * k / 200;
    r.velocity(t, v);
    r.acceleration(t, a);
    double vv = 0, va = 0;
    for (int i = 0; i < 4; ++i) {
      vv += v[i] * v[i];
      va += v[i] * a[i];
    }
    const AxisRapidMotion m = r.pathMotion(t);
    EXPECT_NEAR(m.velocity, std::sqrt(vv), 1e-12 * (1.0 + m.velocity));
    EXPECT_NEAR(m.acceleration, va / std::sqrt(vv), 1e-9 * (1.0 + std::abs(m.acceleration)));
    // d|v|/dt against a central difference of the speed.
    const double h = 1e-6;
    const double diff = (r.pathSpeed(t + h) - r.pathSpeed(t - h)) / (2 * h);
    EXPECT_NEAR(m.acceleration, diff, 1e-3 * 2000.0) << "t " << t;
  }
}

TEST(AxisRapid, InvalidLimitsGiveNoMotion) {
  AxisLimits l = equalLimits();
  l.jerk[1] = 0.0;
  const AxisValues from = xyz(0, 0, 0), to = xyz(10, 10, 0);
  const AxisRapid r = AxisRapid::make(from, to, l);
  EXPECT_FALSE(r.valid());
  EXPECT_EQ(r.duration(), 0.0);
  // A zero limit on an axis that does not move is fine.
  EXPECT_TRUE(AxisRapid::make(from, xyz(10, 0, 0), l).valid());
  AxisValues bad = to;
  bad[0] = NAN;
  EXPECT_FALSE(AxisRapid::make(from, bad, equalLimits()).valid());
  // possible() (the planner's check) says the same without planning.
  EXPECT_FALSE(AxisRapid::possible(from, to, l));
  EXPECT_TRUE(AxisRapid::possible(from, xyz(10, 0, 0), l));
  EXPECT_FALSE(AxisRapid::possible(from, bad, equalLimits()));
  EXPECT_TRUE(AxisRapid::possible(from, to, equalLimits()));
}

TEST(AxisRapid, DeterministicAndAllocationFree) {
  const AxisLimits l = mixedLimits();
  const AxisValues from = axes4(1, 2, 3, 4), to = axes4(-97.5, 33.25, -12.125, 181);
  const long before = test::allocationCount();
  const AxisRapid a = AxisRapid::make(from, to, l);
  const AxisRapid b = AxisRapid::make(from, to, l);
  uint64_t h = 0xcbf29ce484222325ULL;
  AxisValues pa, pb;
  const int n = static_cast<int>(a.duration() / l.ipo_cycle) + 2;
  bool same = true;
  for (int k = 0; k < n; ++k) {
    a.position(k * l.ipo_cycle, pa);
    b.position(k * l.ipo_cycle, pb);
    same = same && std::memcmp(pa.data(), pb.data(), sizeof(double) * 4) == 0;
    unsigned char bytes[sizeof(double) * 4];
    std::memcpy(bytes, pa.data(), sizeof bytes);
    for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ULL;
    (void)a.pathMotion(k * l.ipo_cycle);
  }
  EXPECT_EQ(test::allocationCount() - before, 0);
  EXPECT_TRUE(same);
  EXPECT_EQ(a.duration(), b.duration());
  std::printf("axis rapid determinism: %d ticks, FNV-1a 0x%016llx\n", n,
              static_cast<unsigned long long>(h));
}

}  // namespace
}  // namespace ncc::vm::motion
