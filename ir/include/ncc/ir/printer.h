#pragma once
// Prints IR blocks as text (`ncc compile --emit=ir`), one block per line followed by its
// operations, with fixed formatting (3 decimals for mm, fixed field order) so golden tests can
// diff the output.
#include <ostream>
#include <string>
#include <vector>

#include "ncc/ir/ir.h"

namespace ncc::ir {

// Axis names used when printing (MachineConfig::axes order).
using AxisNames = std::vector<std::string>;

// "G17", "G18", "G19": the code of a plane, as diagnostics and the printer write it.
const char* planeCode(Plane p);

void printBlock(std::ostream& out, const Block& block, const AxisNames& axes);
std::string printBlock(const Block& block, const AxisNames& axes);

// A sink that prints every block it receives.
class PrintingSink : public BlockSink {
 public:
  PrintingSink(std::ostream& out, AxisNames axes) : out_(out), axes_(std::move(axes)) {}
  void accept(Block&& block) override { printBlock(out_, block, axes_); }
  void finish() override {}

 private:
  std::ostream& out_;
  AxisNames axes_;
};

}  // namespace ncc::ir
