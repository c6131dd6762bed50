// Prints microseconds per block of the BlockReader with each parser choice on one file:
//   frontend_block_timing [file.nc] [repeats]
// A measurement for docs/frontend.md, not a test (timings are never pass/fail).
#include <chrono>
#include <cstdio>
#include <string>

#include "ncc/frontend/block_reader.h"

using namespace ncc;
using namespace ncc::frontend;

int main(int argc, char** argv) {
  std::string path = argc > 1 ? argv[1]
                              : std::string(NCC_SHARED_DIR) + "/corpus/cam-iso/camotics-tiger_tiger.nc";
  int repeats = argc > 2 ? std::stoi(argv[2]) : 3;
  SourceManager sm;
  uint32_t file = sm.addFile(path);
  for (ParserChoice choice : {ParserChoice::AntlrOnly, ParserChoice::Auto}) {
    double best_us = 1e300;
    ReaderStats stats;
    size_t errors = 0;
    for (int r = 0; r < repeats; ++r) {
      DiagnosticEngine diags(&sm);
      ReaderOptions options;
      options.parser = choice;
      auto start = std::chrono::steady_clock::now();
      BlockReader reader(sm, file, diags, options);
      while (reader.next()) {
      }
      auto end = std::chrono::steady_clock::now();
      double us = std::chrono::duration<double, std::micro>(end - start).count();
      if (us < best_us) best_us = us;
      stats = reader.stats();
      errors = diags.errorCount();
    }
    std::printf("%-10s %8llu lines %8llu blocks (%llu fast) %zu errors: %.3f us/line, %.1f ms total\n",
                choice == ParserChoice::Auto ? "auto" : "antlr-only",
                static_cast<unsigned long long>(stats.lines),
                static_cast<unsigned long long>(stats.blocks),
                static_cast<unsigned long long>(stats.fast_path_blocks), errors,
                best_us / static_cast<double>(stats.lines ? stats.lines : 1), best_us / 1000.0);
  }
  return 0;
}
