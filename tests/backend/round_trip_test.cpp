// IR -> bytes -> load -> verify -> disassemble (golden) and -> re-encode (identical bytes).
#include <fstream>
#include <sstream>
#include <vector>

#include "gtest/gtest.h"
#include "ncc/backend/bytecode_writer.h"
#include "ncc/backend/encode.h"
#include "ncc/bytecode/disassembler.h"
#include "ncc/bytecode/loader.h"
#include "ncc/bytecode/verifier.h"
#include "ncc/bytecode/writer.h"

namespace ncc {
namespace {

using MF = ir::MachineFunction;

std::vector<uint8_t> bytesOf(const std::string& s) { return {s.begin(), s.end()}; }

ir::Block block(uint32_t file, uint32_t line, ir::Operations ops,
                bool exact_stop = false) {
  ir::Block b;
  b.loc = SourceLocation{file, line, 1};
  b.exact_stop = exact_stop;
  b.ops = std::move(ops);
  return b;
}

ir::Rapid rapid(double x, double y, double z, ir::RapidType type = ir::RapidType::Linear) {
  return ir::Rapid{{x, y, z}, ir::Space::Machine, type};
}

ir::Linear line(double x, double y, double z, double feed, bool per_rev = false) {
  return ir::Linear{{x, y, z}, ir::Space::Machine, feed, per_rev};
}

// A small program touching every operation kind the IR has.
std::string compileSample(const MachineConfig& machine, SourceManager& sources) {
  const uint32_t file = sources.addBuffer("part.nc", "");
  ir::Arc arc;
  arc.to = {20.0, 10.0, -2.0};
  arc.center = {10.0, 10.0, 0.0};
  arc.space = ir::Space::Machine;
  arc.clockwise = true;
  arc.feed = 250.0;
  ir::Arc arc_zx = arc;
  arc_zx.plane = ir::Plane::ZX;
  arc_zx.clockwise = false;
  arc_zx.to = {30.0, 10.0, -2.0};
  arc_zx.center = {25.0, 0.0, -2.0};
  arc_zx.extra_turns = 2;
  ir::ReferenceCheck check;
  check.position = {0.0, 0.0, 0.0};
  check.axes = 0b101;
  check.reference = 1;

  std::ostringstream out;
  backend::BytecodeWriter writer(out, machine, Dialect::FanucM, sources);
  writer.accept(block(file, 1, {MF{MF::Kind::ToolSelect, 5, 0.0}, MF{MF::Kind::ToolChange}}));
  writer.accept(block(file, 2, {MF{MF::Kind::SpindleSpeed, 0, 1200.0}, MF{MF::Kind::SpindleCW}}));
  writer.accept(block(file, 3, {rapid(10.0, 10.0, 5.0)}));
  writer.accept(block(file, 4, {line(10.0, 10.0, -2.0, 100.0)}, /*exact_stop=*/true));
  writer.accept(block(file, 5, {arc}));
  writer.accept(block(file, 6, {arc_zx}));
  writer.accept(block(file, 7, {ir::Dwell{1.5, false}, MF{MF::Kind::CoolantOn}}));
  writer.accept(block(file, 8, {line(0.0, 0.0, -2.0, 0.2, true)}));
  writer.accept(block(file, 9, {}));  // no operations: nothing encoded, no line entry
  writer.accept(block(file, 10, {MF{MF::Kind::OtherM, 123, 0.0}, MF{MF::Kind::ProgramStop},
                                 MF{MF::Kind::OptionalStop}}));
  writer.accept(block(file, 11, {rapid(0.0, 0.0, 0.0, ir::RapidType::PerAxis), check}));
  writer.accept(block(file, 12, {MF{MF::Kind::CoolantOff}, MF{MF::Kind::SpindleStop},
                                 MF{MF::Kind::SpindleOrient}, MF{MF::Kind::SpindleCCW}}));
  writer.accept(block(file, 13, {MF{MF::Kind::ProgramEndRewind}}));
  writer.finish();
  EXPECT_TRUE(writer.ok());
  return out.str();
}

std::string readGolden(const std::string& name) {
  std::ifstream in(std::string(NCC_BACKEND_GOLDEN_DIR) + "/" + name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(RoundTrip, IrToBytecodeLoadsVerifiesAndDisassemblesToGolden) {
  MachineConfig machine = defaultMachine();
  SourceManager sources;
  const std::string bytes = compileSample(machine, sources);

  bytecode::Program program;
  std::optional<bytecode::Error> error = bytecode::load(bytesOf(bytes), program);
  ASSERT_FALSE(error) << error->code << ": " << error->message;
  bytecode::VerifyOptions options;
  options.machine = &machine;
  error = bytecode::verify(program, options);
  ASSERT_FALSE(error) << error->code << ": " << error->message;

  EXPECT_EQ(program.header.config_hash, machine.configHash());
  EXPECT_EQ(program.header.dialect, Dialect::FanucM);
  ASSERT_EQ(program.strings.size(), 2u);
  EXPECT_EQ(program.strings[1], "part.nc");
  ASSERT_EQ(program.units.size(), 1u);
  EXPECT_EQ(program.units[0].name, 1u);
  EXPECT_EQ(program.lines.size(), 12u);  // one per block with operations

  // The machine hash is not stable across machine-config changes: blank it for the golden.
  bytecode::Program listed = program;
  listed.header.config_hash = 0;
  EXPECT_EQ(bytecode::disassemble(listed), readGolden("round_trip.dis"));
}

TEST(RoundTrip, ReencodingALoadedProgramGivesIdenticalBytes) {
  MachineConfig machine = defaultMachine();
  SourceManager sources;
  const std::string bytes = compileSample(machine, sources);
  bytecode::Program program;
  ASSERT_FALSE(bytecode::load(bytesOf(bytes), program));
  std::ostringstream again;
  ASSERT_FALSE(bytecode::write(program, again));
  EXPECT_EQ(again.str(), bytes);
}

TEST(BytecodeWriter, WorkSpaceTargetIsAnInternalError) {
  MachineConfig machine = defaultMachine();
  SourceManager sources;
  const uint32_t file = sources.addBuffer("part.nc", "");
  DiagnosticEngine diags(&sources);
  std::ostringstream out;
  backend::BytecodeWriter writer(out, machine, Dialect::FanucM, sources, &diags);
  ir::Rapid work{{1.0, 2.0, 3.0}, ir::Space::Work, ir::RapidType::Linear};
  writer.accept(block(file, 4, {work}));
  writer.finish();
  EXPECT_FALSE(writer.ok());
  ASSERT_EQ(diags.diagnostics().size(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].code, "NCC9001");
  EXPECT_EQ(diags.diagnostics()[0].location.line, 4u);
  EXPECT_NE(diags.diagnostics()[0].message.find("work-space"), std::string::npos);
}

// Values beyond the format's bounds are refused at their block (NCC7017), so the compiler
// never writes a file that the verifier would refuse.
TEST(BytecodeWriter, ValuesBeyondTheBoundsAreRefusedAtTheirBlock) {
  struct Case {
    ir::Operation op;
    const char* words;
  };
  ir::Arc turns;
  turns.space = ir::Space::Machine;
  turns.feed = 100.0;
  turns.to = {1.0, 0.0, 0.0};  // a full circle from the previous block's end
  turns.center = {5.0, 0.0, 0.0};
  turns.extra_turns = 1000;
  ir::Arc centre = turns;
  centre.extra_turns = 0;
  centre.center = {0.0, -2e6, 0.0};
  const Case cases[] = {
      {ir::Rapid{{1.5e6, 0.0, 0.0}, ir::Space::Machine, ir::RapidType::Linear},
       "the X position 1500000 (machine coordinates, after offsets) is beyond +-1000000"},
      {ir::Linear{{0.0, 0.0, -1e300}, ir::Space::Machine, 100.0},
       "the Z position -1e+300"},
      {turns, "1000 extra turns of an arc (at most 999)"},
      {centre, "the arc centre (0, -2000000)"},
      {ir::Dwell{1e300, false}, "a dwell of 1e+300 s is beyond 100000"},
      {ir::Dwell{2e5, true}, "a dwell of 200000 revolutions"},
  };
  for (const Case& c : cases) {
    MachineConfig machine = defaultMachine();
    SourceManager sources;
    const uint32_t file = sources.addBuffer("part.nc", "");
    DiagnosticEngine diags(&sources);
    std::ostringstream out;
    backend::BytecodeWriter writer(out, machine, Dialect::FanucM, sources, &diags);
    writer.accept(block(file, 3, {ir::Rapid{{1.0, 0.0, 0.0}, ir::Space::Machine,
                                            ir::RapidType::Linear}}));
    writer.accept(block(file, 7, {c.op}));
    writer.finish();
    EXPECT_FALSE(writer.ok()) << c.words;
    ASSERT_EQ(diags.diagnostics().size(), 1u) << c.words;
    EXPECT_EQ(diags.diagnostics()[0].code, "NCC7017");
    EXPECT_EQ(diags.diagnostics()[0].location.line, 7u);
    EXPECT_NE(diags.diagnostics()[0].message.find(c.words), std::string::npos)
        << diags.diagnostics()[0].message;
  }
}

// The string pool names files without their folders: how the path was spelled does not
// change the file.
TEST(BytecodeWriter, StringPoolHoldsFileNamesWithoutFolders) {
  std::string first;
  for (const char* spelling : {"part.nc", "./part.nc", "/home/me/jobs/part.nc", "a/../part.nc"}) {
    MachineConfig machine = defaultMachine();
    SourceManager sources;
    const uint32_t file = sources.addFile(spelling);
    std::ostringstream out;
    backend::BytecodeWriter writer(out, machine, Dialect::FanucM, sources);
    writer.accept(block(file, 1, {ir::Rapid{{1.0, 2.0, 3.0}, ir::Space::Machine,
                                            ir::RapidType::Linear}}));
    writer.finish();
    ASSERT_TRUE(writer.ok());
    const std::string bytes = out.str();
    bytecode::Program program;
    ASSERT_FALSE(bytecode::load(std::span<const uint8_t>(
                                    reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()),
                                program));
    EXPECT_EQ(program.strings, (std::vector<std::string>{"", "part.nc"})) << spelling;
    if (first.empty()) first = bytes;
    EXPECT_EQ(bytes, first) << spelling;
  }
}

TEST(BytecodeWriter, HoleCycleIsAnInternalError) {
  // The `cycles` pass replaces every ir::HoleCycle; one reaching the backend is a pipeline
  // fault, reported (by the verifier and, behind it, the encoder), never written.
  MachineConfig machine = defaultMachine();
  SourceManager sources;
  const uint32_t file = sources.addBuffer("part.nc", "");
  DiagnosticEngine diags(&sources);
  std::ostringstream out;
  backend::BytecodeWriter writer(out, machine, Dialect::FanucM, sources, &diags);
  ir::HoleCycle cycle;
  cycle.code10 = 810;
  cycle.feed = 100.0;
  writer.accept(block(file, 3, {cycle}));
  writer.finish();
  EXPECT_FALSE(writer.ok());
  ASSERT_EQ(diags.diagnostics().size(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].code, "NCC9001");
  EXPECT_NE(diags.diagnostics()[0].message.find("hole cycle"), std::string::npos);
  // The encoder alone says the same.
  ir::Block b = block(file, 3, {cycle});
  auto encoded = backend::encodeOperation(b.ops[0], b, machine);
  ASSERT_TRUE(encoded.error.has_value());
  EXPECT_EQ(encoded.error->first, "NCC9001");
}

TEST(BytecodeWriter, ArcPlaneNeedsItsAxesOnTheMachine) {
  MachineConfig machine = defaultMachine();
  machine.axes.erase(machine.axes.begin() + 1);  // X Z: no Y, so no G17 arc
  SourceManager sources;
  const uint32_t file = sources.addBuffer("lathe.nc", "");
  DiagnosticEngine diags(&sources);
  std::ostringstream out;
  backend::BytecodeWriter writer(out, machine, Dialect::FanucT, sources, &diags);
  ir::Arc arc;
  arc.space = ir::Space::Machine;
  arc.feed = 100.0;
  writer.accept(block(file, 2, {arc}));
  EXPECT_FALSE(writer.ok());
  ASSERT_EQ(diags.diagnostics().size(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].code, "NCC9003");
}

TEST(BytecodeWriter, ZxArcUsesZAndXAsPlaneAxes) {
  MachineConfig machine = defaultMachine();
  SourceManager sources;
  const uint32_t file = sources.addBuffer("p.nc", "");
  std::ostringstream out;
  backend::BytecodeWriter writer(out, machine, Dialect::FanucM, sources);
  ir::Arc arc;
  arc.space = ir::Space::Machine;
  arc.plane = ir::Plane::ZX;
  arc.feed = 100.0;
  arc.to = {0.0, 0.0, 0.0};
  arc.center = {7.0, 99.0, 3.0};
  writer.accept(block(file, 1, {arc}));
  writer.finish();
  const std::string s = out.str();
  bytecode::Program program;
  ASSERT_FALSE(bytecode::load(bytesOf(s), program));
  bytecode::Instruction in;
  uint32_t size = 0;
  ASSERT_EQ(bytecode::decode(program.code, 0, 3, in, size), bytecode::DecodeStatus::Ok);
  EXPECT_EQ(in.op, bytecode::Opcode::Arc);
  EXPECT_EQ(in.plane, bytecode::ArcPlane::ZX);
  EXPECT_EQ(in.axis1, 2);  // Z
  EXPECT_EQ(in.axis2, 0);  // X
  EXPECT_EQ(in.center1, 3.0);
  EXPECT_EQ(in.center2, 7.0);
}

TEST(BytecodeWriter, EmptyProgramIsJustEnd) {
  MachineConfig machine = defaultMachine();
  SourceManager sources;
  std::ostringstream out;
  backend::BytecodeWriter writer(out, machine, Dialect::MazakM, sources);
  writer.finish();
  ASSERT_TRUE(writer.ok());
  const std::string s = out.str();
  bytecode::Program program;
  ASSERT_FALSE(bytecode::load(bytesOf(s), program));
  ASSERT_FALSE(bytecode::verify(program));
  EXPECT_EQ(program.code, std::vector<uint8_t>{static_cast<uint8_t>(bytecode::Opcode::End)});
  EXPECT_EQ(program.header.dialect, Dialect::MazakM);
}

// The hinted lookup (the executor's, in program order) finds what the plain one finds, for
// offsets asked in order, backwards, at random, between entries and before the first, with
// repeated offsets in the table.
TEST(LineTable, HintedLookupIsThePlainOne) {
  bytecode::Program program;
  for (uint32_t offset : {4u, 9u, 9u, 20u, 21u, 40u, 100u})
    program.lines.push_back({offset, 0, offset, 1});
  std::vector<uint32_t> asked;
  for (uint32_t o = 0; o <= 110; ++o) asked.push_back(o);
  for (uint32_t o = 110; o-- > 0;) asked.push_back(o);
  for (uint32_t k = 0; k < 500; ++k) asked.push_back((k * 7919u) % 113u);
  std::size_t hint = 0;
  for (uint32_t o : asked) {
    const bytecode::LineEntry* plain = program.lineFor(o);
    EXPECT_EQ(program.lineFor(o, hint), plain) << o;
    if (plain != nullptr) {
      EXPECT_EQ(&program.lines[hint], plain) << o;
    }
  }
  std::size_t beyond = 99;  // a hint past the table is only a hint
  EXPECT_EQ(program.lineFor(50, beyond), program.lineFor(50));
  bytecode::Program empty;
  std::size_t none = 0;
  EXPECT_EQ(empty.lineFor(3, none), nullptr);
}

}  // namespace
}  // namespace ncc
