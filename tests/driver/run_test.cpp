// The driver's run side: run-time alarms, and the CLI's exit code 3 for an
// alarm raised by the VM (a program compiled by ncc today has every check done at compile
// time, so the alarm path is driven by hand-assembled bytecode).
#include <unistd.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "gtest/gtest.h"
#include "ncc/bytecode/assembler.h"
#include "ncc/bytecode/writer.h"
#include "ncc/driver/json_output.h"
#include "ncc/driver/run.h"
#include "ncc/driver/simulate.h"

namespace ncc::driver {
namespace {

bytecode::Header headerFor(const MachineConfig& machine) {
  bytecode::Header header;
  header.config_hash = machine.configHash();
  for (const AxisConfig& axis : machine.axes) header.axes.push_back({axis.name, axis.kind});
  return header;
}

AxisValues at(double x, double y, double z) { return AxisValues{x, y, z}; }

TEST(RunProgram, ReferenceCheckMismatchRaisesAnAlarmWithItsLocation) {
  MachineConfig machine = defaultMachine();
  bytecode::Assembler a(headerFor(machine));
  a.at(1, 1).rapid(at(5, 0, 0));
  a.at(1, 2, 4).refCheck(0b001, 1, at(0, 0, 0));  // X is at 5, reference point 1 at 0
  a.op(bytecode::Opcode::End);
  bytecode::Program program = a.finish();

  // Every output mode runs this simulation (one verdict); count the moves it takes.
  struct CountMoves : vm::EventObserver {
    void onEvent(const vm::Event& e) override { motions += e.kind == vm::Event::Kind::Motion; }
    int motions = 0;
  } moves;
  SimulationOptions options;
  options.observer = &moves;
  SimulationResult result = simulate(program, machine, nullptr, options);
  ASSERT_TRUE(result.error.empty()) << result.error;
  ASSERT_TRUE(result.alarm);
  EXPECT_EQ(result.alarm->code, "NCC7201");
  EXPECT_EQ(result.alarm->where.line, 2u);
  EXPECT_EQ(result.alarm->where.column, 4u);
  EXPECT_EQ(moves.motions, 1);  // the rapid before the check ran
}

TEST(JsonOutput, NumbersAreRoundedTrimmedAndNeverNegativeZero) {
  EXPECT_EQ(jsonNumber(10.0), "10.0");
  EXPECT_EQ(jsonNumber(-5.0), "-5.0");
  EXPECT_EQ(jsonNumber(0.125), "0.125");
  EXPECT_EQ(jsonNumber(1.0000004), "1.0");
  EXPECT_EQ(jsonNumber(-0.0000001), "0.0");
  EXPECT_EQ(jsonNumber(123456.7891234), "123456.789123");
}

#ifdef NCC_CLI_PATH
TEST(Cli, RunTimeAlarmExitsThreeWithDiagnostic) {
  MachineConfig machine = defaultMachine();
  std::filesystem::path dir = std::filesystem::temp_directory_path() /
                              ("ncc-driver-test-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::filesystem::path source = dir / "refcheck.nc";
  std::ofstream(source) << "G00 X5.\nG27 X5.\n";
  bytecode::Assembler a(headerFor(machine));
  a.at(1, 1).rapid(at(5, 0, 0));
  a.at(1, 2, 5).refCheck(0b001, 1, at(0, 0, 0));
  a.op(bytecode::Opcode::End);
  bytecode::Program program = a.finish({"", source.string()});
  std::filesystem::path ncb = dir / "refcheck.ncb";
  {
    std::ofstream out(ncb, std::ios::binary);
    ASSERT_FALSE(bytecode::write(program, out));
  }
  std::filesystem::path err = dir / "stderr.txt";
  std::string command = std::string(NCC_CLI_PATH) + " run " + ncb.string() + " 2> " + err.string();
  int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 3);
  std::ifstream in(err);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("refcheck.nc:2:5: error[NCC7201]"), std::string::npos) << text;
  EXPECT_NE(text.find("G27 X5."), std::string::npos) << text;  // the source line is quoted
  std::filesystem::remove_all(dir);
}
#endif

}  // namespace
}  // namespace ncc::driver
