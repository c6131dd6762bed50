// The verifier rejects hostile programs, each with its own code, and accepts valid ones.
#include "ncc/bytecode/verifier.h"

#include "gtest/gtest.h"
#include "test_programs.h"

namespace ncc {
namespace {

using bytecode::Assembler;
using bytecode::Opcode;

// The verifier's answer; the same program paged (test::paged, when the writer and the loader
// take it) must get exactly the same answer from the streaming passes over its file.
std::string verifyMessage(const bytecode::Program& p, const bytecode::VerifyOptions& o = {}) {
  std::optional<bytecode::Error> e = bytecode::verify(p, o);
  const std::string answer = e ? e->code + ": " + e->message : "ok";
  if (std::optional<bytecode::Program> file = test::paged(p)) {
    std::optional<bytecode::Error> f = bytecode::verify(*file, o);
    EXPECT_EQ(f ? f->code + ": " + f->message : "ok", answer) << "paged";
  }
  return answer;
}

std::string verifyCode(const bytecode::Program& p, const bytecode::VerifyOptions& o = {}) {
  const std::string answer = verifyMessage(p, o);
  return answer.substr(0, answer.find(':'));
}

TEST(Verifier, AcceptsValidProgram) { EXPECT_EQ(verifyCode(test::smallProgram()), "ok"); }

// The variable names of 2.3 (DIN's R10, COUNT): each names a variable of the program, in
// ascending order, by a string of the pool; a name table that does not is refused, and the
// paged path answers the same (the names travel through the writer and the loader).
TEST(Verifier, VariableNamesNameVariablesOfTheProgram) {
  bytecode::Program p = test::smallProgram();
  p.header.variable_count = 11001;
  p.strings.push_back("R7");
  p.strings.push_back("COUNT");
  const uint32_t r7 = static_cast<uint32_t>(p.strings.size() - 2);
  p.variable_names = {{10007, r7}, {11000, r7 + 1}};
  EXPECT_EQ(verifyCode(p), "ok");
  // (In memory only: the writer grows the header's count to hold every name it writes.)
  bytecode::Program beyond = p;
  beyond.variable_names[1].number = 11001;
  const std::optional<bytecode::Error> e = bytecode::verify(beyond, {});
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code + ": " + e->message,
            "NCC7117: variable name for #11001: not a variable of the program, or out of order");
  bytecode::Program unordered = p;
  std::swap(unordered.variable_names[0], unordered.variable_names[1]);
  EXPECT_EQ(verifyCode(unordered), "NCC7117");
  bytecode::Program zero = p;
  zero.variable_names[0].number = 0;
  EXPECT_EQ(verifyCode(zero), "NCC7117");
  bytecode::Program no_string = p;
  no_string.variable_names[1].name = 999;
  EXPECT_EQ(verifyMessage(no_string),
            "NCC7117: variable name for #11000: string 999 is not in the pool");
  bytecode::Program empty_string = p;
  empty_string.variable_names[0].name = 0;  // string 0 is ""
  EXPECT_EQ(verifyCode(empty_string), "NCC7117");
}

TEST(Verifier, RejectsUnknownOpcode) {
  bytecode::Program p = test::smallProgram();
  p.code.insert(p.code.begin(), 0x00);
  for (auto& l : p.lines) l.offset += l.offset == 0 ? 0 : 1;
  EXPECT_EQ(verifyMessage(p), "NCC7101: code offset 000000: unknown opcode 0x00");
}

TEST(Verifier, RejectsTruncatedInstruction) {
  bytecode::Program p = test::smallProgram();
  p.code.pop_back();  // END gone, LINE cut short
  p.code.pop_back();
  EXPECT_EQ(verifyCode(p), "NCC7101");
}

TEST(Verifier, RejectsEmptyCode) {
  bytecode::Program p = test::smallProgram();
  p.code.clear();
  p.lines.clear();
  EXPECT_EQ(verifyCode(p), "NCC7109");
}

TEST(Verifier, RejectsUnknownFlagBits) {
  Assembler a(test::xyzHeader());
  a.rapid({0, 0, 0}, bytecode::kFlagClockwise).op(Opcode::End);  // CW is for arcs only
  EXPECT_EQ(verifyCode(a.finish()), "NCC7102");
  // G63's fixed override (1.1) is for feed moves only.
  Assembler rapid(test::xyzHeader());
  rapid.rapid({0, 0, 0}, bytecode::kFlagFixedOverride).op(Opcode::End);
  EXPECT_EQ(verifyCode(rapid.finish()), "NCC7102");
  Assembler feed(test::xyzHeader());
  feed.line({0, 0, 1}, 100.0, bytecode::kFlagFixedOverride).op(Opcode::End);
  EXPECT_EQ(verifyCode(feed.finish()), "ok");
}

// Values no program holds (format.h, "Value bounds"): each is refused with NCC7103 and a
// message naming the bound, instead of a run that simulates for hours.
TEST(Verifier, RejectsValuesBeyondTheirBounds) {
  auto message = [](auto build) {
    Assembler a(test::xyzHeader());
    build(a);
    a.op(Opcode::End);
    return verifyMessage(a.finish());
  };
  for (double v : {1e6 + 1, 1e9, -1e12, 1e308}) {
    EXPECT_EQ(message([v](Assembler& a) { a.rapid({0, v, 0}); }).substr(0, 7), "NCC7103") << v;
    EXPECT_EQ(message([v](Assembler& a) { a.line({v, 0, 0}, 100.0); }).substr(0, 7), "NCC7103");
    EXPECT_EQ(message([v](Assembler& a) { a.arc({0, 0, 0}, 0, 1, v, 0.0, 100.0, 0); })
                  .substr(0, 7),
              "NCC7103");
    EXPECT_EQ(message([v](Assembler& a) { a.refCheck(1, 1, {0, 0, v}); }).substr(0, 7),
              "NCC7103");
  }
  EXPECT_EQ(message([](Assembler& a) { a.rapid({0, 1e9, 0}); }),
            "NCC7103: code offset 000000 (RAPID): coordinate of Y 1e+09 is beyond the bound of "
            "+-1e+06 mm (or degrees)");
  EXPECT_EQ(message([](Assembler& a) { a.dwell(1e300); }),
            "NCC7103: code offset 000000 (DWELL): dwell of 1e+300 s is beyond the bound of "
            "100000");
  EXPECT_EQ(message([](Assembler& a) { a.dwell(2e5, bytecode::kFlagRevolutions); })
                .substr(0, 7),
            "NCC7103");
  EXPECT_EQ(message([](Assembler& a) {
              a.arc({0, 0, 0}, 0, 1, 5.0, 0.0, 100.0, 0, bytecode::ArcPlane::XY, 1000000);
            }),
            "NCC7103: code offset 000000 (ARC): 1000000 extra turns (at most 999)");
  // The bounds themselves are valid.
  EXPECT_EQ(message([](Assembler& a) {
              a.rapid({1e6, -1e6, 0}).dwell(1e5);
              a.arc({1e6, -1e6, 0}, 0, 1, 1e6, 0.0, 100.0, 0, bytecode::ArcPlane::XY, 999);
            }),
            "ok");
}

TEST(Verifier, RejectsNonFiniteAndNonPositiveOperands) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  {
    Assembler a(test::xyzHeader());
    a.rapid({0, nan, 0}).op(Opcode::End);
    EXPECT_EQ(verifyCode(a.finish()), "NCC7104");
  }
  {
    Assembler a(test::xyzHeader());
    a.line({0, 0, 0}, 0.0).op(Opcode::End);
    EXPECT_EQ(verifyCode(a.finish()), "NCC7104");
  }
  {
    Assembler a(test::xyzHeader());
    a.arc({0, 0, 0}, 0, 1, inf, 0.0, 100.0, 0).op(Opcode::End);
    EXPECT_EQ(verifyCode(a.finish()), "NCC7104");
  }
  {
    Assembler a(test::xyzHeader());
    a.dwell(-1.0).op(Opcode::End);
    EXPECT_EQ(verifyCode(a.finish()), "NCC7104");
  }
  {
    Assembler a(test::xyzHeader());
    a.push(nan).op(Opcode::Pop).op(Opcode::End);
    EXPECT_EQ(verifyCode(a.finish()), "NCC7104");
  }
}

