#pragma once
// Shared helpers for the motion tests: primitive builders, a caller loop that feeds a
// MotionPlanner like the VM does, a portable seeded random source.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <numbers>
#include <vector>

#include "gtest/gtest.h"
#include "ncc/machine/machine_config.h"
#include "ncc/vm/events.h"
#include "ncc/vm/motion/planner.h"

namespace ncc::motion_test {

using vm::MotionPrimitive;
using Kind = MotionPrimitive::Kind;

inline AxisValues xyz(double x, double y, double z) {
  AxisValues v{};
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

inline MotionPrimitive line(const AxisValues& from, const AxisValues& to, double feed,
                            bool exact_stop = false) {
  MotionPrimitive m;
  m.kind = Kind::Line;
  m.from = from;
  m.to = to;
  m.feed = feed;
  m.exact_stop = exact_stop;
  return m;
}

inline MotionPrimitive rapid(const AxisValues& from, const AxisValues& to) {
  MotionPrimitive m;
  m.kind = Kind::Rapid;
  m.from = from;
  m.to = to;
  return m;
}

// Arc in the plane (a1, a2) around (c1, c2).
inline MotionPrimitive arc(const AxisValues& from, const AxisValues& to, int a1, int a2,
                           double c1, double c2, bool cw, double feed, uint32_t turns = 0) {
  MotionPrimitive m;
  m.kind = Kind::Arc;
  m.from = from;
  m.to = to;
  m.axis1 = static_cast<uint8_t>(a1);
  m.axis2 = static_cast<uint8_t>(a2);
  m.center[a1] = c1;
  m.center[a2] = c2;
  m.cw = cw;
  m.feed = feed;
  m.extra_turns = turns;
  return m;
}

inline MotionPrimitive dwell(const AxisValues& at, double seconds) {
  MotionPrimitive m;
  m.kind = Kind::Dwell;
  m.from = at;
  m.to = at;
  m.seconds = seconds;
  return m;
}

struct Trace {
  std::vector<AxisValues> points;
  std::vector<vm::motion::SetpointInfo> infos;
  uint64_t ticks() const { return points.size(); }
};

// Runs `program` through a planner the way the VM loop does: before each tick, push while the
// planner wants more (and, with `plan_ahead`, let it plan the next piece, as
// vm::Controller::prepare does). `max_ticks` guards against a hang. `before_tick(k, planner)`,
// when given, runs before tick k's setpoint (an operator turning the feed override knob);
// `setup(planner)` once before the first push. `pushes(k)`, when given, says whether the
// caller pushes before tick k at all (false: a preparation that has fallen behind).
using PlannerHook = std::function<void(uint64_t, vm::motion::MotionPlanner&)>;
inline Trace run(const MachineConfig& machine, const std::vector<MotionPrimitive>& program,
                 std::size_t capacity = 1024, uint64_t max_ticks = 50'000'000,
                 bool plan_ahead = false, const PlannerHook& before_tick = {},
                 const std::function<void(vm::motion::MotionPlanner&)>& setup = {},
                 const std::function<bool(uint64_t)>& pushes = {}) {
  vm::motion::MotionPlanner planner(machine, capacity);
  if (setup) setup(planner);
  Trace trace;
  std::size_t next = 0;
  AxisValues p{};
  vm::motion::SetpointInfo info;
  for (uint64_t k = 0; k < max_ticks; ++k) {
    const bool pushing = !pushes || pushes(k);
    while (pushing && next < program.size() && planner.canAccept()) planner.push(program[next++]);
    if (next == program.size()) planner.endOfProgram();
    if (before_tick) before_tick(k, planner);
    if (plan_ahead) planner.planAhead();
    if (!planner.setpoint(k, p, info)) break;
    trace.points.push_back(p);
    trace.infos.push_back(info);
  }
  return trace;
}

// The same run with the whole program queued before the first tick (no look-ahead window):
// what the plan is with everything known.
inline Trace runWholeQueued(const MachineConfig& machine,
                            const std::vector<MotionPrimitive>& program) {
  return run(
      machine, program, 1 << 14, 50'000'000, false, {},
      [&](vm::motion::MotionPlanner& planner) {
        for (const MotionPrimitive& m : program) ASSERT_TRUE(planner.push(m));
        planner.endOfProgram();
      },
      [](uint64_t) { return false; });
}

// splitmix64: the same sequence on every platform (std distributions are not portable).
class Random {
 public:
  explicit Random(uint64_t seed) : state_(seed) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(next() >> 11) * 0x1.0p-53);
  }
  int below(int n) { return static_cast<int>(next() % static_cast<uint64_t>(n)); }

