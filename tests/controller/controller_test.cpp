// vm::Controller end to end: loading errors, the tick loop, source positions, stops, feed per
// revolution, and alarms from the executor (G27) and the servo model (25050).
#include "ncc/vm/controller.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "controller_test_util.h"
#include "ncc/bytecode/writer.h"

namespace ncc {
namespace {

using namespace controller_test;
using vm::TickOutput;
using vm::TickStatus;

std::vector<TickOutput> runAll(vm::Controller& ctl, uint64_t max_ticks = 10'000'000) {
  std::vector<TickOutput> ticks;
  TickOutput out;
  while (ticks.size() < max_ticks && ctl.tick(out) == TickStatus::Running) ticks.push_back(out);
  return ticks;
}

TEST(Controller, LoadReportsBadBytesInsteadOfThrowing) {
  const std::vector<uint8_t> junk = {'N', 'C', 'C', 'X', 1, 2, 3};
  bytecode::Error error;
  EXPECT_EQ(vm::Controller::load(junk, defaultMachine(), error), nullptr);
  EXPECT_EQ(error.code.substr(0, 5), "NCC70");
}

TEST(Controller, CreateVerifiesAgainstTheMachine) {
  MachineConfig m = defaultMachine();
  bytecode::Assembler a = assemblerFor(m);
  a.line(xyz(1, 0, 0), 600.0).op(bytecode::Opcode::End);
  bytecode::Program p = a.finish();
  p.header.config_hash ^= 1;  // compiled for another machine
  bytecode::Error error;
  EXPECT_EQ(vm::Controller::create(p, m, error), nullptr);
  EXPECT_EQ(error.code.substr(0, 5), "NCC71");
}

// A MachineConfig built in code skips the machine file's checks: create() refuses what the
// VM cannot run with (a zero cycle made NaN setpoints), naming the value.
TEST(Controller, CreateRefusesAMachineItCannotRun) {
  struct Case {
    const char* names;
    void (*spoil)(MachineConfig&);
  };
  const Case cases[] = {
      {"ipo_cycle", [](MachineConfig& m) { m.ipo_cycle_seconds = 0.0; }},
      {"ipo_cycle", [](MachineConfig& m) { m.ipo_cycle_seconds = 0.5; }},
      {"chord_tolerance", [](MachineConfig& m) { m.chord_tolerance = 0.0; }},
      {"corner_tolerance", [](MachineConfig& m) { m.corner_tolerance = -0.01; }},
      {"max_acceleration of Y", [](MachineConfig& m) { m.axes[1].max_acceleration = 0.0; }},
      {"max_jerk of Z",
       [](MachineConfig& m) { m.axes[2].max_jerk = std::numeric_limits<double>::infinity(); }},
      {"rapid_velocity of X", [](MachineConfig& m) { m.axes[0].rapid_velocity = -1.0; }},
      {"max_velocity of X", [](MachineConfig& m) { m.axes[0].max_velocity = std::nan(""); }},
      {"kv of Z", [](MachineConfig& m) { m.axes[2].servo.kv = 0.0; }},
      {"pitch_error.step of X", [](MachineConfig& m) { m.axes[0].servo.pitch_error.step = 0.0; }},
      {"equiv_speedctrl_time of Y",
       [](MachineConfig& m) { m.axes[1].servo.equiv_speedctrl_time = -0.001; }},
      {"min_travel of X", [](MachineConfig& m) { m.axes[0].min_travel = m.axes[0].max_travel; }},
      // NaN or out-of-range servo values gave NaN actual positions and no alarm.
      {"velo_ffw_weight of X", [](MachineConfig& m) { m.axes[0].servo.velo_ffw_weight = std::nan(""); }},
      {"contour_tol of Y", [](MachineConfig& m) { m.axes[1].servo.contour_tol = 0.0; }},
      {"standstill_pos_tol of Z", [](MachineConfig& m) { m.axes[2].servo.standstill_pos_tol = -1.0; }},
      {"standstill_delay_time of X",
       [](MachineConfig& m) { m.axes[0].servo.standstill_delay_time = -0.1; }},
      {"stop_limit_fine of Y", [](MachineConfig& m) { m.axes[1].servo.stop_limit_fine = 0.0; }},
      {"positioning_time of Z", [](MachineConfig& m) { m.axes[2].servo.positioning_time = 0.0; }},
      {"backlash of X",
       [](MachineConfig& m) { m.axes[0].servo.backlash = std::numeric_limits<double>::infinity(); }},
      {"backlash_compensation of Y",
       [](MachineConfig& m) { m.axes[1].servo.backlash_compensation = std::nan(""); }},
      {"pitch_error.start of X", [](MachineConfig& m) { m.axes[0].servo.pitch_error.start = std::nan(""); }},
      {"pitch_compensation.values[1] of Z",
       [](MachineConfig& m) { m.axes[2].servo.pitch_compensation.values = {0.0, std::nan(""), 0.0}; }},
      // A grid whose support points coincide, and a slope that overflows (review 12).
      {"pitch_error.step of Y",
       [](MachineConfig& m) { m.axes[1].servo.pitch_error = PitchTable{1e16, 0.5, {0.0, 0.001}}; }},
      {"pitch_error.values[1] of X",
       [](MachineConfig& m) { m.axes[0].servo.pitch_error = PitchTable{0.0, 1e-312, {0.0, 0.01}}; }},
      {"start_position of Y", [](MachineConfig& m) { m.start_position[1] = std::nan(""); }},
  };
  for (const Case& c : cases) {
    MachineConfig m = defaultMachine();
    c.spoil(m);
    bytecode::Assembler a = assemblerFor(m);
    a.line(xyz(1, 0, 0), 600.0).op(bytecode::Opcode::End);
    bytecode::Error error;
    EXPECT_EQ(vm::Controller::create(a.finish(), m, error), nullptr) << c.names;
    EXPECT_EQ(error.code, "NCC7115") << c.names;
    EXPECT_NE(error.message.find(c.names), std::string::npos) << error.message;
  }
  // The defaults run.
  MachineConfig m = defaultMachine();
  bytecode::Assembler a = assemblerFor(m);
  a.line(xyz(1, 0, 0), 600.0).op(bytecode::Opcode::End);
  bytecode::Error error;
  EXPECT_NE(vm::Controller::create(a.finish(), m, error), nullptr) << error.message;
}

TEST(Controller, LoadsWrittenBytesAndRunsToTheEnd) {
  MachineConfig m = defaultMachine();
  bytecode::Assembler a = assemblerFor(m);
  a.at(1, 1).rapid(xyz(10, 0, 5));
  a.at(1, 2).line(xyz(10, 20, 5), 1200.0);
  a.at(1, 3).op(bytecode::Opcode::ProgramEndRewind).op(bytecode::Opcode::End);
  std::ostringstream written;
  ASSERT_FALSE(bytecode::write(a.finish(), written));
  const std::string text = written.str();
  const std::vector<uint8_t> bytes(text.begin(), text.end());
  bytecode::Error error;
  std::unique_ptr<vm::Controller> ctl = vm::Controller::load(bytes, m, error);
  ASSERT_TRUE(ctl) << error.message;

  std::vector<TickOutput> ticks = runAll(*ctl);
  ASSERT_GT(ticks.size(), 1000u);
  for (std::size_t k = 0; k < ticks.size(); ++k) {
    ASSERT_EQ(ticks[k].tick, k);
    ASSERT_EQ(ticks[k].time, static_cast<double>(k) * 0.001);
  }
  EXPECT_EQ(ticks.back().commanded, xyz(10, 20, 5));
  EXPECT_EQ(ctl->status(), TickStatus::Finished);
  EXPECT_EQ(ctl->alarm(), nullptr);
  // Source of the active block: the rapid, then the line.
  EXPECT_EQ(ticks[10].where.line, 1u);
  EXPECT_EQ(ticks[10].file, "test.nc");
  EXPECT_EQ(ticks[ticks.size() - 10].where.line, 2u);

  // Once finished, tick() repeats the last tick.
  TickOutput again;
  EXPECT_EQ(ctl->tick(again), TickStatus::Finished);
  EXPECT_EQ(again.tick, ticks.back().tick);
  EXPECT_EQ(again.commanded, ticks.back().commanded);
  EXPECT_EQ(again.status, TickStatus::Finished);
}

TEST(Controller, ProgramStopBringsThePathToRest) {
  // Two collinear lines pass at full speed; with M00 between them the path stops.
  MachineConfig m = defaultMachine();
  auto minimumInterior = [&](bool with_stop) {
    bytecode::Assembler a = assemblerFor(m);
    a.line(xyz(10, 0, 0), 3000.0);
    if (with_stop) a.op(bytecode::Opcode::ProgramStop);
    a.line(xyz(20, 0, 0), 3000.0).op(bytecode::Opcode::End);
    std::unique_ptr<vm::Controller> ctl = make(a.finish(), m);
    double lowest = 1e9;
    for (const TickOutput& t : runAll(*ctl))
      if (t.commanded[0] > 5.0 && t.commanded[0] < 15.0) lowest = std::min(lowest, t.path_velocity);
    return lowest;
  };
  EXPECT_NEAR(minimumInterior(false), 50.0, 1e-9);
  EXPECT_EQ(minimumInterior(true), 0.0);
}

TEST(Controller, LookAheadDepthComesFromTheMachine) {
  // A circle r 10 in 0.01 mm chords at F6000: the planner keeps a stop within what it holds,
  // so 256 segments (2.56 mm) allow only part of the feed (braking on the curve takes about
  // 6.7 mm from 100 mm/s); the machine's lookahead_segments = 4096 holds it and the circle
  // runs at F. An explicit ControllerOptions::window_capacity overrides the machine. The
  // statistics count the ticks the depth held the speed down: with 4096 only at the start,
  // while the first ticks' events (max_events_per_tick) fill the window.
  struct Result {
    double top = 0.0;
    uint64_t limited_ticks = 0, ticks = 0;
  };
  auto topSpeed = [](int machine_segments, std::size_t option_segments) {
    MachineConfig m = defaultMachine();
    m.lookahead_segments = machine_segments;
    m.start_position = xyz(10, 0, 0);
    bytecode::Assembler a = assemblerFor(m);
    const int n = 6283;
    for (int i = 1; i <= n; ++i) {
      const double t = 2.0 * std::numbers::pi * i / n;
      a.line(i == n ? xyz(10, 0, 0) : xyz(10 * std::cos(t), 10 * std::sin(t), 0), 6000.0);
    }
    a.op(bytecode::Opcode::End);
    vm::ControllerOptions options;
    options.window_capacity = option_segments;
    bytecode::Error error;
    std::unique_ptr<vm::Controller> ctl = vm::Controller::create(a.finish(), m, error, options);
    EXPECT_TRUE(ctl) << error.message;
    Result r;
    if (!ctl) return r;
    for (const TickOutput& t : runAll(*ctl)) r.top = std::max(r.top, t.path_velocity);
    r.limited_ticks = ctl->statistics().lookahead_limited_ticks;
    r.ticks = ctl->statistics().ticks;
    return r;
  };
  const Result shallow = topSpeed(256, 0), deep = topSpeed(4096, 0);
  EXPECT_LT(shallow.top, 90.0);
  EXPECT_GT(shallow.limited_ticks, shallow.ticks / 2);
  EXPECT_NEAR(deep.top, 100.0, 1e-4);  // F over the chord bows' speed bound, 1 + 2.5e-7
  EXPECT_LT(deep.limited_ticks, deep.ticks / 5);
  EXPECT_LT(topSpeed(4096, 256).top, 90.0);
}

// G01 X300 at F6000 from the origin, on line 5.
bytecode::Program longLine(const MachineConfig& m) {
  bytecode::Assembler a = assemblerFor(m);
  a.at(1, 5).line(xyz(300, 0, 0), 6000.0);
  a.op(bytecode::Opcode::End);
  return a.finish();
}

TEST(Controller, FeedOverrideTurnedDuringTheRun) {
  // G01 X300 at F6000 on the default machine: at 100 % it cruises at 100 mm/s; the operator
  // turns the knob to 40 % at t = 1 s, then to 120 % at t = 2 s (the run is planned for
  // 120 %). The path speed follows, the program ends where it should, and the knob reports
  // what it was turned to. Without a planned maximum the knob stops at the start value.
  const MachineConfig m = defaultMachine();
  const bytecode::Program prog = longLine(m);
  vm::ControllerOptions options;
  options.max_feed_override = 1.2;
  bytecode::Error error;
  std::unique_ptr<vm::Controller> ctl = vm::Controller::create(prog, m, error, options);
  ASSERT_TRUE(ctl) << error.message;
  std::vector<TickOutput> ticks;
  TickOutput out;
  for (uint64_t k = 0;; ++k) {
    if (k == 1000) ctl->setFeedOverride(0.4);
    if (k == 2000) ctl->setFeedOverride(1.2);
    if (ctl->tick(out) != TickStatus::Running) break;
    ticks.push_back(out);
  }
  ASSERT_GT(ticks.size(), 2500u);
  EXPECT_NEAR(ticks[900].path_velocity, 100.0, 1e-9);
  EXPECT_NEAR(ticks[1900].path_velocity, 40.0, 1e-9);
  EXPECT_NEAR(ticks[2400].path_velocity, 120.0, 1e-9);
  EXPECT_DOUBLE_EQ(ctl->feedOverride(), 1.2);
  EXPECT_EQ(ticks.back().commanded, xyz(300, 0, 0));
  EXPECT_EQ(ctl->statistics().limit_violations, 0);

  std::unique_ptr<vm::Controller> capped = vm::Controller::create(prog, m, error);
  ASSERT_TRUE(capped);
  capped->setFeedOverride(1.2);
  EXPECT_DOUBLE_EQ(capped->feedOverride(), 1.0);
}

TEST(Controller, RapidOverrideTurnedDuringTheRun) {
  // A linear G00 X2000 on the default machine (500 mm/s): turned to 30 % at 1 s and back to
  // 100 % at 3 s, the path speed follows; the knob reads back what was requested (clamped to
  // 100 %), and the run ends on X2000 without a limit violation.
  const MachineConfig m = defaultMachine();
  bytecode::Assembler a = assemblerFor(m);
  a.rapid(xyz(2000, 0, 0)).op(bytecode::Opcode::End);
  const bytecode::Program prog = a.finish();
  bytecode::Error error;
  std::unique_ptr<vm::Controller> ctl = vm::Controller::create(prog, m, error);
  ASSERT_TRUE(ctl) << error.message;
  std::vector<TickOutput> ticks;
  TickOutput out;
  for (uint64_t k = 0;; ++k) {
    if (k == 1000) ctl->setRapidOverride(0.3);
    if (k == 3000) ctl->setRapidOverride(1.7);
    if (ctl->tick(out) != TickStatus::Running) break;
    ticks.push_back(out);
  }
  ASSERT_GT(ticks.size(), 3500u);
  EXPECT_NEAR(ticks[900].path_velocity, 500.0, 1e-9);
  EXPECT_NEAR(ticks[2900].path_velocity, 150.0, 1e-9);
  EXPECT_NEAR(ticks[3400].path_velocity, 500.0, 1e-9);
  EXPECT_DOUBLE_EQ(ctl->rapidOverride(), 1.0);
  EXPECT_EQ(ticks.back().commanded, xyz(2000, 0, 0));
  EXPECT_EQ(ctl->statistics().limit_violations, 0);
}

TEST(Controller, FeedHoldStopsThePathUntilReleased) {
  // G01 X300 at F6000, held at 1 s and released at 2.5 s: the path stands on the line
  // meanwhile (Running, zero speed, the same setpoint), the run takes 1.5 s longer and ends
  // on X300 without a limit violation.
  const MachineConfig m = defaultMachine();
  const bytecode::Program prog = longLine(m);
  bytecode::Error error;
  std::unique_ptr<vm::Controller> plain = vm::Controller::create(prog, m, error);
  std::unique_ptr<vm::Controller> ctl = vm::Controller::create(prog, m, error);
  ASSERT_TRUE(plain && ctl) << error.message;
  const std::size_t plain_ticks = runAll(*plain).size();
  std::vector<TickOutput> ticks;
  TickOutput out;
  for (uint64_t k = 0;; ++k) {
    if (k == 1000) ctl->setFeedHold(true);
    if (k == 2500) ctl->setFeedHold(false);
    EXPECT_EQ(ctl->feedHold(), k >= 1000 && k < 2500);
    if (ctl->tick(out) != TickStatus::Running) break;
    ticks.push_back(out);
  }
  EXPECT_EQ(ticks.size(), plain_ticks + 1500);
  for (std::size_t k = 1200; k < 2500; ++k) {
    ASSERT_EQ(ticks[k].commanded, ticks[1200].commanded) << k;
    ASSERT_EQ(ticks[k].path_velocity, 0.0) << k;
  }
  EXPECT_GT(ticks[1200].commanded[0], 90.0);
  EXPECT_EQ(ticks[2000].where.line, 5u);  // held, it still names the block it stands in
  EXPECT_EQ(ticks.back().commanded, xyz(300, 0, 0));
  EXPECT_EQ(ctl->statistics().limit_violations, 0);
}

TEST(Controller, OperatorRequestsGiveTheSameTraceInBothLoops) {
  // Feed and rapid override turns and feed holds take effect at the next prepare(), whenever they were
  // requested since the one before. The simple loop requests before tick k (whose prepare()
  // applies it); the real-time loop requests the same right after the prepare() that
  // precedes tick k - 1, a whole tick earlier and after that prepare() pulled its events.
  // With a shallow window the queue changes between those points, so applying a request at
  // once would re-plan a different queue; latched, both loops give the same trace bit for bit.
  MachineConfig m = defaultMachine();
  bytecode::Assembler a = assemblerFor(m);
  for (int i = 1; i <= 600; ++i) {
    const AxisValues p = xyz(0.05 * i, 2.0 * std::sin(0.02 * i), 0);
    if (i % 150 == 0) a.rapid(xyz(p[0], p[1], 40)).rapid(xyz(p[0] + 30, p[1], 40)).rapid(p);
    a.line(p, i % 200 < 100 ? 6000.0 : 3000.0);
  }
  a.op(bytecode::Opcode::End);
  const bytecode::Program prog = a.finish();
  auto request = [](vm::Controller& ctl, uint64_t k) {
    if (k % 37 == 0) ctl.setFeedOverride(0.1 + 0.07 * static_cast<double>(k % 13));
    if (k % 53 == 0) ctl.setRapidOverride(0.2 + 0.1 * static_cast<double>(k % 9));
    if (k % 400 == 150) ctl.setFeedHold(true);
    if (k % 400 == 260) ctl.setFeedHold(false);
  };
  auto trace = [&](bool prepare_in_tick) {
    vm::ControllerOptions options;
    options.window_capacity = 48;
    options.prepare_in_tick = prepare_in_tick;
    bytecode::Error error;
    std::unique_ptr<vm::Controller> ctl = vm::Controller::create(prog, m, error, options);
    EXPECT_TRUE(ctl) << error.message;
    std::vector<AxisValues> points;
    TickOutput out;
    if (!prepare_in_tick) {
      request(*ctl, 0);
      ctl->prepare();  // precedes tick 0
      request(*ctl, 1);
    }
    for (uint64_t k = 0; k < 200'000; ++k) {
      if (prepare_in_tick) request(*ctl, k);
      if (ctl->tick(out) != TickStatus::Running) break;
      points.push_back(out.commanded);
      if (!prepare_in_tick) {
        ctl->prepare();  // precedes tick k + 1
        request(*ctl, k + 2);
      }
    }
    EXPECT_EQ(ctl->status(), TickStatus::Finished);
    return points;
  };
  const std::vector<AxisValues> simple = trace(true), realtime = trace(false);
  ASSERT_GT(simple.size(), 1000u);
  EXPECT_EQ(simple, realtime);
}

TEST(Controller, FeedPerRevolutionUsesTheSpindleSpeed) {
  MachineConfig m = defaultMachine();
  bytecode::Assembler a = assemblerFor(m);
  a.spindleSpeed(1000.0).line(xyz(50, 0, 0), 0.12, bytecode::kFlagFeedPerRev);
  a.op(bytecode::Opcode::End);
  std::unique_ptr<vm::Controller> ctl = make(a.finish(), m);
  double top = 0.0;
  for (const TickOutput& t : runAll(*ctl)) top = std::max(top, t.path_velocity);
  EXPECT_NEAR(top, 0.12 * 1000.0 / 60.0, 1e-12);  // 2 mm/s
}

TEST(Controller, FeedPerRevolutionWithTheSpindleStoppedIsAnAlarm) {
  // No S at all, and S1000 then M05: the G95 block raises NCC7207 once the motion queued
  // before it has run; nothing after it moves.
  const MachineConfig m = defaultMachine();
  for (bool with_m05 : {false, true}) {
    bytecode::Assembler a = assemblerFor(m);
    a.at(1, 1).line(xyz(5, 0, 0), 600.0);
    if (with_m05) a.spindleSpeed(1000.0).op(bytecode::Opcode::SpindleCW).op(bytecode::Opcode::SpindleStop);
    a.at(1, 3, 1).line(xyz(10, 0, 0), 0.1, bytecode::kFlagFeedPerRev);
    a.at(1, 4).line(xyz(20, 0, 0), 600.0).op(bytecode::Opcode::End);
    std::unique_ptr<vm::Controller> ctl = make(a.finish(), m);
    const std::vector<TickOutput> ticks = runAll(*ctl);
    EXPECT_EQ(ctl->status(), TickStatus::Alarm) << with_m05;
    ASSERT_NE(ctl->alarm(), nullptr);
    EXPECT_EQ(ctl->alarm()->code, "NCC7207");
    EXPECT_EQ(ctl->alarm()->message,
              "feed per revolution with the spindle stopped: S is 0 (or not given) or M05 is "
              "active");
    EXPECT_EQ(ctl->alarm()->where, (SourceLocation{1, 3, 1}));
    ASSERT_FALSE(ticks.empty());
    EXPECT_EQ(ticks.back().commanded, xyz(5, 0, 0));
  }
  // M03 after M05 runs it again.
  bytecode::Assembler a = assemblerFor(m);
  a.spindleSpeed(1000.0).op(bytecode::Opcode::SpindleStop).op(bytecode::Opcode::SpindleCW);
  a.line(xyz(1, 0, 0), 0.1, bytecode::kFlagFeedPerRev).op(bytecode::Opcode::End);
  std::unique_ptr<vm::Controller> ctl = make(a.finish(), m);
  runAll(*ctl);
  EXPECT_EQ(ctl->status(), TickStatus::Finished);
}

TEST(Controller, ExactStopWaitsForTheAxesToBeInPosition) {
  // Kv 1 without feed-forward or speed-loop lag: after the G09 block the setpoint is held on
  // its end point while the error decays by (1 - Kv T) per cycle, until it is within
  // STOP_LIMIT_FINE (0.01 mm); the next block starts on the following tick.
  ServoConfig servo;
  servo.ffw_mode = FeedForwardMode::None;
  servo.equiv_speedctrl_time = 0.0;
  const MachineConfig m = machineWith(servo);
  bytecode::Assembler a = assemblerFor(m);
  a.line(xyz(10, 0, 0), 600.0, bytecode::kFlagExactStop);
  a.line(xyz(10, 5, 0), 600.0).op(bytecode::Opcode::End);
  std::unique_ptr<vm::Controller> ctl = make(a.finish(), m);
  const std::vector<TickOutput> ticks = runAll(*ctl);
  ASSERT_EQ(ctl->status(), TickStatus::Finished);
  std::size_t first = ticks.size(), last = 0;
  for (std::size_t k = 0; k < ticks.size(); ++k) {
    if (ticks[k].commanded != xyz(10, 0, 0)) continue;
    first = std::min(first, k);
    last = k;
  }
  ASSERT_LT(first, ticks.size());
  ASSERT_GT(last, first + 2);
  const double e0 = std::abs(ticks[first].commanded[0] - ticks[first].actual[0]);
  const double decay = 1.0 - kvPerSecond(1.0) * m.ipo_cycle_seconds;
  std::size_t expected = 0;
  for (double e = e0; e > 0.01; e *= decay) ++expected;
  EXPECT_GT(expected, 10u);
  // In position on tick last - 1 (checked after its servo step), not one tick earlier; the
  // next block's first sample (tick `last`) is its start point, the stop point.
  EXPECT_EQ(last - 1 - first, expected);
  EXPECT_LE(std::abs(ticks[last - 1].commanded[0] - ticks[last - 1].actual[0]), 0.01);
  EXPECT_GT(std::abs(ticks[last - 2].commanded[0] - ticks[last - 2].actual[0]), 0.01);
}

TEST(Controller, PositioningTimeoutIsAlarm25080) {
  ServoConfig servo;
  servo.ffw_mode = FeedForwardMode::None;
  servo.kv = 0.05;              // 0.83/s: the lag decays far too slowly
  servo.positioning_time = 0.1;
  servo.contour_tol = 1e6;
  servo.standstill_pos_tol = 1e6;
  const MachineConfig m = machineWith(servo);
  bytecode::Assembler a = assemblerFor(m);
  a.at(1, 1).line(xyz(10, 0, 0), 600.0, bytecode::kFlagExactStop);
  a.at(1, 2).line(xyz(10, 5, 0), 600.0).op(bytecode::Opcode::End);
  std::unique_ptr<vm::Controller> ctl = make(a.finish(), m);
  const std::vector<TickOutput> ticks = runAll(*ctl);
  EXPECT_EQ(ctl->status(), TickStatus::Alarm);
  ASSERT_NE(ctl->alarm(), nullptr);
  EXPECT_EQ(ctl->alarm()->code, "25080");
  EXPECT_EQ(ctl->alarm()->where.line, 1u);
  EXPECT_EQ(ctl->alarm()->message.rfind("positioning monitoring: axis X is ", 0), 0u)
      << ctl->alarm()->message;
  EXPECT_NE(ctl->alarm()->message.find(" mm from its end point, outside STOP_LIMIT_FINE 0.010000 mm "
                                       "after POSITIONING_TIME 0.100 s"),
            std::string::npos)
      << ctl->alarm()->message;
  EXPECT_EQ(ticks.back().commanded, xyz(10, 0, 0));  // the next block never started
}

TEST(Controller, ReferenceCheckAlarmStopsTheRunWhenTheBlockIsReached) {
  MachineConfig m = defaultMachine();
  bytecode::Assembler a = assemblerFor(m);
  a.at(1, 1).rapid(xyz(0, 0, 10));
  a.at(1, 2, 4).refCheck(0b111, 1, xyz(0, 0, 0));
  a.at(1, 3).rapid(xyz(5, 5, 5)).op(bytecode::Opcode::End);
  std::unique_ptr<vm::Controller> ctl = make(a.finish(), m);

  std::vector<TickOutput> ticks = runAll(*ctl);
  ASSERT_FALSE(ticks.empty());
  EXPECT_EQ(ctl->status(), TickStatus::Alarm);
  ASSERT_NE(ctl->alarm(), nullptr);
  EXPECT_EQ(ctl->alarm()->code, "NCC7201");
  EXPECT_EQ(ctl->alarm()->where, (SourceLocation{1, 2, 4}));
  EXPECT_EQ(ctl->alarm()->message,
            "G27 reference position check failed: axis Z is at 10, reference point is 0");
  // The rapid before the check ran to its end; the one after it never started.
  EXPECT_EQ(ticks.back().commanded, xyz(0, 0, 10));
  TickOutput again;
  EXPECT_EQ(ctl->tick(again), TickStatus::Alarm);
  EXPECT_EQ(again.tick, ticks.back().tick);
}

TEST(Controller, FollowingErrorAlarmStopsTheRunOnTheTickThatTripsIt) {
  // No feed-forward, Kv 1: 6 mm of following error at F6000, over a 0.5 mm CONTOUR_TOL.
  ServoConfig servo;
  servo.ffw_mode = FeedForwardMode::None;
  servo.contour_tol = 0.5;
  MachineConfig m = machineWith(servo);
  bytecode::Assembler a = assemblerFor(m);
  a.at(1, 7).line(xyz(0, 100, 0), 6000.0).op(bytecode::Opcode::End);
  std::unique_ptr<vm::Controller> ctl = make(a.finish(), m);

  TickOutput out;
  TickStatus status = TickStatus::Running;
  uint64_t produced = 0;
  while ((status = ctl->tick(out)) == TickStatus::Running) ++produced;
  ASSERT_EQ(status, TickStatus::Alarm);
  ASSERT_NE(ctl->alarm(), nullptr);
  EXPECT_EQ(ctl->alarm()->code, "25050");
  EXPECT_EQ(ctl->alarm()->where.line, 7u);
  EXPECT_NE(ctl->alarm()->message.find("axis Y"), std::string::npos) << ctl->alarm()->message;
  // `out` is the tick that tripped it: just over the tolerance, far from the line's end.
  EXPECT_EQ(out.tick, produced);
  EXPECT_EQ(out.status, TickStatus::Alarm);
  EXPECT_GT(std::abs(out.following_error[1]), 0.5);
  EXPECT_LT(std::abs(out.following_error[1]), 0.6);
  EXPECT_LT(out.commanded[1], 10.0);
}

TEST(Controller, StepLimitStopsAMacroLoopWithoutMotion) {
  MachineConfig m = defaultMachine();
  bytecode::Assembler a = assemblerFor(m);
  bytecode::Assembler::Label top = a.newLabel();
  bytecode::Assembler::Label end = a.newLabel();
  a.bind(top).push(1.0).jump(bytecode::Opcode::JumpIfFalse, end).jump(bytecode::Opcode::Jump, top);
  a.bind(end).op(bytecode::Opcode::End);
  vm::ControllerOptions options;
  options.step_limit = 100000;
  std::unique_ptr<vm::Controller> ctl = make(a.finish(), m, options);
  TickOutput out;
  EXPECT_EQ(ctl->tick(out), TickStatus::Alarm);
  EXPECT_EQ(ctl->alarm()->code, "NCC7204");
}

}  // namespace
}  // namespace ncc