TEST(Verifier, RejectsOperandsOutOfRange) {
  {
    Assembler a(test::xyzHeader());
    a.arc({0, 0, 0}, 0, 3, 0.0, 0.0, 100.0, 0).op(Opcode::End);  // axis 3 of 3
    EXPECT_EQ(verifyCode(a.finish()), "NCC7103");
  }
  {
    Assembler a(test::xyzHeader());
    a.arc({0, 0, 0}, 1, 1, 0.0, 0.0, 100.0, 0).op(Opcode::End);  // same axis twice
    EXPECT_EQ(verifyCode(a.finish()), "NCC7103");
  }
  {
    bytecode::Instruction in;
    in.op = Opcode::Arc;
    in.plane = static_cast<bytecode::ArcPlane>(3);
    in.value = 1.0;
    Assembler a(test::xyzHeader());
    a.emit(in).op(Opcode::End);
    EXPECT_EQ(verifyCode(a.finish()), "NCC7103");
  }
  {
    Assembler a(test::xyzHeader());
    a.refCheck(0b1000, 1, {}).op(Opcode::End);  // fourth axis of three
    EXPECT_EQ(verifyCode(a.finish()), "NCC7103");
  }
  {
    Assembler a(test::xyzHeader());
    a.refCheck(0b1, 5, {}).op(Opcode::End);  // reference point 5
    EXPECT_EQ(verifyCode(a.finish()), "NCC7103");
  }
  {
    Assembler a(test::xyzHeader());
    a.mCode(-3).op(Opcode::End);
    EXPECT_EQ(verifyCode(a.finish()), "NCC7103");
  }
  {
    Assembler a(test::xyzHeader());
    a.load(10000).op(Opcode::Pop).op(Opcode::End);  // default table: #0..#9999
    EXPECT_EQ(verifyCode(a.finish()), "NCC7103");
  }
  {
    Assembler a(test::xyzHeader());
    a.push(1.0).store(0).op(Opcode::End);
    EXPECT_EQ(verifyMessage(a.finish()),
              "NCC7103: code offset 000009 (STORE): #0 cannot be assigned");
  }
}