 private:
  uint64_t state_;
};

inline uint64_t fnv1a(const Trace& trace, int axes) {
  uint64_t h = 0xcbf29ce484222325ULL;
  for (const AxisValues& p : trace.points) {
    unsigned char bytes[sizeof(double) * kMaxAxes];
    std::memcpy(bytes, p.data(), sizeof(double) * static_cast<std::size_t>(axes));
    for (std::size_t i = 0; i < sizeof(double) * static_cast<std::size_t>(axes); ++i) {
      h ^= bytes[i];
      h *= 0x100000001b3ULL;
    }
  }
  return h;
}

struct Worst {
  double velocity = 0, acceleration = 0, jerk = 0;  // largest ratio to the axis limit
};

// Rounding of a setpoint: each is the double nearest its exact value, within half a unit in
// the last place (ulp) of the largest coordinate, and a difference of n + 1 setpoints adds
// up to 2^n of those halves. Below that floor a sampled value says nothing (a line at the
// full jerk of an axis of 13 mm/s^3, 20 mm from zero, read 1.0000018x it). It is taken off
// every sampled value before it is compared: 8 ulp / T^3 of jerk, 4 ulp / T^2 of
// acceleration (twice what rounding needs, for the few ulp the position's own arithmetic
// adds; 1e-8 of the default machine's jerk at 1000 mm).
class SetpointRounding {
 public:
  SetpointRounding(double largest_coordinate, double T) {
    const double m = std::abs(largest_coordinate);
    const double ulp = std::nextafter(m, INFINITY) - m;
    acceleration_floor_ = 4.0 * ulp / (T * T);
    jerk_floor_ = 8.0 * ulp / (T * T * T);
  }
  // |sampled| less the floor (0 below it).
  double acceleration(double sampled) const { return std::max(std::abs(sampled) - acceleration_floor_, 0.0); }
  double jerk(double sampled) const { return std::max(std::abs(sampled) - jerk_floor_, 0.0); }

 private:
  double acceleration_floor_ = 0.0, jerk_floor_ = 0.0;
};

// Finite differences of the setpoints against the axis limits, less their rounding. The
// velocity limit is the rapid speed when either tick is on a rapid, else the feed limit.
inline Worst check(const MachineConfig& m, const Trace& t) {
  Worst w;
  const double T = m.ipo_cycle_seconds;
  const auto& p = t.points;
  double largest = 0.0;
  for (const AxisValues& q : p)
    for (int i = 0; i < m.axisCount(); ++i) largest = std::max(largest, std::abs(q[i]));
  const SetpointRounding rounding(largest, T);
  for (std::size_t k = 1; k < p.size(); ++k) {
    const bool rapid = t.infos[k].kind == Kind::Rapid || t.infos[k - 1].kind == Kind::Rapid;
    for (int i = 0; i < m.axisCount(); ++i) {
      const AxisConfig& ax = m.axes[i];
      const double v = (p[k][i] - p[k - 1][i]) / T;
      w.velocity = std::max(w.velocity, std::abs(v) / ((rapid ? ax.rapid_velocity : ax.max_velocity) / 60.0));
      if (k >= 2) {
        const double a = (p[k][i] - 2 * p[k - 1][i] + p[k - 2][i]) / (T * T);
        w.acceleration = std::max(w.acceleration, rounding.acceleration(a) / ax.max_acceleration);
      }
      if (k >= 3) {
        const double j = (p[k][i] - 3 * p[k - 1][i] + 3 * p[k - 2][i] - p[k - 3][i]) / (T * T * T);
        w.jerk = std::max(w.jerk, rounding.jerk(j) / ax.max_jerk);
      }
    }
  }
  return w;
}

// Sets one axis' acceleration (mm/s^2) and jerk (mm/s^3) limits: machines with unequal axes.
inline void setAxisLimits(MachineConfig& m, int axis, double acceleration, double jerk) {
  m.axes[static_cast<std::size_t>(axis)].max_acceleration = acceleration;
  m.axes[static_cast<std::size_t>(axis)].max_jerk = jerk;
}

