// ServoModel::step() for 6 axes with every feature on (torque feed-forward, backlash and
// pitch tables): ns per tick, and the worst tick seen (DESIGN.md: report the worst tick); and
// for the built-in 3-axis mill (velocity feed-forward, no tables), the common case.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "six_axis_machine.h"
#include "ncc/vm/servo/servo_model.h"

namespace {

// Setpoints of a circle in XY with the other axes oscillating, precomputed.
std::vector<ncc::AxisValues> setpoints(long n) {
  std::vector<ncc::AxisValues> out(n);
  for (long k = 0; k < n; ++k) {
    const double t = 0.001 * static_cast<double>(k);
    for (int i = 0; i < 6; ++i) out[k][i] = 50.0 * std::sin(3.0 * t + i);
  }
  return out;
}

// ServoModel::step() on `machine`, cycling through the precomputed setpoints.
void stepLoop(benchmark::State& state, const ncc::MachineConfig& machine) {
  ncc::vm::ServoModel model(machine);
  const std::vector<ncc::AxisValues> sp = setpoints(4096);
  size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(model.step(sp[k]).actual[0]);
    k = (k + 1) & 4095;
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_ServoStep6Axes(benchmark::State& state) { stepLoop(state, ncc::bench::sixAxes()); }
BENCHMARK(BM_ServoStep6Axes);

void BM_ServoStepDefaultMill(benchmark::State& state) { stepLoop(state, ncc::defaultMachine()); }
BENCHMARK(BM_ServoStepDefaultMill);

// Worst single tick over 1e6 ticks, timed one by one (includes the clock's own cost).
void BM_ServoWorstTick6Axes(benchmark::State& state) {
  ncc::vm::ServoModel model(ncc::bench::sixAxes());
  const std::vector<ncc::AxisValues> sp = setpoints(4096);
  using Clock = std::chrono::steady_clock;
  double worst_ns = 0.0;
  for (auto _ : state) {
    for (long k = 0; k < 1000000; ++k) {
      const auto t0 = Clock::now();
      benchmark::DoNotOptimize(model.step(sp[k & 4095]).actual[0]);
      const auto t1 = Clock::now();
      worst_ns = std::max(worst_ns, std::chrono::duration<double, std::nano>(t1 - t0).count());
    }
  }
  state.counters["worst_tick_ns"] = worst_ns;
}
BENCHMARK(BM_ServoWorstTick6Axes)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
