#pragma once
// Per-tick traces of a run (`ncc run --emit=trace -o FILE`): the commanded setpoint and the
// servo model's actual position of every axis, and the source line of the block being
// interpolated, at every IPO tick (or every Nth: --trace-every).
//
// Two encodings, chosen by the output file's extension:
// - CSV (`.csv`): a header `t,X_cmd,Y_cmd,...,X_act,Y_act,...,line`, then one row per tick, time
//   in seconds, positions in mm/deg with 6 decimals.
// - Binary (`.nct`, any other extension): compact, for long programs. Positions are stored as
//   zig-zag LEB128 varints of the change since the previous tick, so a tick of a 6-axis machine
//   typically takes 6-20 bytes. Format in docs/trace.md.
// Both print the same whole nanometres (1 µdeg): every position is quantised once, by
// quantiseNanometres, and the CSV prints that integer, so `ncc trace FILE.nct` gives the CSV
// of the same run byte for byte.
#include <array>
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
  uint64_t tick_every = 1;        // the trace holds ticks 0, N, 2N, ... (N >= 1)
};

using NanometreValues = std::array<int64_t, kMaxAxes>;

// One row of a trace as stored: positions in whole nanometres (µdeg).
struct TraceRow {
  uint64_t tick = 0;
  NanometreValues commanded{};
  NanometreValues actual{};
  uint32_t line = 0;  // source line of the block being interpolated; 0 when unknown
};

// mm (deg) to whole nanometres (µdeg), rounded as printf's "%.6f" rounds the double (to
// nearest, ties to even on the exact binary value), clamped far beyond any machine's travel.
int64_t quantiseNanometres(double value);

class TraceWriter {
 public:
  explicit TraceWriter(uint64_t tick_every) : tick_every_(tick_every == 0 ? 1 : tick_every) {}
  virtual ~TraceWriter() = default;
  // Every tick of the run in increasing order, from 0: the writer quantises the positions and
  // keeps the ticks that are multiples of the header's tick_every.
  void sample(uint64_t tick, const AxisValues& commanded, const AxisValues& actual, uint32_t line);
  // A row as stored (ticks 0, N, 2N, ... of the header's stride N, in order).
  virtual void write(const TraceRow& row) = 0;
  virtual void finish() = 0;

 private:
  uint64_t tick_every_;
};

std::unique_ptr<TraceWriter> makeCsvTraceWriter(std::ostream& out, TraceHeader header);
std::unique_ptr<TraceWriter> makeBinaryTraceWriter(std::ostream& out, TraceHeader header);

// Why a binary trace could not be read: an ncc code (NCC0050 not a trace, NCC0051 a version
// this ncc does not read, NCC0052 malformed or truncated), a message, and the byte offset.
struct TraceError {
  std::string code;
  std::string message;
  uint64_t offset = 0;
};

// Reads a binary trace row by row (memory stays flat on long traces). Never throws; a malformed
// or truncated file, or one of another version, ends with error() set.
class TraceReader {
 public:
  explicit TraceReader(std::istream& in) : in_(in) {}
  // Reads the header; false with error() set when it is not a readable trace.
  bool open();
  const TraceHeader& header() const { return header_; }
  // The next row; false at the end of the trace (error() empty) or on an error.
  bool next(TraceRow& row);
  const std::optional<TraceError>& error() const { return error_; }

 private:
  bool fail(const char* code, std::string message);
  int get();
  bool varint(uint64_t& v);

  std::istream& in_;
  TraceHeader header_;
  std::optional<TraceError> error_;
  uint64_t offset_ = 0;
  uint64_t rows_ = 0;
  bool ended_ = false;
  TraceRow last_;
};

// A whole binary trace in memory, positions back in mm (tests, small tools).
struct TraceSample {
  uint64_t tick = 0;
  AxisValues commanded{};
  AxisValues actual{};
  uint32_t line = 0;
};
struct Trace {
  TraceHeader header;
  std::vector<TraceSample> samples;
};
// nullopt on a malformed file (why in `*error` when given).
std::optional<Trace> readBinaryTrace(std::istream& in, TraceError* error = nullptr);

}  // namespace ncc::driver