// The default machine (defaultMachine()) in path units, for closed forms: its IPO cycle, axis
// acceleration, and the path jerk of a line from rest to rest (a program of one line, an
// exact stop: the whole axis jerk) and of a move whose end may be passed moving (a linear
// G00 without exact stop: the smooth share).
inline constexpr double kDefaultT = 0.001;
inline constexpr double kDefaultA = 2000.0;
inline constexpr double kDefaultLineJ = vm::motion::kBetweenStopsJerkShare * 50000.0;
inline constexpr double kDefaultMovingJ = vm::motion::kSmoothJerkShare * 50000.0;

// Path speed along X between ticks k - 1 and k of a trace sampled every kDefaultT.
inline double speedAlongX(const Trace& t, uint64_t k) {
  return (t.points[k][0] - t.points[k - 1][0]) / kDefaultT;
}

// Numerical tolerance of the finite-difference check: positions are exact to ~1e-13 mm,
// which reads as 8e-13 / T^3 = 8e-4 mm/s^3 of jerk; 1e-6 relative covers it with margin.
constexpr double kTolerance = 1e-6;

// Every sampled setpoint within the machine's axis limits (check(), kTolerance).
inline void expectWithinLimits(const MachineConfig& m, const Trace& t) {
  const Worst w = check(m, t);
  EXPECT_LE(w.velocity, 1.0 + kTolerance);
  EXPECT_LE(w.acceleration, 1.0 + kTolerance);
  EXPECT_LE(w.jerk, 1.0 + kTolerance);
}

// Rest-to-rest time over L at path limits v, a, j: the four closed forms of docs/planner.md.
inline double restToRestTime(double L, double v, double a, double j) {
  const double va = a * a / j;  // velocity gained by one full jerk pair
  const double vp_tri = std::cbrt(L * L * j / 4.0);  // peak with neither limit reached
  if (vp_tri <= std::min(v, va)) return 4.0 * std::cbrt(L / (2.0 * j));
  if (v <= va) {  // a_max never reached
    if (L >= 2.0 * v * std::sqrt(v / j)) return L / v + 2.0 * std::sqrt(v / j);
    return 4.0 * std::cbrt(L / (2.0 * j));
  }
  const double t_no_cruise = a / j + std::sqrt((a / j) * (a / j) + 4.0 * L / a);
  const double vp = a * (t_no_cruise / 2.0 - a / j);
  if (vp <= v) return t_no_cruise;  // a_max reached, v_max not
  return L / v + v / a + a / j;      // both reached
}

