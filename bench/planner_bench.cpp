// Motion planner throughput (figures, not pass/fail): planned segments per second on 10 um
// G01 chains, straight and along a fast circle, and interpolated ticks per second on a circle.
//   build/bench/planner_bench
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <vector>

#include "ncc/machine/machine_config.h"
#include "ncc/vm/events.h"
#include "ncc/vm/motion/planner.h"
#include "planner_run.h"

namespace {

using ncc::AxisValues;
using ncc::vm::MotionPrimitive;

using ncc::bench::line;

// The VM's planner loop; returns ticks.
uint64_t runProgram(const ncc::MachineConfig& machine, const std::vector<MotionPrimitive>& prog) {
  const uint64_t ticks = ncc::bench::runPlanner(machine, prog);
  benchmark::DoNotOptimize(ticks);
  return ticks;
}

// 20,000 collinear 10 um segments at F6000 (10 segments per tick): planning dominates.
void BM_PlannedSegments(benchmark::State& state) {
  const ncc::MachineConfig machine = ncc::defaultMachine();
  std::vector<MotionPrimitive> prog;
  AxisValues p{};
  for (int i = 1; i <= 20000; ++i) {
    AxisValues q{};
    q[0] = 0.01 * i * 0.6;
    q[1] = 0.01 * i * 0.8;
    prog.push_back(line(p, q, 6000.0));
    p = q;
  }
  uint64_t ticks = 0;
  for (auto _ : state) ticks += runProgram(machine, prog);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(prog.size()));
  state.counters["ticks/s"] = benchmark::Counter(static_cast<double>(ticks), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PlannedSegments)->Unit(benchmark::kMillisecond);

// A circle r = 10 in chords of about 0.01 mm at F6000 (10 chords per tick): a fast curved
// chain, whose limits come from the ramp envelope search (computed once per chain shape).
// Argument 0: equal chords; 1: chords of 0.005 to 0.015 mm (every chord has its own length
// and sagitta; vertices next to chords above about 0.014 mm deviate too much for a chain and
// are blended, so this one also pays for blends and their short runs in the backward pass).
void BM_PlannedCurvedChain(benchmark::State& state) {
  const ncc::MachineConfig machine = ncc::defaultMachine();
  const bool varying = state.range(0) != 0;
  std::vector<MotionPrimitive> prog;
  const double r = 10.0;
  AxisValues p{};
  p[0] = r;
  double angle = 0.0;
  for (int i = 0; angle < 2.0 * std::numbers::pi; ++i) {
    const double chord = varying ? 0.005 + 0.01 * ((i * 7919) % 101) / 100.0 : 0.01;
    angle = std::min(angle + chord / r, 2.0 * std::numbers::pi);
    AxisValues q{};
    q[0] = r * std::cos(angle);
    q[1] = r * std::sin(angle);
    prog.push_back(line(p, q, 6000.0));
    p = q;
  }
  for (auto _ : state) runProgram(machine, prog);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(prog.size()));
}
BENCHMARK(BM_PlannedCurvedChain)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Ten full circles r = 20 at F3000 as one arc each: interpolation dominates.
void BM_Ticks(benchmark::State& state) {
  const ncc::MachineConfig machine = ncc::defaultMachine();
  std::vector<MotionPrimitive> prog;
  AxisValues s{};
  s[0] = 20.0;
  for (int i = 0; i < 10; ++i) {
    MotionPrimitive m;
    m.kind = MotionPrimitive::Kind::Arc;
    m.from = s;
    m.to = s;
    m.feed = 3000.0;
    prog.push_back(m);
  }
  uint64_t ticks = 0;
  for (auto _ : state) ticks += runProgram(machine, prog);
  state.SetItemsProcessed(static_cast<int64_t>(ticks));
  state.counters["ticks/s"] = benchmark::Counter(static_cast<double>(ticks), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Ticks)->Unit(benchmark::kMillisecond);

// A feed override turn (MotionPlanner::setFeedOverride) with N segments queued, each its own
// run (a zig-zag of 1 mm lines whose corners stop): the re-plan of the whole window, which
// vm::Controller runs in prepare(). Time is per turn; `ns/queued_run` per run re-planned; the
// peer, measured in the same run, is pushing those N segments into the window
// (`turn/push_window`: how many window fills one turn costs).
void BM_FeedOverrideTurn(benchmark::State& state) {
  const ncc::MachineConfig machine = ncc::defaultMachine();
  const auto segments = static_cast<std::size_t>(state.range(0));
  ncc::vm::motion::MotionPlanner planner(machine, segments + 16);
  planner.setOverrides(1.0, 1.0, 1.0);
  std::vector<MotionPrimitive> prog;
  AxisValues p{};
  for (std::size_t i = 1; i <= segments; ++i) {
    AxisValues q = p;
    q[0] += 1.0;
    q[1] = (i % 2 == 0) ? 0.0 : 1.0;
    prog.push_back(line(p, q, 30000.0));
    p = q;
  }
  const auto fill_start = std::chrono::steady_clock::now();
  for (const MotionPrimitive& m : prog) planner.push(m);
  const double fill_ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - fill_start).count();
  double knob = 0.5;
  const auto turns_start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    planner.setFeedOverride(knob);
    knob = knob == 0.5 ? 0.9 : 0.5;
  }
  const double turn_ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - turns_start).count() /
                         static_cast<double>(state.iterations());
  state.counters["ns/queued_run"] = turn_ns / static_cast<double>(planner.queued());
  state.counters["turn/push_window"] = turn_ns / fill_ns;
}
BENCHMARK(BM_FeedOverrideTurn)->Arg(256)->Arg(1024)->Arg(4096);

}  // namespace

BENCHMARK_MAIN();
