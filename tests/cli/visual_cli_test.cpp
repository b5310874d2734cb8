// The visual-debugger options of `render` and the `tree` command end to end:
// clear messages and exit code 2 for bad input, outputs where they belong.
#include <gtest/gtest.h>

#include <fstream>

#include "render/image.h"
#include "tests/support/visual_test_support.h"

namespace {

using namespace physdbg::visualtesting;

TEST(VisualCli, BadArgumentsExitTwoNamingTheProblem) {
  ScratchFolder folder;
  const std::string out = " -o " + (folder / "out");
  struct Case {
    std::string arguments, mentions;
  };
  for (const Case& c : {Case{"render bounce --layers shapes,sparkles" + out, "sparkles"},
                        Case{"render bounce --size 0x10" + out, "--size"},
                        Case{"render bounce --size big" + out, "--size"},
                        Case{"render bounce -o /proc/physdbg-not-here", "/proc/physdbg-not-here"},
                        Case{"render bounce --frames 3:3" + out, "--frames"},
                        Case{"render bounce --frames a:b" + out, "--frames"},
                        Case{"render bounce --tree-depth 4:2" + out, "--tree-depth"},
                        Case{"render bounce --tree-depth 3" + out, "--tree-depth"},
                        Case{"render bounce --follow 999" + out, "--follow"},
                        Case{"render bounce --eye 1,2" + out, "--eye"},
                        Case{"render bounce --target 1,2,x" + out, "--target"},
                        Case{"render bounce --fov 200" + out, "--fov"},
                        Case{"render bounce --eye 0,0,0 --target 0,0,0" + out, "camera"},
                        Case{"tree bounce --size 100x100" + out, "--size"},
                        Case{"render bounce --backend vulkan" + out, "--backend"},
                        Case{"replay run.rec --backend" + out, "--backend"},
                        Case{"tree bounce --max-events 0" + out, "--max-events"}}) {
    const Result result = runPhysdbg(c.arguments);
    EXPECT_EQ(result.exitCode, 2) << c.arguments << "\n" << result.output;
    EXPECT_NE(result.output.find(c.mentions), std::string::npos) << c.arguments << "\n" << result.output;
  }
}

TEST(VisualCli, HelpExitsZeroForTheVisualCommands) {
  for (const char* command : {"tree --help", "record --help", "replay --help"}) {
    const Result result = runPhysdbg(command);
    EXPECT_EQ(result.exitCode, 0) << command << "\n" << result.output;
    EXPECT_NE(result.output.find("usage: physdbg"), std::string::npos) << command;
  }
}

TEST(VisualCli, MissingFfmpegIsAClearUsageError) {
  ScratchFolder folder;
  // With an empty PATH the shell cannot find ffmpeg, whether or not it is installed.
  const Result result =
      runPhysdbg("render bounce --frames 1 --size 64x48 -o " + (folder / "out") + " --video " + (folder / "v.mp4"),
                 "PATH=/physdbg-no-such-folder");
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("ffmpeg is not installed"), std::string::npos) << result.output;
}

TEST(VisualCli, TreeWritesFramePairsAndThePlot) {
  ScratchFolder folder;
  const Result result = runPhysdbg("tree pyramid --size 400x300 --max-events 2 -o " + (folder / "tree"));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (const char* name : {"event_000_before.png", "event_000_after.png", "event_001_after.png", "sar_height.png"}) {
    const physdbg::render::Image image = physdbg::render::readPng(folder / ("tree/" + std::string(name)));
    EXPECT_EQ(image.width, 800) << name;
    EXPECT_EQ(image.height, 300) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(folder / "tree/event_002_before.png"));
  EXPECT_TRUE(fileBytes(folder / "tree/event_000_before.png") != fileBytes(folder / "tree/event_000_after.png"));
  EXPECT_NE(result.output.find("rotations"), std::string::npos) << result.output;
}

