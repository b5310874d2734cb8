// End-to-end tests of physdbg compare: exit codes, printed figures, diff file.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include "render/image.h"

namespace {

namespace fs = std::filesystem;

struct Outcome {
  int exitCode = -1;
  std::string output;
};

Outcome physdbg(const std::string& arguments) {
  const std::string command = std::string(PHYSDBG_BINARY) + " " + arguments + " 2>&1";
  Outcome outcome;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return outcome;
  std::array<char, 4096> buffer{};
  while (const std::size_t read = fread(buffer.data(), 1, buffer.size(), pipe)) outcome.output.append(buffer.data(), read);
  const int status = pclose(pipe);
  outcome.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

class CompareCommand : public ::testing::Test {
 protected:
  fs::path folder = fs::temp_directory_path() / ("physdbg-compare-test-" + std::to_string(::getpid()) + "-" +
                                                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
  void SetUp() override { fs::create_directories(folder); }
  void TearDown() override { fs::remove_all(folder); }

  std::string write(const std::string& name, int markedPixels) {
    physdbg::render::Image image{40, 30, std::vector<std::uint8_t>(40 * 30 * 4, 40)};
    for (int i = 0; i < markedPixels; ++i) image.rgba[(i * 7 % 1200) * 4] = 250;
    const std::string path = (folder / name).string();
    physdbg::render::writePng(path, image);
    return path;
  }
};

TEST_F(CompareCommand, IdenticalImagesExitZero) {
  const Outcome outcome = physdbg("compare " + write("a.png", 3) + " " + write("b.png", 3));
  EXPECT_EQ(outcome.exitCode, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("identical"), std::string::npos) << outcome.output;
}

TEST_F(CompareCommand, DifferentImagesExitOneAndWriteTheDiff) {
  const std::string diff = (folder / "diff.png").string();
  const Outcome outcome = physdbg("compare " + write("a.png", 0) + " " + write("b.png", 20) + " --diff " + diff);
  EXPECT_EQ(outcome.exitCode, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("DIFFERENT"), std::string::npos) << outcome.output;
  const physdbg::render::Image image = physdbg::render::readPng(diff);
  EXPECT_EQ(image.width, 40);
  EXPECT_EQ(image.height, 30);
  // The same images pass when the allowed share covers 20 of 1200 pixels.
  EXPECT_EQ(physdbg("compare " + write("c.png", 0) + " " + write("d.png", 20) + " --max-share 0.02").exitCode, 0);
}

TEST_F(CompareCommand, BadUsageAndUnreadableFilesExitTwo) {
  const std::string a = write("a.png", 0);
  for (const std::string& arguments : {"compare " + a, "compare " + a + " " + a + " --threshold 300",
                                       "compare " + a + " " + a + " --radius -1",
                                       "compare " + a + " " + (folder / "missing.png").string()}) {
    const Outcome outcome = physdbg(arguments);
    EXPECT_EQ(outcome.exitCode, 2) << arguments << "\n" << outcome.output;
  }
}

}  // namespace
