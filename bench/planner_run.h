#pragma once
// Motion primitives and the VM's planner loop, shared by the planner benchmarks.
#include <cstdint>
#include <vector>

#include "ncc/machine/machine_config.h"
#include "ncc/vm/events.h"
#include "ncc/vm/motion/planner.h"

namespace ncc::bench {

inline vm::MotionPrimitive line(const AxisValues& from, const AxisValues& to, double feed,
                                bool exact_stop = false) {
  vm::MotionPrimitive m;
  m.kind = vm::MotionPrimitive::Kind::Line;
  m.from = from;
  m.to = to;
  m.feed = feed;
  m.exact_stop = exact_stop;
  return m;
}

// Runs `prog` through a planner the way the VM loop does; returns the index of the tick on
// which it reported the end (the program takes that many ticks minus one of motion).
inline uint64_t runPlanner(const MachineConfig& machine, const std::vector<vm::MotionPrimitive>& prog,
                           std::size_t capacity = 1024) {
  vm::motion::MotionPlanner planner(machine, capacity);
  AxisValues out{};
  vm::motion::SetpointInfo info;
  std::size_t next = 0;
  uint64_t k = 0;
  for (;; ++k) {
    while (next < prog.size() && planner.canAccept()) planner.push(prog[next++]);
    if (next == prog.size()) planner.endOfProgram();
    if (!planner.setpoint(k, out, info)) break;
  }
  return k;
}

}  // namespace ncc::bench
