#include "ncc/driver/trace.h"

#include <bit>
#include <cmath>
#include <cstring>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace ncc::driver {

namespace {

constexpr char kMagic[4] = {'N', 'C', 'C', 'T'};
// 2: the tick stride in the header and a source line per row (version 1 had neither).
constexpr uint8_t kVersion = 2;
constexpr double kUnitsPerMm = 1e6;  // 1 nm (1 µdeg) per stored unit; 1e6 is exact
// Positions are clamped to ±kMaxUnits (±4000 km): below 2^52, so every unit is a double.
constexpr int64_t kMaxUnits = 4'000'000'000'000'000;

// "-12.345678" from whole nanometres: the CSV's 6 decimals, never "-0.000000".
void appendMillimetres(std::string& out, int64_t units) {
  const uint64_t magnitude =
      units < 0 ? uint64_t{0} - static_cast<uint64_t>(units) : static_cast<uint64_t>(units);
  absl::StrAppend(&out, units < 0 ? "-" : "", magnitude / 1'000'000, ".");
  uint64_t fraction = magnitude % 1'000'000;
  char digits[6];
  for (int i = 5; i >= 0; --i, fraction /= 10) digits[i] = static_cast<char>('0' + fraction % 10);
  out.append(digits, 6);
}

class CsvTraceWriter : public TraceWriter {
 public:
  CsvTraceWriter(std::ostream& out, TraceHeader header)
      : TraceWriter(header.tick_every), out_(out), header_(std::move(header)) {
    out_ << 't';
    for (const std::string& axis : header_.axes) out_ << ',' << axis << "_cmd";
    for (const std::string& axis : header_.axes) out_ << ',' << axis << "_act";
    out_ << ",line\n";
  }
  void write(const TraceRow& row) override {
    // Time from the integer tick, never accumulated.
    row_.clear();
    absl::StrAppendFormat(&row_, "%.6f", static_cast<double>(row.tick) * header_.tick_seconds);
    const size_t n = header_.axes.size();
    for (size_t i = 0; i < n; ++i) appendMillimetres(row_ += ',', row.commanded[i]);
    for (size_t i = 0; i < n; ++i) appendMillimetres(row_ += ',', row.actual[i]);
    absl::StrAppend(&row_, ",", row.line, "\n");
    out_ << row_;
  }
  void finish() override { out_.flush(); }

 private:
  std::ostream& out_;
  TraceHeader header_;
  std::string row_;  // reused: no allocation per row once it has grown
};

void putVarint(std::ostream& out, uint64_t v) {
  while (v >= 0x80) {
    out.put(static_cast<char>((v & 0x7F) | 0x80));
    v >>= 7;
  }
  out.put(static_cast<char>(v));
}

// Differences are taken modulo 2^64 (unsigned), so no value of a malformed file can overflow.
uint64_t zigzag(int64_t v) { return (static_cast<uint64_t>(v) << 1) ^ static_cast<uint64_t>(v >> 63); }
int64_t unzigzag(uint64_t v) { return static_cast<int64_t>(v >> 1) ^ -static_cast<int64_t>(v & 1); }
int64_t wrappingAdd(int64_t a, int64_t b) {
  return static_cast<int64_t>(static_cast<uint64_t>(a) + static_cast<uint64_t>(b));
}
uint64_t wrappingDelta(int64_t now, int64_t before) {
  return zigzag(static_cast<int64_t>(static_cast<uint64_t>(now) - static_cast<uint64_t>(before)));
}

// Binary layout (docs/trace.md): magic "NCCT", version u8, axis count u8, tick seconds f64 (LE),
// tick stride (varint), axis names (u8 length + bytes each), then per row: a marker byte 1, for
// every axis the commanded then the actual position as zig-zag varints of the change since the
// previous row, then the source line likewise; a final marker byte 0 ends the trace.
class BinaryTraceWriter : public TraceWriter {
 public:
  BinaryTraceWriter(std::ostream& out, TraceHeader header)
      : TraceWriter(header.tick_every), out_(out), header_(std::move(header)) {
    out_.write(kMagic, 4);
    out_.put(static_cast<char>(kVersion));
    out_.put(static_cast<char>(header_.axes.size()));
    uint64_t bits = std::bit_cast<uint64_t>(header_.tick_seconds);
    for (int i = 0; i < 8; ++i) out_.put(static_cast<char>((bits >> (8 * i)) & 0xFF));
    putVarint(out_, header_.tick_every);
    for (const std::string& axis : header_.axes) {
      out_.put(static_cast<char>(axis.size()));
      out_.write(axis.data(), static_cast<std::streamsize>(axis.size()));
    }
  }
  void write(const TraceRow& row) override {
    out_.put(1);
    for (size_t i = 0; i < header_.axes.size(); ++i) {
      putVarint(out_, wrappingDelta(row.commanded[i], last_.commanded[i]));
      putVarint(out_, wrappingDelta(row.actual[i], last_.actual[i]));
    }
    putVarint(out_, wrappingDelta(row.line, last_.line));
    last_ = row;
  }
  void finish() override {
    out_.put(0);
    out_.flush();
  }

