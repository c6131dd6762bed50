#pragma once
// The machine a program is compiled for and run on: axes, offset registers, work offsets,
// reference points, start position and the dialect's controller parameters.
// Read from TOML (machine_file.h); a conformance case's [machine] and [start] tables are a
// valid machine file. `defaultMachine()` is a 3-axis metric mill.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ncc/machine/axes.h"
#include "ncc/machine/dialect.h"
#include "ncc/machine/params.h"
#include "ncc/machine/probe.h"
#include "ncc/machine/signals.h"
#include "ncc/machine/servo_config.h"

namespace ncc {

enum class AxisKind : uint8_t { Linear, Rotary };

struct AxisConfig {
  std::string name;             // "X", "Y", "Z", "A", ...
  AxisKind kind = AxisKind::Linear;
  bool diameter = false;        // lathe: programmed and reported as a diameter
  double min_travel = -1e9;     // machine coordinates, mm or deg
  double max_travel = 1e9;
  double rapid_velocity = 30000.0;  // mm/min (deg/min): G00 speed
  double max_velocity = 30000.0;    // mm/min: cutting feed limit
  double max_acceleration = 2000.0; // mm/s^2
  double max_jerk = 50000.0;        // mm/s^3
  ServoConfig servo;                // run-time only: not hashed
  friend bool operator==(const AxisConfig&, const AxisConfig&) = default;
};

// One mill offset register pair: H (length) and D (radius) share numbers on FANUC/Mazak.
struct ToolOffsetRegisters {
  std::map<int, double> length;  // H number -> tool length, mm
  std::map<int, double> radius;  // D number -> cutter radius, mm
  friend bool operator==(const ToolOffsetRegisters&, const ToolOffsetRegisters&) = default;
};

// Lathe tool offset memory (geometry/wear with tip direction), used by fanuc-t.
struct LatheOffset {
  double x = 0.0, z = 0.0, radius = 0.0;
  int tip = 0;                  // imaginary tool nose direction 0..9
  friend bool operator==(const LatheOffset&, const LatheOffset&) = default;
};
struct LatheOffsetRegisters {
  std::map<int, LatheOffset> combined;        // T1 = {...}: one register, geometry only
  std::map<int, LatheOffset> geometry;        // geometryN
  std::map<int, LatheOffset> wear;            // wearN
  std::map<int, LatheOffset> second_geometry; // second_geometryN
  std::map<int, LatheOffset> edge;            // Siemens DIN: D<n> = {...}, cutting edge n
  friend bool operator==(const LatheOffsetRegisters&, const LatheOffsetRegisters&) = default;
};

struct MachineConfig {
  std::vector<AxisConfig> axes;          // in order; at most kMaxAxes
  ToolOffsetRegisters tool_offsets;
  LatheOffsetRegisters lathe_offsets;
  // Work offsets by name: "G54".."G59", "G54.1P1".."G54.1P48" (FANUC/Mazak additional),
  // "G54P1".."G54P93" (Siemens ISO). Machine coordinates of the work zero, per axis index.
  std::map<std::string, AxisValues> work_offsets;
  AxisValues start_position{};           // machine position before the program starts
  double ipo_cycle_seconds = 0.001;      // interpolation cycle T
  // Largest distance (mm) between an arc and the chords joining consecutive IPO setpoints; the
  // planner lowers the feed on small arcs to keep it. Machine file: [machine] chord_tolerance.
  double chord_tolerance = 0.001;
  // G64 continuous path: largest distance (mm) between the path and the programmed corner of
  // two lines; the planner replaces the corner by a curvature-continuous blend within it.
  // 0: corners stop. Machine file: [machine] corner_tolerance.
  double corner_tolerance = 0.01;
  // Most motion segments the VM's look-ahead holds (a line, a corner blend, an arc each take
  // one). The planner keeps a stop within what it holds, so with short segments this bounds
  // the speed: a circle r 10 in 0.01 mm chords at F6000 brakes over about 6.7 mm, 670 of
  // its chords; with 256 it stays below 90 mm/s. Each takes about 2 KB. Machine file:
  // [machine] lookahead_segments, from kMinLookaheadSegments (what one line may queue, with
  // room to plan) to kMaxLookaheadSegments (about 32 MB).
  int lookahead_segments = 1024;
  static constexpr int kMinLookaheadSegments = 16, kMaxLookaheadSegments = 16384;
  ParameterSet params;                   // [machine.params]
  // [machine.probe] (or `ncc run --probe`): where the simulated skip signal of G31 comes on.
  // Run-time only: not hashed.
  ProbeConfig probe;
  // [machine.signals] (or `ncc run --signal`): the interface input signals #1000-#1035 a
  // program reads. Run-time only: not hashed.
  InputSignals signals;
  // [machine] dialect: the language of the machine's programs, when the file names it
  // (`--dialect` overrides it). Not hashed: the bytecode header carries the dialect.
  std::optional<Dialect> dialect;

  int axisIndex(std::string_view name) const;  // -1 if not configured
  int axisCount() const { return static_cast<int>(axes.size()); }

  // Stable hash of everything that changes compiled code: axes (names, kinds, diameter,
  // travel limits), offset registers, work offsets, start position and params. Not hashed:
  // the axes' velocity/acceleration/jerk limits, servo parameters and the IPO cycle (the VM
  // reads them at run time). FNV-1a 64 over a canonical serialisation: the same on every run
  // and platform.
  // Stored in bytecode headers so a program is not run on a machine it was not compiled for.
  uint64_t configHash() const;

  friend bool operator==(const MachineConfig&, const MachineConfig&) = default;
};

// 3-axis metric mill: X Y Z linear, G54-G59 at zero, no tool offsets, every parameter default.
MachineConfig defaultMachine();

}  // namespace ncc
