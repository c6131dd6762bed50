#pragma once
// The simulated skip signal (G31): a trigger plane per axis, in machine coordinates. Read from
// [machine.probe] (machine_file.cpp) or `ncc run --probe AXIS=VALUE`; the VM applies it when it
// runs a SKIP instruction. A run-time property: not part of the configuration hash, so the
// same compiled program runs against any probe.
//
// The rule (docs/machine-file.md, [machine.probe]): the signal of axis i is on when the tool
// point is at or beyond the plane `axis i = trigger` on the far side from where the move
// started, seen in the direction the move takes that axis. A move that does not move axis i
// never turns its signal on. A skip move stops at the first point of its path where a signal
// is on: at once when one is on at its start, else where it first reaches a plane, else at
// its end point (no signal).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ncc/machine/axes.h"

namespace ncc {

struct AxisConfig;

struct ProbeConfig {
  AxisMask axes = 0;        // bit i: axis i has a trigger plane
  AxisValues trigger{};     // machine coordinates, mm or degrees
  friend bool operator==(const ProbeConfig&, const ProbeConfig&) = default;
};

// `AXIS=VALUE` (`Z=-42.5`): sets that axis' trigger. The reason when the text is not an axis
// of `axes`, `=` and a finite number within the position bound (bounds::kMaxPosition).
std::optional<std::string> setProbeFromOption(ProbeConfig& probe,
                                              const std::vector<AxisConfig>& axes,
                                              std::string_view text);

// Where a straight move stops on the probe: the fraction of the move, 0 (a signal on at the
// start) to 1, and the axis whose plane stopped it.
struct ProbeHit {
  double fraction = 0.0;
  int axis = -1;
};
// The first signal on the straight move from `from` to `to`, or nullopt when none comes on.
std::optional<ProbeHit> probeStop(const ProbeConfig& probe, const AxisValues& from,
                                  const AxisValues& to, int axis_count);
// The point where the move stops: on the hit axis exactly its trigger plane.
AxisValues probeStopPoint(const ProbeConfig& probe, const ProbeHit& hit, const AxisValues& from,
                          const AxisValues& to, int axis_count);

}  // namespace ncc