// Euclidean distance over X Y Z.
inline double distance(const AxisValues& a, const AxisValues& b) {
  double s = 0.0;
  for (int i = 0; i < 3; ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}

// Distance from p to the segment [a, b] over X Y Z.
inline double toSegment(const AxisValues& p, const AxisValues& a, const AxisValues& b) {
  double ab2 = 0.0, ap_ab = 0.0;
  for (int i = 0; i < 3; ++i) {
    ab2 += (b[i] - a[i]) * (b[i] - a[i]);
    ap_ab += (p[i] - a[i]) * (b[i] - a[i]);
  }
  const double f = ab2 > 0.0 ? std::clamp(ap_ab / ab2, 0.0, 1.0) : 0.0;
  AxisValues q{};
  for (int i = 0; i < 3; ++i) q[i] = a[i] + f * (b[i] - a[i]);
  return distance(p, q);
}

// Distance from p to a helix around (cx, cy) in the XY plane (radius r, from angle a0 through
// `sweep`, Z linear in the angle), by brute force: the nearest of 128 points along it, then a
// golden-section search around it. Any point of the helix is at least as far as the nearest,
// so this never under-estimates the distance.
inline double toHelix(const AxisValues& p, const MotionPrimitive& m, double cx, double cy,
                      double r, double a0, double sweep) {
  auto at = [&](double f) {
    const double a = a0 + sweep * f;
    AxisValues q = m.from;
    q[0] = cx + r * std::cos(a);
    q[1] = cy + r * std::sin(a);
    q[2] = m.from[2] + (m.to[2] - m.from[2]) * f;
    return distance(p, q);
  };
  constexpr int kSamples = 128;
  int best = 0;
  double nearest = at(0.0);
  for (int k = 1; k <= kSamples; ++k) {
    const double d = at(static_cast<double>(k) / kSamples);
    if (d < nearest) nearest = d, best = k;
  }
  double lo = std::max(0, best - 1) / static_cast<double>(kSamples);
  double hi = std::min(kSamples, best + 1) / static_cast<double>(kSamples);
  for (int i = 0; i < 80; ++i) {
    const double m1 = lo + (hi - lo) * 0.381966, m2 = hi - (hi - lo) * 0.381966;
    if (at(m1) < at(m2)) hi = m2; else lo = m1;
  }
  return std::min(nearest, at(0.5 * (lo + hi)));
}

// Distance from p to a programmed primitive, worked out here without PathSegment (what the
// tests check the planner against): a line, or an arc in the X, Y plane of less than a full
// turn (a helix when Z changes).
inline double toPrimitive(const AxisValues& p, const MotionPrimitive& m) {
  if (m.kind != Kind::Arc) return toSegment(p, m.from, m.to);
  const double cx = m.center[0], cy = m.center[1];
  const double r = std::hypot(m.from[0] - cx, m.from[1] - cy);
  const double a0 = std::atan2(m.from[1] - cy, m.from[0] - cx);
  double sweep = std::atan2(m.to[1] - cy, m.to[0] - cx) - a0;
  if (m.cw && sweep >= 0.0) sweep -= 2.0 * std::numbers::pi;
  if (!m.cw && sweep <= 0.0) sweep += 2.0 * std::numbers::pi;
  // The angle of p from the start, in the arc's direction, in [0, 2pi).
  double a = std::atan2(p[1] - cy, p[0] - cx) - a0;
  if (m.cw) a = -a;
  a = std::fmod(std::fmod(a, 2.0 * std::numbers::pi) + 2.0 * std::numbers::pi, 2.0 * std::numbers::pi);
  if (m.from[2] != m.to[2]) return toHelix(p, m, cx, cy, r, a0, sweep);
  const double off_plane = p[2] - m.from[2];
  if (a <= std::abs(sweep)) return std::hypot(std::hypot(p[0] - cx, p[1] - cy) - r, off_plane);
  return std::min(distance(p, m.from), distance(p, m.to));
}

// A lower bound of the distance from p to the primitive: to the box around its end points (a
// line) or around its whole circle (an arc).
inline double toBoundingBox(const AxisValues& p, const MotionPrimitive& m) {
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    double lo = std::min(m.from[i], m.to[i]), hi = std::max(m.from[i], m.to[i]);
    if (m.kind == Kind::Arc && i < 2) {
      const double r = std::hypot(m.from[0] - m.center[0], m.from[1] - m.center[1]);
      lo = m.center[i] - r;
      hi = m.center[i] + r;
    }
    const double out = std::max({lo - p[i], p[i] - hi, 0.0});
    sum += out * out;
  }
  return std::sqrt(sum);
}

// Largest distance of any setpoint from the programmed path.
inline double worstDeviation(const Trace& t, const std::vector<MotionPrimitive>& prog) {
  double worst = 0.0;
  for (const AxisValues& p : t.points) {
    double best = 1e300;
    for (const MotionPrimitive& m : prog)
      if (toBoundingBox(p, m) < best) best = std::min(best, toPrimitive(p, m));
    worst = std::max(worst, best);
  }
  return worst;
}

// A circle of radius r as n chords at `feed`, starting and ending at (r, 0); the vertices
// rounded to multiples of `rounding` mm where that is not 0 (as a CAM system writes them).
inline std::vector<MotionPrimitive> polygonCircle(double r, int n, double feed,
                                                  double rounding = 0.0) {
  std::vector<MotionPrimitive> prog;
  AxisValues p = xyz(r, 0, 0);
  for (int i = 1; i <= n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    AxisValues q = i == n ? xyz(r, 0, 0) : xyz(r * std::cos(a), r * std::sin(a), 0);
    if (rounding > 0.0 && i < n)
      for (int k = 0; k < 2; ++k) q[k] = std::round(q[k] / rounding) * rounding;
    prog.push_back(line(p, q, feed));
    p = q;
  }
  return prog;
}

// Every sampled velocity, acceleration and jerk of `t` within the axis limits (check()).
inline void expectWithinAxisLimits(const MachineConfig& m, const Trace& t) {
  const Worst w = check(m, t);
  EXPECT_LE(w.velocity, 1.0 + kTolerance);
  EXPECT_LE(w.acceleration, 1.0 + kTolerance);
  EXPECT_LE(w.jerk, 1.0 + kTolerance);
}

}  // namespace ncc::motion_test