namespace ncc {
namespace {

// createBorrowing runs the caller's program without copying it: the same ticks as create().
TEST(Controller, BorrowingRunsTheSameTicksWithoutACopy) {
  MachineConfig m = defaultMachine();
  bytecode::Assembler a = controller_test::assemblerFor(m);
  a.at(1, 1).rapid(controller_test::xyz(10, 0, 5));
  a.at(1, 2).line(controller_test::xyz(10, 20, 5), 1200.0);
  a.at(1, 3).op(bytecode::Opcode::ProgramEndRewind).op(bytecode::Opcode::End);
  const bytecode::Program program = a.finish();
  bytecode::Error error;
  std::unique_ptr<vm::Controller> borrowing =
      vm::Controller::createBorrowing(program, m, error);
  ASSERT_TRUE(borrowing) << error.message;
  EXPECT_EQ(&borrowing->program(), &program);
  std::unique_ptr<vm::Controller> owning = controller_test::make(program, m);
  EXPECT_NE(&owning->program(), &program);
  vm::TickOutput x, y;
  vm::TickStatus sx, sy;
  do {
    sx = borrowing->tick(x);
    sy = owning->tick(y);
    ASSERT_EQ(sx, sy);
    ASSERT_EQ(x.commanded, y.commanded);
    ASSERT_EQ(x.actual, y.actual);
  } while (sx == vm::TickStatus::Running);
  EXPECT_EQ(sx, vm::TickStatus::Finished);
  // It verifies as create() does.
  bytecode::Program other = program;
  other.header.config_hash ^= 1;
  EXPECT_EQ(vm::Controller::createBorrowing(other, m, error), nullptr);
  EXPECT_EQ(error.code.substr(0, 5), "NCC71");
}

}  // namespace
}  // namespace ncc