TEST(Verifier, RejectsJumpIntoTheMiddleOfAnInstruction) {
  Assembler a(test::xyzHeader());
  bytecode::Instruction jump;
  jump.op = Opcode::Jump;
  jump.target = 2;  // inside the RAPID that follows
  a.emit(jump).rapid({0, 0, 0}).op(Opcode::End);
  EXPECT_EQ(verifyCode(a.finish()), "NCC7105");
}

TEST(Verifier, RejectsJumpPastTheCode) {
  Assembler a(test::xyzHeader());
  Assembler::Label never = a.newLabel();  // never bound
  a.jump(Opcode::Jump, never).op(Opcode::End);
  EXPECT_EQ(verifyCode(a.finish()), "NCC7105");
}

TEST(Verifier, RejectsStackUnderflow) {
  Assembler a(test::xyzHeader());
  a.push(1.0).op(Opcode::Add).op(Opcode::Pop).op(Opcode::End);
  EXPECT_EQ(verifyMessage(a.finish()),
            "NCC7106: code offset 000009 (ADD): needs 2 values, the stack holds 1");
}

TEST(Verifier, RejectsStackDeeperThanTheLimit) {
  Assembler a(test::xyzHeader());
  for (int i = 0; i <= bytecode::kMaxStackDepth; ++i) a.push(i);
  a.op(Opcode::End);
  EXPECT_EQ(verifyCode(a.finish()), "NCC7107");
}