int countBluish(const physdbg::render::Image& image) {
  int count = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4)
    count += image.rgba[i + 2] > 200 && image.rgba[i] < 200 && image.rgba[i + 1] < 240;
  return count;
}

TEST(VisualCli, TreeDepthLimitsTheTreeLayer) {
  ScratchFolder folder;
  const std::string common = "render pyramid --frames 1 --size 160x96 --layers tree -o ";
  ASSERT_EQ(runPhysdbg(common + (folder / "all")).exitCode, 0);
  ASSERT_EQ(runPhysdbg(common + (folder / "root") + " --tree-depth 0:0").exitCode, 0);
  ASSERT_EQ(runPhysdbg(common + (folder / "none") + " --tree-depth 90:").exitCode, 0);
  const int all = countBluish(physdbg::render::readPng(folder / "all/frame_00000.png"));
  const int root = countBluish(physdbg::render::readPng(folder / "root/frame_00000.png"));
  const int none = countBluish(physdbg::render::readPng(folder / "none/frame_00000.png"));
  EXPECT_GT(root, 20);   // the root box is drawn
  EXPECT_GT(all, root);  // deeper boxes add lines
  EXPECT_EQ(none, 0);    // no node is 90 deep
}

TEST(VisualCli, FollowKeepsTheBodyAtTheCentre) {
  ScratchFolder folder;
  // bounce drops spheres onto a floor; body 1 is a sphere, falling between frames.
  const Result result = runPhysdbg("render bounce --frames 3 --steps-per-frame 20 --size 96x64 --layers shapes "
                                   "--follow 1 -o " + (folder / "follow"));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (const char* name : {"frame_00000.png", "frame_00002.png"}) {
    const physdbg::render::Image image = physdbg::render::readPng(folder / ("follow/" + std::string(name)));
    const std::size_t centre = (static_cast<std::size_t>(image.height / 2) * image.width + image.width / 2) * 4;
    const bool background = std::abs(image.rgba[centre] - 28) <= 1 && std::abs(image.rgba[centre + 1] - 31) <= 1 &&
                            std::abs(image.rgba[centre + 2] - 36) <= 1;
    EXPECT_FALSE(background) << name << ": the followed body should cover the centre";
  }
  const Result ortho = runPhysdbg("render bounce --frames 1 --size 96x64 --layers shapes --ortho --eye 0,30,0.1 "
                                  "--target 0,0,0 --fov 30 -o " + (folder / "ortho"));
  ASSERT_EQ(ortho.exitCode, 0) << ortho.output;
}

// A body that joins the run at step 2 and leaves at step 4 is drawn in
// frames 2 and 3 only, at the centre the camera looks at; the recording of
// the same run marks it absent in the other frames.
TEST(VisualCli, BodiesAppearAndDisappearWithTheirLifetimes) {
  ScratchFolder folder;
  std::ofstream(folder / "visit.json") << R"({"gravity": [0, 0, 0], "camera": {"eye": [0, 0, 5], "target": [0, 0, 0]},
      "bodies": [{"shape": {"sphere": {"radius": 0.2}}, "position": [2, 0, 0]},
                 {"shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}}, "add_at_step": 2, "remove_at_step": 4}]})";
  const Result result =
      runPhysdbg("render " + (folder / "visit.json") + " --frames 6 --size 64x48 --layers shapes -o " + (folder / "out"));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (int frame = 0; frame < 6; ++frame) {
    const physdbg::render::Image image =
        physdbg::render::readPng(folder / ("out/frame_0000" + std::to_string(frame) + ".png"));
    const std::size_t centre = (static_cast<std::size_t>(image.height / 2) * image.width + image.width / 2) * 4;
    const bool background = std::abs(image.rgba[centre] - 28) <= 1 && std::abs(image.rgba[centre + 1] - 31) <= 1 &&
                            std::abs(image.rgba[centre + 2] - 36) <= 1;
    EXPECT_EQ(background, frame < 2 || frame >= 4) << "frame " << frame;
  }
}

}  // namespace
