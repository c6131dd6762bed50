#pragma once
// Per-tick traces of a run (`ncc run --emit=trace -o FILE`): the commanded setpoint and the
// servo model's actual position of every axis at every IPO tick.
//
// Two encodings, chosen by the output file's extension:
// - CSV (`.csv`): a header `t,X_cmd,Y_cmd,...,X_act,Y_act,...`, then one row per tick, time in
//   seconds, positions in mm/deg with 6 decimals.
// - Binary (`.nct`, any other extension): compact, for long programs. Positions are quantised to
//   1 nm (1 µdeg) and stored as zig-zag LEB128 varints of the change since the previous tick, so a
//   tick of a 6-axis machine typically takes 6-20 bytes. Format in docs/trace.md.
#include <cstdint>
#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "ncc/machine/axes.h"

namespace ncc::driver {

struct TraceHeader {
  std::vector<std::string> axes;  // names, machine order
  double tick_seconds = 0.001;    // IPO cycle
};

class TraceWriter {
 public:
  virtual ~TraceWriter() = default;
  // Ticks must be written in increasing order, starting at 0.
  virtual void sample(uint64_t tick, const AxisValues& commanded, const AxisValues& actual) = 0;
  virtual void finish() = 0;
};

std::unique_ptr<TraceWriter> makeCsvTraceWriter(std::ostream& out, TraceHeader header);
std::unique_ptr<TraceWriter> makeBinaryTraceWriter(std::ostream& out, TraceHeader header);

// Reads a binary trace back (tests, tools). Returns nullopt on a malformed file.
struct TraceSample {
  uint64_t tick = 0;
  AxisValues commanded{};
  AxisValues actual{};
};
struct Trace {
  TraceHeader header;
  std::vector<TraceSample> samples;
};
std::optional<Trace> readBinaryTrace(std::istream& in);

}  // namespace ncc::driver
