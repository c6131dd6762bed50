#include "ncc/driver/trace.h"

#include <sstream>

#include "gtest/gtest.h"

namespace ncc::driver {
namespace {

TEST(Trace, CsvHasHeaderAndOneRowPerTickWithTimeFromTheTickNumber) {
  std::ostringstream out;
  auto writer = makeCsvTraceWriter(out, TraceHeader{{"X", "Y"}, 0.001});
  writer->sample(0, AxisValues{0.0, 0.0}, AxisValues{0.0, 0.0}, 3);
  writer->sample(1, AxisValues{0.001, -2.5}, AxisValues{0.0005, -2.49999}, 4);
  writer->finish();
  EXPECT_EQ(out.str(),
            "t,X_cmd,Y_cmd,X_act,Y_act,line\n"
            "0.000000,0.000000,0.000000,0.000000,0.000000,3\n"
            "0.001000,0.001000,-2.500000,0.000500,-2.499990,4\n");
}

TEST(Trace, BinaryRoundTripsToTheNanometre) {
  std::stringstream buffer;
  TraceHeader header{{"X", "Y", "Z"}, 0.002};
  auto writer = makeBinaryTraceWriter(buffer, header);
  std::vector<TraceSample> written;
  for (uint64_t k = 0; k < 1000; ++k) {
    TraceSample s;
    s.tick = k;
    s.commanded = AxisValues{0.0137 * k, -1000.0 + 0.5 * k, 250.000001};
    s.actual = AxisValues{0.0137 * k - 0.01, -1000.0 + 0.5 * k - 0.2, 250.0};
    writer->sample(k, s.commanded, s.actual, static_cast<uint32_t>(k / 7));
    written.push_back(s);
  }
  writer->finish();
  // Compact: a slowly moving 3-axis trace needs far fewer than the 48 bytes of raw doubles.
  EXPECT_LT(buffer.str().size(), 1000u * 20u);

  std::optional<Trace> read = readBinaryTrace(buffer);
  ASSERT_TRUE(read);
  EXPECT_EQ(read->header.axes, header.axes);
  EXPECT_EQ(read->header.tick_seconds, 0.002);
  ASSERT_EQ(read->samples.size(), written.size());
  for (size_t k = 0; k < written.size(); ++k) {
    EXPECT_EQ(read->samples[k].tick, k);
    EXPECT_EQ(read->samples[k].line, k / 7);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(read->samples[k].commanded[i], written[k].commanded[i], 0.5e-6);
      EXPECT_NEAR(read->samples[k].actual[i], written[k].actual[i], 0.5e-6);
    }
  }
}

TEST(Trace, MalformedBinaryIsRejected) {
  std::istringstream not_a_trace("NCCX");
  EXPECT_FALSE(readBinaryTrace(not_a_trace));
  std::stringstream truncated;
  auto writer = makeBinaryTraceWriter(truncated, TraceHeader{{"X"}, 0.001});
  writer->sample(0, AxisValues{1.0}, AxisValues{1.0}, 1);
  std::string bytes = truncated.str();  // no end marker
  std::istringstream in(bytes.substr(0, bytes.size() - 1));
  EXPECT_FALSE(readBinaryTrace(in));
}

}  // namespace
}  // namespace ncc::driver