 private:
  std::ostream& out_;
  TraceHeader header_;
  TraceRow last_;
};

}  // namespace

int64_t quantiseNanometres(double value) {
  const double product = value * kUnitsPerMm;
  const double limit = static_cast<double>(kMaxUnits);
  if (!(product > -limit)) return -kMaxUnits;  // NaN too
  if (!(product < limit)) return kMaxUnits;
  // The product's own rounding error, exactly: a product that looks like a tie (n + 0.5) may
  // stand for an exact value on either side of it, which is what "%.6f" rounds. (Dividing by
  // 1e-6, not a double, moved some values next to a half nanometre to the other nanometre.)
  const double residual = std::fma(value, kUnitsPerMm, -product);
  double units = std::nearbyint(product);  // to nearest, ties to even
  if (std::abs(product - units) == 0.5 && residual != 0.0)
    units = residual > 0.0 ? std::floor(product) + 1.0 : std::floor(product);
  return static_cast<int64_t>(units);
}

void TraceWriter::sample(uint64_t tick, const AxisValues& commanded, const AxisValues& actual,
                         uint32_t line) {
  if (tick % tick_every_ != 0) return;
  TraceRow row;
  row.tick = tick;
  row.line = line;
  for (int i = 0; i < kMaxAxes; ++i) {
    row.commanded[i] = quantiseNanometres(commanded[i]);
    row.actual[i] = quantiseNanometres(actual[i]);
  }
  write(row);
}

std::unique_ptr<TraceWriter> makeCsvTraceWriter(std::ostream& out, TraceHeader header) {
  return std::make_unique<CsvTraceWriter>(out, std::move(header));
}

std::unique_ptr<TraceWriter> makeBinaryTraceWriter(std::ostream& out, TraceHeader header) {
  return std::make_unique<BinaryTraceWriter>(out, std::move(header));
}

bool TraceReader::fail(const char* code, std::string message) {
  if (!error_) error_ = TraceError{code, std::move(message), offset_};
  return false;
}

int TraceReader::get() {
  const int c = in_.get();
  if (c != std::char_traits<char>::eof()) ++offset_;
  return c == std::char_traits<char>::eof() ? -1 : c;
}

bool TraceReader::varint(uint64_t& v) {
  v = 0;
  for (int shift = 0; shift < 64; shift += 7) {
    const int c = get();
    if (c < 0) return fail("NCC0052", "malformed trace: the file ends inside a number");
    v |= static_cast<uint64_t>(c & 0x7F) << shift;
    if ((c & 0x80) == 0) return true;
  }
  return fail("NCC0052", "malformed trace: a number longer than 10 bytes");
}

