// Front-end throughput on typical CAM blocks, in blocks per second (items/s):
//   ParseIsoBlock  one line -> AST (the parser alone)
//   ReadBlocks     a program buffer -> AST blocks (line splitting + parsing, BlockReader)
//   ReadAndLower   the same, then lowering to canonical IR blocks (modal state machine)
// Figures, never pass/fail: run `cmake --build build --target bench` or the binary directly.
#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include "ncc/frontend/block_reader.h"
#include "ncc/ir/ir.h"
#include "ncc/machine/machine_config.h"
#include "ncc/passes/lowering.h"
#include "ncc/support/diagnostics.h"
#include "ncc/support/source_manager.h"

namespace {

// What CAM post-processors write most: feed moves with three axes, arcs with I J, rapids.
constexpr std::array<std::string_view, 8> kCamBlocks = {
    "G1 X12.345 Y-3.21 Z-1.05 F1200.",
    "X12.845 Y-3.21 Z-1.062",
    "G1 X13.345 Y-3.21 Z-1.071",
    "G2 X15.345 Y-1.21 I0. J2.",
    "G3 X13.345 Y0.79 I-2. J0.",
    "G1 X11.5 Y0.79 Z-1.1 F800.",
    "G0 Z5.",
    "G0 X0. Y0.",
};

// A program of `blocks` lines cycling through kCamBlocks, framed by a header and M30.
std::string camProgram(size_t blocks) {
  std::string text = "G17 G21 G90 G94 G54\nS12000 M3\n";
  text.reserve(blocks * 28);
  for (size_t i = 0; i < blocks; ++i) {
    text += kCamBlocks[i % kCamBlocks.size()];
    text += '\n';
  }
  text += "M5\nM30\n";
  return text;
}

// Counts lowered IR blocks (a check that lowering ran); keeps them from being optimised away.
class CountingSink final : public ncc::ir::BlockSink {
 public:
  void accept(ncc::ir::Block&& block) override {
    benchmark::DoNotOptimize(block);
    ++count;
  }
  void finish() override {}
  size_t count = 0;
};

void BM_ParseIsoBlock(benchmark::State& state) {
  ncc::SourceManager sources;
  ncc::DiagnosticEngine diags(&sources);
  size_t i = 0;
  for (auto _ : state) {
    auto block = ncc::frontend::parseIsoBlock(kCamBlocks[i % kCamBlocks.size()], 1,
                                              static_cast<uint32_t>(i + 1), diags);
    benchmark::DoNotOptimize(block);
    ++i;
  }
  if (diags.hasErrors()) state.SkipWithError("a benchmark block did not parse");
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_ParseIsoBlock);

void BM_ReadBlocks(benchmark::State& state) {
  const size_t blocks = static_cast<size_t>(state.range(0));
  const std::string program = camProgram(blocks);
  size_t read = 0;
  for (auto _ : state) {
    ncc::SourceManager sources;
    ncc::DiagnosticEngine diags(&sources);
    uint32_t file = sources.addBuffer("bench.nc", program);
    ncc::frontend::BlockReader reader(sources, file, diags);
    while (auto block = reader.next()) {
      benchmark::DoNotOptimize(block);
      ++read;
    }
    if (diags.hasErrors()) state.SkipWithError("the benchmark program did not parse");
  }
  state.SetItemsProcessed(static_cast<int64_t>(read));
}
BENCHMARK(BM_ReadBlocks)->Arg(10'000)->Unit(benchmark::kMillisecond);

void BM_ReadAndLower(benchmark::State& state) {
  const size_t blocks = static_cast<size_t>(state.range(0));
  const std::string program = camProgram(blocks);
  const ncc::MachineConfig machine = ncc::defaultMachine();
  size_t read = 0;
  for (auto _ : state) {
    ncc::SourceManager sources;
    ncc::DiagnosticEngine diags(&sources);
    uint32_t file = sources.addBuffer("bench.nc", program);
    ncc::frontend::BlockReader reader(sources, file, diags);
    CountingSink sink;
    ncc::passes::Lowering lowering(
        {.dialect = ncc::Dialect::FanucM, .machine = &machine, .program_dir = {}}, diags, sink);
    while (auto block = reader.next()) {
      ++read;
      if (lowering.lower(*block).program_end) break;
    }
    lowering.finish();
    if (diags.hasErrors() || sink.count == 0) state.SkipWithError("the benchmark program did not lower");
  }
  state.SetItemsProcessed(static_cast<int64_t>(read));  // source blocks
}
BENCHMARK(BM_ReadAndLower)->Arg(10'000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
