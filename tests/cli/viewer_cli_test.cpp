// One body in focus and replay as a viewer, end to end through the physdbg
// command: --highlight and --labels change the picture, a replay with other
// layers, focus or camera draws what a render with them draws, and what a
// recording cannot give is refused with a reason.
#include <gtest/gtest.h>

#include <string>

#include "cli_test_support.h"
#include "render/image.h"

namespace {

using physdbg::visualtesting::fileBytes;
using physdbg::visualtesting::Result;
using physdbg::visualtesting::runPhysdbg;
using physdbg::visualtesting::ScratchFolder;

const std::string small = " --size 160x120 --no-timing";

// Pixels that differ between two PNGs of one size.
int differingPixels(const std::string& a, const std::string& b) {
  const physdbg::render::Image first = physdbg::render::readPng(a), second = physdbg::render::readPng(b);
  if (first.width != second.width || first.height != second.height) return -1;
  int count = 0;
  for (std::size_t i = 0; i < first.rgba.size(); i += 4)
    count += first.rgba[i] != second.rgba[i] || first.rgba[i + 1] != second.rgba[i + 1] ||
             first.rgba[i + 2] != second.rgba[i + 2];
  return count;
}

Result succeed(const std::string& arguments) {
  const Result result = runPhysdbg(arguments);
  EXPECT_EQ(result.exitCode, 0) << arguments << "\n" << result.output;
  return result;
}

TEST(ViewerCli, HighlightChangesThePicture) {
  ScratchFolder folder;
  succeed("render stack --frames 1" + small + " -o " + (folder / "plain"));
  succeed("render stack --frames 1 --highlight 3" + small + " -o " + (folder / "focus"));
  EXPECT_GT(differingPixels(folder / "plain/frame_00000.png", folder / "focus/frame_00000.png"), 500);
}

TEST(ViewerCli, LabelsDrawText) {
  ScratchFolder folder;
  succeed("render stack --frames 1 --layers shapes" + small + " -o " + (folder / "plain"));
  succeed("render stack --frames 1 --layers shapes --labels" + small + " -o " + (folder / "labels"));
  EXPECT_GT(differingPixels(folder / "plain/frame_00000.png", folder / "labels/frame_00000.png"), 50);
}

// The viewer's choices made at replay equal the same choices made at render:
// layers, tree depth, focus, labels, camera and follow.
TEST(ViewerCli, ReplayWithOtherOptionsEqualsRenderWithThem) {
  ScratchFolder folder;
  succeed("record stack --frames 12 --steps-per-frame 4" + small + " -o " + (folder / "stack.rec"));
  for (const std::string& options :
       {std::string(" --layers shapes,contacts,overlay"), std::string(" --layers aabbs,tree --tree-depth 1:2"),
        std::string(" --layers shapes,overlay --highlight 2,5 --labels"),
        std::string(" --layers wire,fat --eye 6,4,9 --target 0,1,0 --fov 30"),
        std::string(" --layers shapes --follow 4 --ortho")}) {
    const std::string rendered = folder / "render", replayed = folder / "replay";
    succeed("render stack --frames 12 --steps-per-frame 4" + small + options + " -o " + rendered);
    succeed("replay " + (folder / "stack.rec") + small.substr(0, small.find(" --no-timing")) + options + " -o " +
            replayed);
    for (const char* frame : {"/frame_00000.png", "/frame_00006.png", "/frame_00011.png"})
      EXPECT_TRUE(fileBytes(rendered + frame) == fileBytes(replayed + frame)) << options << frame;
  }
}

TEST(ViewerCli, ReplayWithoutOptionsShowsTheRecordedLayers) {
  ScratchFolder folder;
  succeed("record stack --frames 3 --layers shapes,contacts" + small + " -o " + (folder / "stack.rec"));
  succeed("render stack --frames 3 --layers shapes,contacts" + small + " -o " + (folder / "render"));
  succeed("replay " + (folder / "stack.rec") + " --size 160x120 -o " + (folder / "replay"));
  EXPECT_TRUE(fileBytes(folder / "render/frame_00002.png") == fileBytes(folder / "replay/frame_00002.png"));
}

TEST(ViewerCli, FocusOnABodyTheSceneLacksIsRefused) {
  ScratchFolder folder;
  for (const char* option : {"--highlight 999", "--highlight 1,999", "--follow 999"}) {
    const Result result = runPhysdbg(std::string("render stack --frames 1 ") + option + small + " -o " + (folder / "f"));
    EXPECT_EQ(result.exitCode, 2) << option << "\n" << result.output;
    EXPECT_NE(result.output.find("no body 999"), std::string::npos) << result.output;
  }
  for (const char* option : {"--highlight ''", "--highlight 1,", "--highlight 1,1", "--highlight x", "--samples 3"}) {
    const Result result = runPhysdbg(std::string("render stack --frames 1 ") + option + small + " -o " + (folder / "f"));
    EXPECT_EQ(result.exitCode, 2) << option << "\n" << result.output;
  }
  succeed("record stack --frames 2" + small + " -o " + (folder / "stack.rec"));
  const Result replay = runPhysdbg("replay " + (folder / "stack.rec") + " --highlight 999 -o " + (folder / "r"));
  EXPECT_EQ(replay.exitCode, 2) << replay.output;
  EXPECT_NE(replay.output.find("no body 999"), std::string::npos) << replay.output;
}

// The recording run showed no tree: a depth range alone would draw nothing.
TEST(ViewerCli, ReplayTreeDepthNeedsTheTreeLayer) {
  ScratchFolder folder;
  succeed("record stack --frames 2 --layers shapes" + small + " -o " + (folder / "stack.rec"));
  const Result refused = runPhysdbg("replay " + (folder / "stack.rec") + " --tree-depth 1:2 -o " + (folder / "r"));
  EXPECT_EQ(refused.exitCode, 2) << refused.output;
  EXPECT_NE(refused.output.find("--tree-depth"), std::string::npos) << refused.output;
  succeed("replay " + (folder / "stack.rec") + " --tree-depth 1:2 --layers shapes,tree --size 64x48 -o " +
          (folder / "ok"));
}

TEST(ViewerCli, RecordLeavesFocusToReplay) {
  ScratchFolder folder;
  const Result result = runPhysdbg("record stack --frames 2 --highlight 1 -o " + (folder / "x.rec"));
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("--highlight"), std::string::npos) << result.output;
}

TEST(ViewerCli, MultisamplingSmoothsEdges) {
  ScratchFolder folder;
  succeed("render stack --frames 1 --layers wire" + small + " -o " + (folder / "aliased"));
  succeed("render stack --frames 1 --layers wire --samples 4" + small + " -o " + (folder / "smooth"));
  EXPECT_GT(differingPixels(folder / "aliased/frame_00000.png", folder / "smooth/frame_00000.png"), 100);
}

}  // namespace
