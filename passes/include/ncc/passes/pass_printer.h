#pragma once
// `--print-after`'s output: the blocks as they leave the named passes, on one stream, each
// run of blocks from one pass under a `; after PASS` line. Blocks stream through the passes
// one at a time, so with several passes named the output interleaves block by block; with
// one, it is that pass's whole IR under one header (what the golden tests diff).
#include <ostream>
#include <set>
#include <string>
#include <string_view>

#include "ncc/ir/ir.h"
#include "ncc/ir/printer.h"

namespace ncc::passes {

class PassPrinter {
 public:
  PassPrinter(std::ostream& out, ir::AxisNames axes) : out_(out), axes_(std::move(axes)) {}
  // An IR block as it leaves `pass`.
  void print(std::string_view pass, const ir::Block& block);
  // A stage before lowering (on AST blocks) prints its own text, one line per block.
  void printLine(std::string_view pass, std::string_view line);
  // At the end of `pass`'s stream: its header alone when it printed nothing (an empty program
  // still shows which pass it is).
  void finish(std::string_view pass);

 private:
  void header(std::string_view pass);

  std::ostream& out_;
  ir::AxisNames axes_;
  std::string current_;          // the pass whose header was printed last
  std::set<std::string> shown_;  // passes whose header has been printed
};

}  // namespace ncc::passes
