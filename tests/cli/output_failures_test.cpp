// An output path that cannot be written is bad input like any other: exit 2
// with a message naming the option and the path, whichever command it is.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli_test_support.h"
#include "render/image.h"

namespace {

using physdbg::clitesting::fakeFfmpegFolder;
using physdbg::clitesting::writeFile;
using physdbg::visualtesting::Result;
using physdbg::visualtesting::runPhysdbg;
using physdbg::visualtesting::ScratchFolder;

TEST(OutputFailures, ExitTwoNamingTheOptionAndThePath) {
  ScratchFolder folder;
  const std::string image = folder / "a.png";
  physdbg::render::writePng(image, {16, 16, std::vector<std::uint8_t>(16 * 16 * 4, 128)});
  const std::string file = folder / "plain-file";
  writeFile(file, "x");
  const std::string directory = folder / "";
  const std::string render = "render default --frames 1 --size 64x48 -o " + (folder / "f");
  struct Case {
    std::string arguments, option, path;
  };
  for (const Case& c :
       {Case{"simulate default --steps 2 --trace /dev/full", "--trace", "/dev/full"},
        Case{"simulate default --steps 2 --trace " + (folder / "no/t.csv"), "--trace", folder / "no/t.csv"},
        Case{"compare " + image + " " + image + " --diff " + directory, "--diff", directory},
        Case{"compare " + image + " " + image + " --diff /dev/full", "--diff", "/dev/full"},
        Case{"record default --frames 2 -o /dev/full", "-o", "/dev/full"},
        Case{"record default --frames 2 -o " + directory, "-o", directory},
        Case{"render default --frames 1 --size 64x48 -o " + file, "-o", file},
        Case{render + " --video " + file + "/v.mp4", "--video", file},  // its folder would be a file
        Case{render + " --video " + directory, "--video", directory}, Case{"tree default -o " + file, "-o", file},
        Case{"report stages -o " + file, "-o", file}}) {
    const Result result =
        runPhysdbg(c.arguments, "PATH=" + fakeFfmpegFolder(folder, folder / "log") + ":/usr/bin:/bin");
    EXPECT_EQ(result.exitCode, 2) << c.arguments << "\n" << result.output;
    EXPECT_NE(result.output.find(c.option + ": "), std::string::npos) << c.arguments << "\n" << result.output;
    EXPECT_NE(result.output.find(c.path), std::string::npos) << c.arguments << "\n" << result.output;
  }
}

// A frame that cannot be written in the middle of a run (here a folder stands
// where frame 2 belongs; a full disk fails the same way) stops the run with
// exit 2 naming -o and the file, after the frames before it and none after.
TEST(OutputFailures, RenderStopsAtTheFirstFrameItCannotWrite) {
  ScratchFolder folder;
  const std::string output = folder / "frames";
  std::filesystem::create_directories(output + "/frame_00002.png");
  const Result result = runPhysdbg("render default --frames 6 --size 64x48 --no-timing -o " + output);
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("-o: "), std::string::npos) << result.output;
  EXPECT_NE(result.output.find(output + "/frame_00002.png"), std::string::npos) << result.output;
  EXPECT_TRUE(std::filesystem::is_regular_file(output + "/frame_00001.png"));
  for (const char* later : {"/frame_00003.png", "/frame_00004.png", "/frame_00005.png"})
    EXPECT_FALSE(std::filesystem::exists(output + later)) << later;
}

}  // namespace
