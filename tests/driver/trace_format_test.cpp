// Trace format v2 (docs/trace.md): positions quantised once, as "%.6f" rounds them, so the CSV
// and the binary trace hold the same nanometres; the tick stride and the source line column;
// every malformed or old binary trace is an error with its code, never a crash.
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>

#include "gtest/gtest.h"
#include "ncc/driver/trace.h"

namespace ncc::driver {
namespace {

std::string printed(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.6f", value);
  return text;
}

std::string fromUnits(int64_t units) {
  char text[64];
  std::snprintf(text, sizeof text, "%s%lld.%06lld", units < 0 ? "-" : "",
                static_cast<long long>(std::llabs(units) / 1000000),
                static_cast<long long>(std::llabs(units) % 1000000));
  return text;
}

TEST(TraceFormat, QuantisingRoundsAsPrintfDoesAtHalfNanometres) {
  // Values next to n + 1/2 nm, where dividing by 1e-6 (the old quantiser) picked the other
  // nanometre for about one value in 20,000: every neighbour must round as "%.6f" prints it.
  std::mt19937_64 random(21);
  std::uniform_int_distribution<int64_t> units(-2'000'000'000, 2'000'000'000);
  int checked = 0;
  for (int i = 0; i < 200000; ++i) {
    double value = (static_cast<double>(units(random)) + 0.5) / 1e6;
    for (int step = 0; step < 3; ++step, value = std::nextafter(value, INFINITY)) {
      const std::string expected = printed(value);
      if (expected == "-0.000000") continue;  // the CSV never writes -0 (below)
      ASSERT_EQ(fromUnits(quantiseNanometres(value)), expected) << std::hexfloat << value;
      ++checked;
    }
  }
  EXPECT_GT(checked, 500000);
  // Exact binary ties (k/128 mm) go to the even nanometre, as printf's do.
  EXPECT_EQ(quantiseNanometres(0.0078125), 7812);
  EXPECT_EQ(quantiseNanometres(-0.0234375), -23438);
}

TEST(TraceFormat, CsvNeverWritesMinusZero) {
  std::ostringstream out;
  auto writer = makeCsvTraceWriter(out, TraceHeader{{"X"}, 0.001, 1});
  writer->sample(0, AxisValues{-1e-9}, AxisValues{-0.0}, 0);
  writer->finish();
  EXPECT_EQ(out.str(), "t,X_cmd,X_act,line\n0.000000,0.000000,0.000000,0\n");
}

// The same samples through both writers, the binary read back and written as CSV.
TEST(TraceFormat, BinaryConvertedToCsvIsTheCsvByteForByte) {
  const TraceHeader header{{"X", "Y", "C"}, 0.001, 1};
  std::ostringstream csv;
  std::stringstream binary;
  auto direct = makeCsvTraceWriter(csv, header);
  auto compact = makeBinaryTraceWriter(binary, header);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> noise(-1e-6, 1e-6);
  for (uint64_t k = 0; k < 20000; ++k) {
    const double t = static_cast<double>(k) * 0.001;
    const AxisValues c{100.0 * std::sin(t), -50.0 + 3.7 * t, 0.0078125 * static_cast<double>(k % 3)};
    const AxisValues a{c[0] + noise(random), c[1] - 0.0000005, c[2] + noise(random)};
    const uint32_t line = static_cast<uint32_t>(10 + (k / 1000) * 3 % 17);
    direct->sample(k, c, a, line);
    compact->sample(k, c, a, line);
  }
  direct->finish();
  compact->finish();

  TraceReader reader(binary);
  ASSERT_TRUE(reader.open());
  EXPECT_EQ(reader.header().axes, header.axes);
  std::ostringstream converted;
  auto writer = makeCsvTraceWriter(converted, reader.header());
  TraceRow row;
  while (reader.next(row)) writer->write(row);
  writer->finish();
  ASSERT_FALSE(reader.error()) << reader.error()->message;
  EXPECT_EQ(converted.str(), csv.str());
}

TEST(TraceFormat, EveryNthTickWithItsStrideAndLine) {
  const TraceHeader header{{"X"}, 0.002, 10};
  std::ostringstream csv;
  std::stringstream binary;
  auto a = makeCsvTraceWriter(csv, header);
  auto b = makeBinaryTraceWriter(binary, header);
  for (uint64_t k = 0; k < 35; ++k) {
    a->sample(k, AxisValues{0.5 * static_cast<double>(k)}, AxisValues{}, static_cast<uint32_t>(k));
    b->sample(k, AxisValues{0.5 * static_cast<double>(k)}, AxisValues{}, static_cast<uint32_t>(k));
  }
  a->finish();
  b->finish();
  EXPECT_EQ(csv.str(),
            "t,X_cmd,X_act,line\n"
            "0.000000,0.000000,0.000000,0\n"
            "0.020000,5.000000,0.000000,10\n"
            "0.040000,10.000000,0.000000,20\n"
            "0.060000,15.000000,0.000000,30\n");
  std::optional<Trace> read = readBinaryTrace(binary);
  ASSERT_TRUE(read);
  EXPECT_EQ(read->header.tick_every, 10u);
  ASSERT_EQ(read->samples.size(), 4u);
  for (uint64_t i = 0; i < 4; ++i) {
    EXPECT_EQ(read->samples[i].tick, 10 * i);
    EXPECT_EQ(read->samples[i].line, 10 * i);
    EXPECT_EQ(read->samples[i].commanded[0], 5.0 * static_cast<double>(i));
  }
}

// The code a damaged trace is rejected with (empty when it reads).
std::string errorCode(const std::string& bytes) {
  std::istringstream in(bytes);
  TraceError error;
  if (readBinaryTrace(in, &error)) return "";
  EXPECT_FALSE(error.message.empty());
  return error.code;
}

std::string goodTrace() {
  std::stringstream out;
  auto writer = makeBinaryTraceWriter(out, TraceHeader{{"X", "Y"}, 0.001, 1});
  writer->sample(0, AxisValues{1.0, 2.0}, AxisValues{1.0, 2.0}, 5);
  writer->sample(1, AxisValues{1.5, 2.0}, AxisValues{1.2, 2.0}, 6);
  writer->finish();
  return out.str();
}

TEST(TraceFormat, DamagedTracesAreErrorsWithACode) {
  const std::string good = goodTrace();
  ASSERT_EQ(errorCode(good), "");
  // Not a trace.
  EXPECT_EQ(errorCode(""), "NCC0050");
  EXPECT_EQ(errorCode("NCC"), "NCC0050");
  EXPECT_EQ(errorCode("t,X_cmd,X_act\n0.0,0.0,0.0\n"), "NCC0050");
  // Version 1 (no stride, no line column) and unknown versions.
  std::string old = good;
  old[4] = 1;
  EXPECT_EQ(errorCode(old), "NCC0051");
  old[4] = static_cast<char>(0xFF);
  EXPECT_EQ(errorCode(old), "NCC0051");
  // Every truncation of a good trace.
  for (std::size_t n = 4; n < good.size(); ++n)
    EXPECT_EQ(errorCode(good.substr(0, n)), n < 5 ? "NCC0050" : "NCC0052") << n;
  // Too many axes, a zero or NaN tick length, a zero stride.
  std::string bad = good;
  bad[5] = 10;
  EXPECT_EQ(errorCode(bad), "NCC0052");
  bad = good;
  for (int i = 6; i < 14; ++i) bad[i] = 0;
  EXPECT_EQ(errorCode(bad), "NCC0052");
  bad = good;
  for (int i = 6; i < 14; ++i) bad[i] = static_cast<char>(0xFF);
  EXPECT_EQ(errorCode(bad), "NCC0052");
  bad = good;
  bad[14] = 0;
  EXPECT_EQ(errorCode(bad), "NCC0052");
  // A bad row marker, data after the end, an over-long number, a position out of range.
  const std::size_t first_row = 14 + 1 + 2 + 2;
  bad = good;
  bad[first_row] = 7;
  EXPECT_EQ(errorCode(bad), "NCC0052");
  EXPECT_EQ(errorCode(good + "x"), "NCC0052");
  bad = good.substr(0, first_row + 1) + std::string(11, static_cast<char>(0x80)) + '\0';
  EXPECT_EQ(errorCode(bad), "NCC0052");
  bad = good.substr(0, first_row + 1) + std::string(9, static_cast<char>(0xFF)) + '\x01' +
        std::string(4, '\0') + '\0';
  EXPECT_EQ(errorCode(bad), "NCC0052");
}

TEST(TraceFormat, RandomBytesNeverCrash) {
  const std::string good = goodTrace();
  std::mt19937 random(3);
  for (int i = 0; i < 20000; ++i) {
    std::string bytes = good;
    const int flips = 1 + static_cast<int>(random() % 4);
    for (int f = 0; f < flips; ++f)
      bytes[random() % bytes.size()] = static_cast<char>(random() & 0xFF);
    std::istringstream in(bytes);
    TraceError error;
    if (!readBinaryTrace(in, &error)) {
      EXPECT_FALSE(error.code.empty());
    }
  }
}

}  // namespace
}  // namespace ncc::driver
