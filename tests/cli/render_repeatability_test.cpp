// physdbg render with --no-timing writes the same PNG bytes run after run,
// overlay included (LP_NUM_THREADS fixed): what golden images rely on.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

std::string fileBytes(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

TEST(RenderRepeatability, NoTimingFramesAreByteIdenticalAcrossRuns) {
  const fs::path folder = fs::temp_directory_path() / ("physdbg-repeat-test-" + std::to_string(::getpid()));
  for (const char* run : {"a", "b"}) {
    const std::string command = std::string("LP_NUM_THREADS=1 ") + PHYSDBG_BINARY + " render default -o " +
                                (folder / run).string() +
                                " --frames 3 --steps-per-frame 10 --size 160x120 --layers shapes,aabbs,overlay "
                                "--no-timing >/dev/null 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
  }
  for (const char* frame : {"frame_00000.png", "frame_00001.png", "frame_00002.png"}) {
    const std::string first = fileBytes(folder / "a" / frame);
    EXPECT_FALSE(first.empty()) << frame;
    EXPECT_EQ(first, fileBytes(folder / "b" / frame)) << frame;
  }
  // Frames differ from each other, so equal files are not an accident of an empty picture.
  EXPECT_NE(fileBytes(folder / "a" / "frame_00000.png"), fileBytes(folder / "a" / "frame_00002.png"));
  fs::remove_all(folder);
}

}  // namespace
