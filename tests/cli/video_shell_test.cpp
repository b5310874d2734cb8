// render --video runs ffmpeg without a shell: a scene name or a path with
// quotes, semicolons or $(...) reaches ffmpeg as literal text and runs nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "cli/output_folder.h"
#include "cli_test_support.h"

namespace {

namespace fs = std::filesystem;

using namespace physdbg::clitesting;
using physdbg::visualtesting::ScratchFolder;

// Names that ran `touch` through the old shell command line.
const std::string hostileName = "x';touch MARKER1;'";
const std::string hostileFrames = "frames 50%';touch MARKER2;'";
const std::string hostileVideo = "-v';touch MARKER3;'$(touch MARKER4).mp4";

void writeHostileScene(const std::string& path) {
  writeFile(path, R"({"name": ")" + hostileName + R"(", "steps": 2,
      "bodies": [{"shape": {"sphere": {"radius": 0.5}}, "position": [0, 2, 0]}]})");
}

void expectNoMarkers(const ScratchFolder& folder) {
  for (const char* marker : {"MARKER1", "MARKER2", "MARKER3", "MARKER4"})
    EXPECT_FALSE(fs::exists(folder / marker)) << marker;
}

// "file:" keeps ffmpeg from reading a path as a protocol or an option; '%'
// is doubled because the frame pattern reads it.
TEST(VideoWithoutShell, FfmpegReceivesTheLiteralPathsAndNothingRuns) {
  ScratchFolder folder;
  writeHostileScene(folder / "evil.json");
  const std::string log = folder / "ffmpeg-arguments.txt";
  const PathPrefix path(fakeFfmpegFolder(folder, log));
  const auto exit =
      physdbgIn(folder / "", {"render", "evil.json", "--size", "64x48", "-o", hostileFrames, "--video", hostileVideo});
  ASSERT_TRUE(exit.succeeded()) << exit.describe();
  expectNoMarkers(folder);
  EXPECT_TRUE(fs::exists(folder / (hostileFrames + "/frame_00002.png")));
  const std::vector<std::string> arguments = readLines(log);
  ASSERT_FALSE(arguments.empty());
  EXPECT_NE(std::find(arguments.begin(), arguments.end(), "file:frames 50%%';touch MARKER2;'/frame_%05d.png"),
            arguments.end());
  EXPECT_EQ(arguments.back(), "file:" + hostileVideo);
}

// As on a fresh checkout with no out/ yet (scripts/demo.sh): --video creates its folder, like -o.
TEST(VideoWithoutShell, TheVideoFolderIsCreated) {
  ScratchFolder folder;
  writeHostileScene(folder / "evil.json");
  const std::string log = folder / "ffmpeg-arguments.txt";
  const PathPrefix path(fakeFfmpegFolder(folder, log));
  const auto exit = physdbgIn(folder / "", {"render", "evil.json", "--size", "64x48", "--video", "out/sub/v.mp4"});
  ASSERT_TRUE(exit.succeeded()) << exit.describe();
  EXPECT_TRUE(fs::is_directory(folder / "out/sub"));
  const std::vector<std::string> arguments = readLines(log);
  ASSERT_FALSE(arguments.empty());
  EXPECT_EQ(arguments.back(), "file:out/sub/v.mp4");
}

// The scene's name reaches ffmpeg only through the default output folder, made safe.
TEST(VideoWithoutShell, TheSceneNameInTheDefaultFolderRunsNothing) {
  ScratchFolder folder;
  writeHostileScene(folder / "evil.json");
  const std::string log = folder / "ffmpeg-arguments.txt";
  const PathPrefix path(fakeFfmpegFolder(folder, log));
  ASSERT_TRUE(physdbgIn(folder / "", {"render", "evil.json", "--size", "64x48", "--video", "v.mp4"}).succeeded());
  expectNoMarkers(folder);
  const std::string frames = physdbg::cli::sceneOutputFolder(hostileName);
  EXPECT_TRUE(fs::exists(folder / (frames + "/frame_00000.png"))) << frames;
  const std::vector<std::string> arguments = readLines(log);
  EXPECT_NE(std::find(arguments.begin(), arguments.end(), "file:" + frames + "/frame_%05d.png"), arguments.end());
}

TEST(VideoWithoutShell, RealFfmpegWritesTheVideoAtItsLiteralPath) {
  if (!physdbg::findExecutable("ffmpeg")) GTEST_SKIP() << "ffmpeg is not installed: no video is encoded here";
  ScratchFolder folder;
  writeHostileScene(folder / "evil.json");
  const auto exit =
      physdbgIn(folder / "", {"render", "evil.json", "--size", "64x48", "-o", hostileFrames, "--video", hostileVideo});
  ASSERT_TRUE(exit.succeeded()) << exit.describe();
  expectNoMarkers(folder);
  ASSERT_TRUE(fs::exists(folder / hostileVideo));
  EXPECT_GT(fs::file_size(folder / hostileVideo), 0u);
}

}  // namespace
