// The opcode table (format.h, OpcodeInfo) that encoding, decoding, sizes, the verifier and the
// disassembler derive from: every opcode round-trips through it, its sizes are the documented
// ones (the byte format of version 2.1), its listings name only what the opcode has, and the
// listing of every opcode is the one the disassembler printed before the table.
#include <array>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "ncc/bytecode/disassembler.h"
#include "ncc/bytecode/format.h"
#include "ncc/bytecode/instruction.h"
#include "ncc/bytecode/verifier.h"
#include "test_programs.h"

namespace ncc {
namespace {

using bytecode::Opcode;
using bytecode::OpcodeInfo;
using bytecode::Operand;

std::vector<Opcode> everyOpcode() {
  std::vector<Opcode> ops;
  for (int byte = 0; byte < 256; ++byte)
    if (bytecode::opcodeInfo(static_cast<uint8_t>(byte)) != nullptr)
      ops.push_back(static_cast<Opcode>(byte));
  return ops;
}

// An instruction whose operand fields all hold distinct values that are not their defaults,
// so a field read from or written to the wrong place shows.
bytecode::Instruction sample(Opcode op, int axis_count) {
  bytecode::Instruction in;
  in.op = op;
  for (Operand kind : bytecode::opcodeInfo(op).operands()) {
    switch (kind) {
      case Operand::Flags: in.flags = bytecode::opcodeInfo(op).allowed_flags; break;
      case Operand::Plane: in.plane = bytecode::ArcPlane::YZ; break;
      case Operand::PlaneAxes:
        in.axis1 = 2;
        in.axis2 = 1;
        break;
      case Operand::Turns: in.turns = 0x01020304u; break;
      case Operand::Feed:
      case Operand::Amount:
      case Operand::Speed:
      case Operand::Constant: in.value = -1234.5678; break;
      case Operand::Target:
      case Operand::Position:
        for (int i = 0; i < axis_count; ++i) in.axes[i] = 0.125 * (i + 1) - 7.0;
        break;
      case Operand::Centre:
        in.center1 = 11.5;
        in.center2 = -22.75;
        break;
      case Operand::Mask: in.mask = 0xA5C3; break;
      case Operand::Reference: in.reference = 3; break;
      case Operand::Variable:
      case Operand::Assigned: in.variable = 0x00ABCDEFu; break;
      case Operand::JumpTarget: in.target = 0x00FEDCBAu; break;
      case Operand::Code: in.code = -0x0102030405060708LL; break;
      case Operand::Results: in.variable = 0x00ABCDEFu; break;
      case Operand::Origin:
        for (int i = 0; i < axis_count; ++i) in.origin[i] = -0.375 * (i + 1) + 9.0;
        break;
    }
  }
  return in;
}

void expectSameFields(const bytecode::Instruction& a, const bytecode::Instruction& b,
                      int axis_count, const char* mnemonic) {
  EXPECT_EQ(a.op, b.op) << mnemonic;
  EXPECT_EQ(a.flags, b.flags) << mnemonic;
  EXPECT_EQ(a.plane, b.plane) << mnemonic;
  EXPECT_EQ(a.axis1, b.axis1) << mnemonic;
  EXPECT_EQ(a.axis2, b.axis2) << mnemonic;
  EXPECT_EQ(a.turns, b.turns) << mnemonic;
  EXPECT_EQ(a.mask, b.mask) << mnemonic;
  EXPECT_EQ(a.reference, b.reference) << mnemonic;
  EXPECT_EQ(a.variable, b.variable) << mnemonic;
  EXPECT_EQ(a.target, b.target) << mnemonic;
  EXPECT_EQ(a.code, b.code) << mnemonic;
  EXPECT_EQ(std::memcmp(&a.value, &b.value, sizeof a.value), 0) << mnemonic;
  for (int i = 0; i < axis_count; ++i) EXPECT_EQ(a.axes[i], b.axes[i]) << mnemonic << " " << i;
  EXPECT_EQ(a.center1, b.center1) << mnemonic;
  EXPECT_EQ(a.center2, b.center2) << mnemonic;
  for (int i = 0; i < axis_count; ++i) EXPECT_EQ(a.origin[i], b.origin[i]) << mnemonic << " " << i;
}

TEST(OpcodeTable, EveryOpcodeRoundTripsAndItsSizeIsTheBytesWritten) {
  for (int axis_count = 1; axis_count <= kMaxAxes; ++axis_count) {
    for (Opcode op : everyOpcode()) {
      const OpcodeInfo& info = bytecode::opcodeInfo(op);
      const bytecode::Instruction in = sample(op, axis_count);
      std::vector<uint8_t> buffer(bytecode::maxInstructionSize() + 16, 0xEE);
      const uint32_t written = bytecode::encode(in, axis_count, buffer.data());
      uint32_t operand_bytes = 0;
      for (Operand kind : info.operands())
        operand_bytes += bytecode::operandSize(kind, axis_count);
      EXPECT_EQ(written, bytecode::instructionSize(op, axis_count)) << info.mnemonic;
      EXPECT_EQ(written, 1 + operand_bytes) << info.mnemonic;
      EXPECT_LE(written, bytecode::maxInstructionSize()) << info.mnemonic;
      EXPECT_EQ(buffer[written], 0xEE) << info.mnemonic << ": wrote past its size";
      EXPECT_EQ(buffer[0], static_cast<uint8_t>(op));

      bytecode::Instruction out;
      uint32_t size = 0;
      const std::span<const uint8_t> code(buffer.data(), written);
      ASSERT_EQ(bytecode::decode(code, 0, axis_count, out, size), bytecode::DecodeStatus::Ok)
          << info.mnemonic;
      EXPECT_EQ(size, written) << info.mnemonic;
      expectSameFields(in, out, axis_count, info.mnemonic);
      // One byte short is a truncated instruction, never a read past the end.
      EXPECT_EQ(bytecode::decode(code.first(written - 1), 0, axis_count, out, size),
                bytecode::DecodeStatus::Truncated)
          << info.mnemonic;
    }
  }
}

// The sizes of docs/bytecode.md ("Sizes with N axes"): the byte format of version 2.1, which
// every compiled program and the VM's pinned traces depend on.
TEST(OpcodeTable, SizesAreTheDocumentedOnes) {
  auto size = [](Opcode op, uint32_t n) { return bytecode::instructionSize(op, n); };
  for (uint32_t n = 1; n <= kMaxAxes; ++n) {
    EXPECT_EQ(size(Opcode::Rapid, n), 2 + 8 * n);
    EXPECT_EQ(size(Opcode::Line, n), 10 + 8 * n);
    EXPECT_EQ(size(Opcode::Arc, n), 33 + 8 * n);
    EXPECT_EQ(size(Opcode::RefCheck, n), 4 + 8 * n);
    EXPECT_EQ(size(Opcode::Skip, n), 14 + 16 * n);  // since 2.1
    EXPECT_EQ(size(Opcode::Dwell, n), 10u);
    for (Opcode op : {Opcode::SpindleSpeed, Opcode::ToolSelect, Opcode::MCode, Opcode::Push})
      EXPECT_EQ(size(op, n), 9u);
    for (Opcode op : {Opcode::Load, Opcode::Store, Opcode::Jump, Opcode::JumpIfFalse})
      EXPECT_EQ(size(op, n), 5u);
  }
  int one_byte = 0;
  for (Opcode op : everyOpcode()) one_byte += bytecode::opcodeInfo(op).operands().empty();
  // END, PREPARE, 12 machine functions, PUSH_VACANT, POP, 5 arithmetic, 6 CMP
  EXPECT_EQ(one_byte, 26);
  EXPECT_EQ(everyOpcode().size(), 40u);
  EXPECT_EQ(bytecode::maxInstructionSize(), 14u + 16u * kMaxAxes);  // SKIP with 9 axes
}

// ARC and REFCHECK byte by byte, as docs/bytecode.md lays them out.
TEST(OpcodeTable, OperandsAreInTheDocumentedByteOrder) {
  bytecode::Instruction arc = sample(Opcode::Arc, 2);
  std::array<uint8_t, 64> b{};
  ASSERT_EQ(bytecode::encode(arc, 2, b.data()), 49u);
  const std::vector<uint8_t> head(b.begin(), b.begin() + 9);
  EXPECT_EQ(head, (std::vector<uint8_t>{0x12, arc.flags, 2, 2, 1, 0x04, 0x03, 0x02, 0x01}));
  auto f64At = [&](int offset) {
    double v;
    uint64_t bits = 0;
    for (int i = 7; i >= 0; --i) bits = (bits << 8) | b[offset + i];
    std::memcpy(&v, &bits, 8);
    return v;
  };
  EXPECT_EQ(f64At(9), arc.value);       // feed
  EXPECT_EQ(f64At(17), arc.axes[0]);    // target[N]
  EXPECT_EQ(f64At(25), arc.axes[1]);
  EXPECT_EQ(f64At(33), arc.center1);    // centre1, centre2
  EXPECT_EQ(f64At(41), arc.center2);

  bytecode::Instruction check = sample(Opcode::RefCheck, 1);
  ASSERT_EQ(bytecode::encode(check, 1, b.data()), 12u);
  EXPECT_EQ(std::vector<uint8_t>(b.begin(), b.begin() + 4),
            (std::vector<uint8_t>{0x30, 0xC3, 0xA5, 3}));  // u16 mask (LE), u8 reference
  EXPECT_EQ(f64At(4), check.axes[0]);
}

// The table's rows agree with themselves: a listing names only operands and flags of its
// opcode and shows every operand, flags go with a flags operand, jumps with a jump target.
TEST(OpcodeTable, RowsAreConsistent) {
  std::set<std::string> mnemonics;
  for (Opcode op : everyOpcode()) {
    const OpcodeInfo& info = bytecode::opcodeInfo(op);
    EXPECT_TRUE(mnemonics.insert(info.mnemonic).second) << info.mnemonic;
    EXPECT_EQ(info.allowed_flags != 0, info.hasOperand(Operand::Flags)) << info.mnemonic;
    const bool jumps = info.flow == bytecode::Flow::Jump || info.flow == bytecode::Flow::Branch;
    EXPECT_EQ(jumps, info.hasOperand(Operand::JumpTarget)) << info.mnemonic;
    EXPECT_GE(info.pops, 0);
    EXPECT_GE(info.pushes, 0);

    std::set<std::string> placeholders;
    const std::string listing = info.listing;
    int depth = 0;
    for (std::size_t i = 0; i < listing.size(); ++i) {
      if (listing[i] == '[') ++depth;
      if (listing[i] == ']') --depth;
      EXPECT_TRUE(depth == 0 || depth == 1) << info.mnemonic << ": " << listing;
      if (listing[i] != '{') continue;
      const std::size_t close = listing.find('}', i);
      ASSERT_NE(close, std::string::npos) << info.mnemonic << ": " << listing;
      placeholders.insert(listing.substr(i + 1, close - i - 1));
      i = close;
    }
    EXPECT_EQ(depth, 0) << info.mnemonic << ": " << listing;
    // What the listing must show: every operand, except those another one shows (the
    // centre names the plane axes, the position the masked ones, a flag name a flag).
    std::set<std::string> names;
    for (Operand kind : info.operands()) names.insert(bytecode::operandName(kind));
    bool flag_named = false;
    for (const bytecode::FlagInfo& flag : bytecode::flagTable()) {
      if (placeholders.count(flag.name)) {
        EXPECT_TRUE(info.allowed_flags & flag.bit) << info.mnemonic << ": {" << flag.name << "}";
        names.insert(flag.name);
        flag_named = true;
      }
    }
    if (flag_named && !placeholders.count("flags")) names.erase("flags");
    if (info.hasOperand(Operand::Centre)) names.erase(bytecode::operandName(Operand::PlaneAxes));
    if (info.hasOperand(Operand::Position)) names.erase(bytecode::operandName(Operand::Mask));
    EXPECT_EQ(placeholders, names) << info.mnemonic << ": " << listing;
  }
  uint8_t all_flags = 0;
  for (const bytecode::FlagInfo& flag : bytecode::flagTable()) {
    EXPECT_EQ(all_flags & flag.bit, 0) << flag.name;
    all_flags |= flag.bit;
  }
  for (Opcode op : everyOpcode())
    EXPECT_EQ(bytecode::opcodeInfo(op).allowed_flags & ~all_flags, 0);
}

// Every opcode and flag listed: every_opcode.dis was printed by the disassembler before the
// opcode table (its own switch per opcode), so the table changed no listing.
TEST(OpcodeTable, EveryOpcodeListsAsBefore) {
  const bytecode::Program program = test::everyOpcodeProgram();
  std::optional<bytecode::Error> error = bytecode::verify(program);
  ASSERT_FALSE(error) << error->code << ": " << error->message;
  std::ifstream in(std::string(NCC_BACKEND_GOLDEN_DIR) + "/every_opcode.dis");
  std::stringstream golden;
  golden << in.rdbuf();
  EXPECT_EQ(bytecode::disassemble(program), golden.str());
  std::set<uint8_t> listed;
  for (uint32_t offset = 0; offset < program.code.size();) {
    bytecode::Instruction instruction;
    uint32_t size = 0;
    ASSERT_EQ(bytecode::decode(program.code, offset, 3, instruction, size),
              bytecode::DecodeStatus::Ok);
    listed.insert(static_cast<uint8_t>(instruction.op));
    offset += size;
  }
  EXPECT_EQ(listed.size(), everyOpcode().size());
}

}  // namespace
}  // namespace ncc