bool TraceReader::open() {
  char magic[4];
  for (char& c : magic) {
    const int byte = get();
    if (byte < 0) return fail("NCC0050", "not an ncc trace: the file is shorter than its header");
    c = static_cast<char>(byte);
  }
  if (std::memcmp(magic, kMagic, 4) != 0)
    return fail("NCC0050", "not an ncc trace: it does not start with \"NCCT\"");
  const int version = get();
  if (version < 0) return fail("NCC0050", "not an ncc trace: the file is shorter than its header");
  if (version != kVersion) {
    return fail("NCC0051", absl::StrCat("trace version ", version, " is not read by this ncc (it "
                                        "reads version ", kVersion,
                                        "): write the trace again with ncc run --emit=trace"));
  }
  const int axes = get();
  if (axes < 0) return fail("NCC0052", "malformed trace: truncated header");
  if (axes > kMaxAxes)
    return fail("NCC0052", absl::StrCat("malformed trace: ", axes, " axes (at most ", kMaxAxes, ")"));
  uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) {
    const int c = get();
    if (c < 0) return fail("NCC0052", "malformed trace: truncated header");
    bits |= static_cast<uint64_t>(c) << (8 * i);
  }
  header_.tick_seconds = std::bit_cast<double>(bits);
  if (!(header_.tick_seconds > 0.0) || !std::isfinite(header_.tick_seconds))
    return fail("NCC0052", "malformed trace: the tick length is not a positive number");
  if (!varint(header_.tick_every)) return false;
  if (header_.tick_every == 0) return fail("NCC0052", "malformed trace: a tick stride of 0");
  for (int i = 0; i < axes; ++i) {
    const int length = get();
    if (length < 0) return fail("NCC0052", "malformed trace: truncated axis names");
    std::string name;
    for (int j = 0; j < length; ++j) {
      const int c = get();
      if (c < 0) return fail("NCC0052", "malformed trace: truncated axis names");
      name += static_cast<char>(c);
    }
    header_.axes.push_back(std::move(name));
  }
  return true;
}

bool TraceReader::next(TraceRow& row) {
  if (ended_ || error_) return false;
  const int marker = get();
  if (marker == 0) {
    ended_ = true;
    if (get() >= 0) return fail("NCC0052", "malformed trace: data after the end marker");
    return false;
  }
  if (marker < 0) return fail("NCC0052", "malformed trace: the file ends without its end marker");
  if (marker != 1)
    return fail("NCC0052", absl::StrFormat("malformed trace: row marker 0x%02x (expected 0 or 1)", marker));
  const int axes = static_cast<int>(header_.axes.size());
  for (int i = 0; i < axes; ++i) {
    uint64_t dc = 0, da = 0;
    if (!varint(dc) || !varint(da)) return false;
    last_.commanded[i] = wrappingAdd(last_.commanded[i], unzigzag(dc));
    last_.actual[i] = wrappingAdd(last_.actual[i], unzigzag(da));
    const auto outside = [](int64_t units) { return units < -kMaxUnits || units > kMaxUnits; };
    if (outside(last_.commanded[i]) || outside(last_.actual[i]))
      return fail("NCC0052", "malformed trace: a position beyond ±4000 km");
  }
  uint64_t dl = 0;
  if (!varint(dl)) return false;
  const int64_t line = wrappingAdd(last_.line, unzigzag(dl));
  if (line < 0 || line > int64_t{UINT32_MAX})
    return fail("NCC0052", "malformed trace: a source line out of range");
  last_.line = static_cast<uint32_t>(line);
  last_.tick = rows_++ * header_.tick_every;
  row = last_;
  return true;
}

std::optional<Trace> readBinaryTrace(std::istream& in, TraceError* error) {
  TraceReader reader(in);
  Trace trace;
  TraceRow row;
  if (reader.open()) {
    trace.header = reader.header();
    while (reader.next(row)) {
      TraceSample sample;
      sample.tick = row.tick;
      sample.line = row.line;
      for (int i = 0; i < kMaxAxes; ++i) {
        sample.commanded[i] = static_cast<double>(row.commanded[i]) / kUnitsPerMm;
        sample.actual[i] = static_cast<double>(row.actual[i]) / kUnitsPerMm;
      }
      trace.samples.push_back(sample);
    }
  }
  if (reader.error()) {
    if (error) *error = *reader.error();
    return std::nullopt;
  }
  return trace;
}

}  // namespace ncc::driver