TEST(Verifier, AcceptsStackExactlyAtTheLimit) {
  Assembler a(test::xyzHeader());
  for (int i = 0; i < bytecode::kMaxStackDepth; ++i) a.push(i);
  a.op(Opcode::End);
  EXPECT_EQ(verifyCode(a.finish()), "ok");
}

TEST(Verifier, RejectsDifferentDepthsAtAJoin) {
  // if (#1) push 1; join: the join is reached with depth 0 and with depth 1.
  Assembler a(test::xyzHeader());
  Assembler::Label join = a.newLabel();
  a.load(1).jump(Opcode::JumpIfFalse, join).push(1.0).bind(join).op(Opcode::End);
  EXPECT_EQ(verifyCode(a.finish()), "NCC7108");
}

TEST(Verifier, RejectsALoopThatGrowsTheStack) {
  Assembler a(test::xyzHeader());
  Assembler::Label top = a.newLabel();
  a.bind(top).push(1.0).load(1).jump(Opcode::JumpIfFalse, top).op(Opcode::End);
  EXPECT_EQ(verifyCode(a.finish()), "NCC7108");
}

TEST(Verifier, RejectsRunningOffTheEnd) {
  Assembler a(test::xyzHeader());
  a.rapid({1, 1, 1});
  EXPECT_EQ(verifyCode(a.finish()), "NCC7109");
}

TEST(Verifier, RejectsAProgramThatNeverEnds) {
  Assembler a(test::xyzHeader());
  Assembler::Label top = a.newLabel();
  a.bind(top).rapid({1, 1, 1}).jump(Opcode::Jump, top).op(Opcode::End);  // END unreachable
  EXPECT_EQ(verifyCode(a.finish()), "NCC7110");
}

TEST(Verifier, AcceptsUnreachableCodeAfterM30) {
  Assembler a(test::xyzHeader());
  a.op(Opcode::ProgramEndRewind).rapid({1, 1, 1}).op(Opcode::End);
  EXPECT_EQ(verifyCode(a.finish()), "ok");
}

TEST(Verifier, RejectsBadLineTable) {
  {
    bytecode::Program p = test::smallProgram();
    std::swap(p.lines[0], p.lines[1]);
    EXPECT_EQ(verifyCode(p), "NCC7111");
  }
  {
    bytecode::Program p = test::smallProgram();
    p.lines[1].offset += 1;
    EXPECT_EQ(verifyCode(p), "NCC7111");
  }
  {
    bytecode::Program p = test::smallProgram();
    p.lines[0].file = 9;
    EXPECT_EQ(verifyCode(p), "NCC7111");
  }
}

TEST(Verifier, RejectsBadUnits) {
  {
    bytecode::Program p = test::smallProgram();
    p.units[0].entry = 1;
    EXPECT_EQ(verifyCode(p), "NCC7112");
  }
  {
    bytecode::Program p = test::smallProgram();
    p.units[0].name = 5;
    EXPECT_EQ(verifyCode(p), "NCC7112");
  }
}

TEST(Verifier, ChecksTheProgramAgainstTheMachine) {
  bytecode::Program p = test::smallProgram();
  MachineConfig machine = defaultMachine();
  bytecode::VerifyOptions options;
  options.machine = &machine;
  p.header.config_hash = machine.configHash();
  EXPECT_EQ(verifyCode(p, options), "ok");

  p.header.config_hash ^= 1;
  EXPECT_EQ(verifyCode(p, options), "NCC7114");
  options.check_config_hash = false;
  EXPECT_EQ(verifyCode(p, options), "ok");

  MachineConfig renamed = machine;
  renamed.axes[2].name = "W";
  options.machine = &renamed;
  EXPECT_EQ(verifyCode(p, options), "NCC7113");

  MachineConfig four = machine;
  AxisConfig rotary;
  rotary.name = "A";
  rotary.kind = AxisKind::Rotary;
  four.axes.push_back(rotary);
  options.machine = &four;
  EXPECT_EQ(verifyCode(p, options), "NCC7113");
}

}  // namespace
}  // namespace ncc
