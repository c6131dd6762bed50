// Determinism: the FNV-1a hash of every tick's commanded and actual positions of a fixed
// program (rapids, 10 um chain, arcs, a helix, dwell, G95, M01) on a machine with torque
// feed-forward and backlash is pinned, identical across two runs and after re-constructing,
// and identical whether the program came from bytes or from memory.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "controller_test_util.h"
#include "ncc/bytecode/writer.h"

namespace ncc {
namespace {

using namespace controller_test;
using vm::TickOutput;
using vm::TickStatus;

MachineConfig machine() {
  MachineConfig m = defaultMachine();
  for (AxisConfig& a : m.axes) {
    a.servo.kv = 2.0;
    a.servo.ffw_mode = FeedForwardMode::Torque;
    a.servo.backlash = 0.01;
    a.servo.backlash_compensation = 0.008;
  }
  return m;
}

bytecode::Program program(const MachineConfig& m) {
  bytecode::Assembler a = assemblerFor(m);
  a.at(1, 1).rapid(xyz(10, 5, 2));
  a.at(1, 2).line(xyz(10, 5, 0), 300.0);
  for (int i = 1; i <= 300; ++i)  // a 10 um chain
    a.at(1, 3).line(xyz(10 + 0.01 * i, 5 + 0.005 * i, 0), 2000.0);
  a.at(1, 4).arc(xyz(23, 6.5, 0), 0, 1, 18.0, 6.5, 1500.0, 0);
  a.at(1, 5).arc(xyz(23, 6.5, -3), 0, 1, 20.0, 6.5, 1200.0, 0, bytecode::ArcPlane::XY, 1);
  a.at(1, 6).dwell(0.25);
  a.at(1, 7).spindleSpeed(2000.0).line(xyz(0, 0, -3), 0.2, bytecode::kFlagFeedPerRev);
  a.at(1, 8).op(bytecode::Opcode::OptionalStop);
  a.at(1, 9).rapid(xyz(0, 0, 20)).op(bytecode::Opcode::ProgramEnd).op(bytecode::Opcode::End);
  return a.finish();
}

struct Result {
  uint64_t hash = 0;
  uint64_t ticks = 0;
};

Result hashRun(vm::Controller& ctl) {
  TraceHash h;
  TickOutput out;
  Result r;
  while (ctl.tick(out) == TickStatus::Running) {
    h.add(out, ctl.axisCount());
    ++r.ticks;
  }
  EXPECT_EQ(ctl.status(), TickStatus::Finished);
  r.hash = h.value();
  return r;
}

// Pinned: a change means the planner, interpolator or servo model changed their output. Check
// the change is intended, then update (docs/embedding.md, "Determinism").
constexpr uint64_t kPinnedHash = 0x4aa8952132eb66baULL;
constexpr uint64_t kPinnedTicks = 7464;

TEST(ControllerDeterminism, PinnedHashAcrossRunsAndConstructions) {
  const MachineConfig m = machine();
  std::unique_ptr<vm::Controller> first = make(program(m), m);
  const Result a = hashRun(*first);
  std::unique_ptr<vm::Controller> second = make(program(m), m);
  const Result b = hashRun(*second);
  EXPECT_EQ(a.hash, b.hash);
  EXPECT_EQ(a.ticks, b.ticks);

  std::ostringstream written;
  ASSERT_FALSE(bytecode::write(program(m), written));
  const std::string text = written.str();
  const std::vector<uint8_t> bytes(text.begin(), text.end());
  bytecode::Error error;
  std::unique_ptr<vm::Controller> loaded = vm::Controller::load(bytes, m, error);
  ASSERT_TRUE(loaded) << error.message;
  const Result c = hashRun(*loaded);
  EXPECT_EQ(a.hash, c.hash);

  std::printf("trace hash 0x%016llx over %llu ticks\n", static_cast<unsigned long long>(a.hash),
              static_cast<unsigned long long>(a.ticks));
  EXPECT_EQ(a.hash, kPinnedHash);
  EXPECT_EQ(a.ticks, kPinnedTicks);
}

// The real-time split (ControllerOptions::prepare_in_tick = false): tick() only interpolates
// and steps the servo, the caller runs prepare() between ticks. Same trace, bit for bit.
TEST(ControllerDeterminism, PrepareBetweenTicksGivesTheSameTrace) {
  const MachineConfig m = machine();
  vm::ControllerOptions split;
  split.prepare_in_tick = false;
  std::unique_ptr<vm::Controller> ctl = make(program(m), m, split);
  TraceHash h;
  TickOutput out;
  uint64_t ticks = 0;
  ctl->prepare();
  while (ctl->tick(out) == TickStatus::Running) {
    h.add(out, ctl->axisCount());
    ++ticks;
    ctl->prepare();
  }
  EXPECT_EQ(ctl->status(), TickStatus::Finished);
  EXPECT_EQ(h.value(), kPinnedHash);
  EXPECT_EQ(ticks, kPinnedTicks);
}

// A preparation that falls behind (run every 40th tick, 3 events at a time) never makes the
// path unsafe: the planner brakes at the end of what it holds. The program still ends at its
// end point, only later.
TEST(ControllerDeterminism, StarvedPreparationOnlySlowsThePath) {
  const MachineConfig m = machine();
  vm::ControllerOptions starved;
  starved.prepare_in_tick = false;
  starved.max_events_per_tick = 3;
  std::unique_ptr<vm::Controller> ctl = make(program(m), m, starved);
  TickOutput out;
  uint64_t ticks = 0;
  std::vector<AxisValues> setpoints;
  for (;; ++ticks) {
    if (ticks % 40 == 0) ctl->prepare();
    if (ctl->tick(out) != TickStatus::Running) break;
    setpoints.push_back(out.commanded);
  }
  EXPECT_EQ(ctl->status(), TickStatus::Finished);
  EXPECT_GT(ticks, kPinnedTicks);
  // The setpoints' second differences stay within every axis' acceleration limit.
  const double T = m.ipo_cycle_seconds;
  double worst = 0.0;
  for (std::size_t k = 2; k < setpoints.size(); ++k) {
    for (int i = 0; i < m.axisCount(); ++i) {
      const double a =
          (setpoints[k][i] - 2.0 * setpoints[k - 1][i] + setpoints[k - 2][i]) / (T * T);
      worst = std::max(worst, std::abs(a) / m.axes[static_cast<std::size_t>(i)].max_acceleration);
    }
  }
  EXPECT_LE(worst, 1.0 + 1e-6);
  EXPECT_DOUBLE_EQ(out.commanded[0], 0.0);
  EXPECT_DOUBLE_EQ(out.commanded[1], 0.0);
  EXPECT_DOUBLE_EQ(out.commanded[2], 20.0);
}

}  // namespace
}  // namespace ncc
