// libFuzzer target: arbitrary bytes through the BlockReader (both ';' rules, both parser
// choices, a DIN switch, and a file that starts in DIN: the DIN grammar) and printBlock. It must never crash, and the two parser choices must
// agree, which extends the differential test of the fast path to fuzz inputs.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "ncc/frontend/block_reader.h"

namespace {

struct Outcome {
  std::vector<std::string> blocks;
  std::vector<std::string> diagnostics;
};

Outcome readAll(const ncc::SourceManager& sources, uint32_t file, ncc::frontend::ReaderOptions options) {
  Outcome out;
  ncc::DiagnosticEngine diags(&sources);
  ncc::frontend::BlockReader reader(sources, file, diags, options);
  while (auto block = reader.next()) {
    out.blocks.push_back(ncc::frontend::printBlock(*block));
  }
  for (const auto& d : diags.diagnostics()) out.diagnostics.push_back(diags.format(d));
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  ncc::SourceManager sources;
  const uint32_t file =
      sources.addBuffer("fuzz.nc", std::string(reinterpret_cast<const char*>(data), size));
  for (bool semicolon_ends_block : {true, false}) {
    ncc::frontend::ReaderOptions fast, antlr;
    fast.semicolon_ends_block = antlr.semicolon_ends_block = semicolon_ends_block;
    // Siemens ISO (';' starts an annotation) switches language on G290/G291: the seam is
    // exercised where the dialect has it.
    fast.language_switch = antlr.language_switch = !semicolon_ends_block;
    antlr.parser = ncc::frontend::ParserChoice::AntlrOnly;
    Outcome a = readAll(sources, file, fast);
    Outcome b = readAll(sources, file, antlr);
    if (a.blocks != b.blocks || a.diagnostics != b.diagnostics) std::abort();  // paths disagree
  }
  // siemens-din: the file starts in DIN (the DIN parser; the ISO fast path for plain words).
  ncc::frontend::ReaderOptions fast, antlr;
  fast.semicolon_ends_block = antlr.semicolon_ends_block = false;
  fast.language_switch = antlr.language_switch = true;
  fast.initial_language = antlr.initial_language = ncc::frontend::Language::Din;
  antlr.parser = ncc::frontend::ParserChoice::AntlrOnly;
  Outcome a = readAll(sources, file, fast);
  Outcome b = readAll(sources, file, antlr);
  if (a.blocks != b.blocks || a.diagnostics != b.diagnostics) std::abort();  // paths disagree
  return 0;
}
