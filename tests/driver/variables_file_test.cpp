// The --vars file's reader is bounded whatever the path names: a device, a FIFO or a huge
// file is refused without reading it whole or waiting for a writer.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "gtest/gtest.h"
#include "ncc/driver/variables_file.h"

namespace ncc::driver {
namespace {

class VariablesFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("ncc-vars-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  // readVariablesFile's result, and its one diagnostic's message when it failed.
  std::optional<std::map<int64_t, SavedVariable>> read(const std::filesystem::path& path,
                                                       std::string* message = nullptr) {
    SourceManager sources;
    DiagnosticEngine diags(&sources);
    auto result = readVariablesFile(path, sources, diags);
    if (message && !diags.diagnostics().empty()) *message = diags.diagnostics()[0].message;
    return result;
  }
  std::filesystem::path dir_;
};

TEST_F(VariablesFile, AMissingFileIsEmptyAndFine) {
  EXPECT_EQ(variablesFileProblem(dir_ / "none.toml"), std::nullopt);
  auto vars = read(dir_ / "none.toml");
  ASSERT_TRUE(vars);
  EXPECT_TRUE(vars->empty());
}

TEST_F(VariablesFile, ARegularFileIsRead) {
  std::ofstream(dir_ / "v.toml") << "\"#500\" = 12.5\n";
  EXPECT_EQ(variablesFileProblem(dir_ / "v.toml"), std::nullopt);
  auto vars = read(dir_ / "v.toml");
  ASSERT_TRUE(vars);
  EXPECT_EQ(vars->at(500).value, 12.5);
}

TEST_F(VariablesFile, ADeviceIsRefused) {
  EXPECT_EQ(variablesFileProblem("/dev/zero"), "not a regular file");
  std::string message;
  EXPECT_FALSE(read("/dev/zero", &message));
  EXPECT_NE(message.find("not a regular file"), std::string::npos) << message;
}

TEST_F(VariablesFile, AFifoIsRefusedWithoutWaitingForAWriter) {
  const std::filesystem::path fifo = dir_ / "v.toml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(variablesFileProblem(fifo), "not a regular file");
  std::string message;
  EXPECT_FALSE(read(fifo, &message));  // returns: the FIFO is opened without blocking
  EXPECT_NE(message.find("not a regular file"), std::string::npos) << message;
}

TEST_F(VariablesFile, AFileOverTheLimitIsRefused) {
  const std::filesystem::path big = dir_ / "big.toml";
  std::ofstream(big).close();
  std::filesystem::resize_file(big, kMaxVariablesFileBytes + 1);  // sparse
  ASSERT_TRUE(variablesFileProblem(big));
  EXPECT_NE(variablesFileProblem(big)->find("larger than 16 MiB"), std::string::npos);
  std::string message;
  EXPECT_FALSE(read(big, &message));
  EXPECT_NE(message.find("larger than 16 MiB"), std::string::npos) << message;
  std::filesystem::resize_file(big, kMaxVariablesFileBytes);  // at the limit: read (not TOML)
  EXPECT_EQ(variablesFileProblem(big), std::nullopt);
}

}  // namespace
}  // namespace ncc::driver
