#include "ncc/driver/trace.h"

#include <bit>
#include <cmath>
#include <cstring>

#include "absl/strings/str_format.h"

namespace ncc::driver {

namespace {

constexpr char kMagic[4] = {'N', 'C', 'C', 'T'};
constexpr uint8_t kVersion = 1;
constexpr double kQuantum = 1e-6;  // mm (or deg) per stored unit: 1 nm

class CsvTraceWriter : public TraceWriter {
 public:
  CsvTraceWriter(std::ostream& out, TraceHeader header) : out_(out), header_(std::move(header)) {
    out_ << 't';
    for (const std::string& axis : header_.axes) out_ << ',' << axis << "_cmd";
    for (const std::string& axis : header_.axes) out_ << ',' << axis << "_act";
    out_ << '\n';
  }
  void sample(uint64_t tick, const AxisValues& commanded, const AxisValues& actual) override {
    // Time from the integer tick, never accumulated.
    out_ << absl::StrFormat("%.6f", static_cast<double>(tick) * header_.tick_seconds);
    const size_t n = header_.axes.size();
    for (size_t i = 0; i < n; ++i) out_ << absl::StrFormat(",%.6f", commanded[i]);
    for (size_t i = 0; i < n; ++i) out_ << absl::StrFormat(",%.6f", actual[i]);
    out_ << '\n';
  }
  void finish() override { out_.flush(); }

 private:
  std::ostream& out_;
  TraceHeader header_;
};

void putVarint(std::ostream& out, uint64_t v) {
  while (v >= 0x80) {
    out.put(static_cast<char>((v & 0x7F) | 0x80));
    v >>= 7;
  }
  out.put(static_cast<char>(v));
}

bool getVarint(std::istream& in, uint64_t& v) {
  v = 0;
  for (int shift = 0; shift < 64; shift += 7) {
    int c = in.get();
    if (c == EOF) return false;
    v |= static_cast<uint64_t>(c & 0x7F) << shift;
    if ((c & 0x80) == 0) return true;
  }
  return false;  // over-long encoding
}

uint64_t zigzag(int64_t v) { return (static_cast<uint64_t>(v) << 1) ^ static_cast<uint64_t>(v >> 63); }
int64_t unzigzag(uint64_t v) { return static_cast<int64_t>(v >> 1) ^ -static_cast<int64_t>(v & 1); }

int64_t quantise(double value) {
  double units = std::nearbyint(value / kQuantum);
  // Beyond ±9.2e12 mm the value is not a position; clamp rather than overflow.
  if (!(units > -9.0e18)) return INT64_MIN / 2;
  if (!(units < 9.0e18)) return INT64_MAX / 2;
  return static_cast<int64_t>(units);
}

// Binary layout (docs/trace.md): magic "NCCT", version u8, axis count u8, tick seconds f64 (LE),
// axis names (u8 length + bytes each), then per sample: a marker byte 1, and for every axis the
// commanded then the actual position as zig-zag varints of the change since the previous sample;
// a final marker byte 0 ends the trace. Ticks are consecutive from 0.
class BinaryTraceWriter : public TraceWriter {
 public:
  BinaryTraceWriter(std::ostream& out, TraceHeader header) : out_(out), header_(std::move(header)) {
    out_.write(kMagic, 4);
    out_.put(static_cast<char>(kVersion));
    out_.put(static_cast<char>(header_.axes.size()));
    uint64_t bits = std::bit_cast<uint64_t>(header_.tick_seconds);
    for (int i = 0; i < 8; ++i) out_.put(static_cast<char>((bits >> (8 * i)) & 0xFF));
    for (const std::string& axis : header_.axes) {
      out_.put(static_cast<char>(axis.size()));
      out_.write(axis.data(), static_cast<std::streamsize>(axis.size()));
    }
  }
  void sample(uint64_t, const AxisValues& commanded, const AxisValues& actual) override {
    out_.put(1);
    for (size_t i = 0; i < header_.axes.size(); ++i) {
      int64_t c = quantise(commanded[i]), a = quantise(actual[i]);
      putVarint(out_, zigzag(c - last_cmd_[i]));
      putVarint(out_, zigzag(a - last_act_[i]));
      last_cmd_[i] = c;
      last_act_[i] = a;
    }
  }
  void finish() override {
    out_.put(0);
    out_.flush();
  }

 private:
  std::ostream& out_;
  TraceHeader header_;
  std::array<int64_t, kMaxAxes> last_cmd_{};
  std::array<int64_t, kMaxAxes> last_act_{};
};

}  // namespace

std::unique_ptr<TraceWriter> makeCsvTraceWriter(std::ostream& out, TraceHeader header) {
  return std::make_unique<CsvTraceWriter>(out, std::move(header));
}

std::unique_ptr<TraceWriter> makeBinaryTraceWriter(std::ostream& out, TraceHeader header) {
  return std::make_unique<BinaryTraceWriter>(out, std::move(header));
}

std::optional<Trace> readBinaryTrace(std::istream& in) {
  char magic[4];
  if (!in.read(magic, 4) || std::memcmp(magic, kMagic, 4) != 0) return std::nullopt;
  if (in.get() != kVersion) return std::nullopt;
  int axes = in.get();
  if (axes < 0 || axes > kMaxAxes) return std::nullopt;
  Trace trace;
  uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) {
    int c = in.get();
    if (c == EOF) return std::nullopt;
    bits |= static_cast<uint64_t>(c) << (8 * i);
  }
  trace.header.tick_seconds = std::bit_cast<double>(bits);
  for (int i = 0; i < axes; ++i) {
    int length = in.get();
    if (length == EOF) return std::nullopt;
    std::string name(static_cast<size_t>(length), '\0');
    if (!in.read(name.data(), length)) return std::nullopt;
    trace.header.axes.push_back(std::move(name));
  }
  std::array<int64_t, kMaxAxes> cmd{}, act{};
  for (uint64_t tick = 0;; ++tick) {
    int marker = in.get();
    if (marker == 0) return trace;
    if (marker != 1) return std::nullopt;
    TraceSample sample;
    sample.tick = tick;
    for (int i = 0; i < axes; ++i) {
      uint64_t dc, da;
      if (!getVarint(in, dc) || !getVarint(in, da)) return std::nullopt;
      cmd[i] += unzigzag(dc);
      act[i] += unzigzag(da);
      sample.commanded[i] = static_cast<double>(cmd[i]) * kQuantum;
      sample.actual[i] = static_cast<double>(act[i]) * kQuantum;
    }
    trace.samples.push_back(sample);
  }
}

}  // namespace ncc::driver
