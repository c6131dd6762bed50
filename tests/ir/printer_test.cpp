#include "ncc/ir/printer.h"

#include <sstream>

#include "gtest/gtest.h"

namespace ncc::ir {
namespace {

const AxisNames kXyz = {"X", "Y", "Z"};

TEST(IrPrinter, PrintsBlockHeaderAndEveryOperationKind) {
  Block b;
  b.loc = SourceLocation{1, 12, 3};
  b.sequence = 40;
  b.modal.feed = 120.0;
  b.modal.spindle_speed = 1500.0;
  b.modal.tool = 3;
  b.modal.length_offset_h = 3;
  b.modal.length_offset_sign = 1;
  b.modal.plane = Plane::ZX;
  b.exact_stop = true;
  b.frame.work_offset = {100.0, 50.0, 0.0};
  b.frame.tool_length = {0.0, 0.0, 75.5};
  Arc arc;
  arc.to = {10.0, 0.0, -5.0};
  arc.center = {5.0, 99.0, -5.0};  // Y is not in the ZX plane: not printed
  arc.plane = Plane::ZX;
  arc.clockwise = false;
  arc.feed = 120.0;
  arc.extra_turns = 1;
  ReferenceCheck check;
  check.position = {0.0, 0.0, 0.0};
  check.axes = 0b011;
  check.reference = 2;
  b.ops = {Rapid{{1.0, 2.0, -0.0001}, Space::Machine, RapidType::PerAxis},
           Linear{{1.0, 2.0, -3.25}, Space::Work, 120.0, false},
           arc,
           Dwell{2.0, true},
           MachineFunction{MachineFunction::Kind::SpindleCW, 0, 0.0},
           MachineFunction{MachineFunction::Kind::OtherM, 140, 0.0},
           MachineFunction{MachineFunction::Kind::SpindleSpeed, 0, 1500.0},
           MachineFunction{MachineFunction::Kind::ToolSelect, 3, 0.0},
           MachineFunction{MachineFunction::Kind::ProgramEndRewind, 0, 0.0},
           check};
  EXPECT_EQ(printBlock(b, kXyz),
            "block 1:12:3 N40 G18 G90 G21 G94 G64 G54 G43 H3 T3 F120.000 S1500.000 exact-stop "
            "offset(X100.000 Y50.000 Z0.000) tool(X0.000 Y0.000 Z75.500)\n"
            "  rapid machine X1.000 Y2.000 Z0.000 per-axis\n"
            "  line work X1.000 Y2.000 Z-3.250 F120.000\n"
            "  arc work G18 ccw X10.000 Y0.000 Z-5.000 centre X5.000 Z-5.000 F120.000 turns 1\n"
            "  dwell 2.000 rev\n"
            "  M03\n"
            "  M140\n"
            "  S1500.000\n"
            "  T3\n"
            "  M30\n"
            "  refcheck ref2 X0.000 Y0.000\n");
}

TEST(IrPrinter, DefaultBlockWithoutSequenceOrFrame) {
  Block b;
  b.loc = SourceLocation{2, 1, 1};
  std::ostringstream out;
  PrintingSink sink(out, kXyz);
  sink.accept(std::move(b));
  sink.finish();
  EXPECT_EQ(out.str(), "block 2:1:1 G17 G90 G21 G94 G64 G54 G49 H0 T0 F0.000 S0.000\n");
}

}  // namespace
}  // namespace ncc::ir
