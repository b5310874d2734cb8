// record/replay and frame-range splits end to end: the pictures must be the
// same bytes whichever way they were made.
#include <gtest/gtest.h>

#include "render/image.h"
#include "tests/support/visual_test_support.h"

namespace {

using namespace physdbg::visualtesting;

// No overlay: its step time differs between runs.
const std::string common = " --size 160x96 --layers shapes,aabbs,contacts ";

void expectSameFrames(const ScratchFolder& folder, const std::string& a, const std::string& b, int first, int last) {
  for (int i = first; i < last; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%05d.png", i);
    const physdbg::render::Image left = physdbg::render::readPng(folder / (a + name));
    const physdbg::render::Image right = physdbg::render::readPng(folder / (b + name));
    EXPECT_EQ(left.rgba, right.rgba) << "frame " << i << " differs between " << a << " and " << b;
  }
}

TEST(RecordReplay, ReplayDrawsTheSameImagesAsRender) {
  ScratchFolder folder;
  ASSERT_EQ(runPhysdbg("render bounce --frames 4 --steps-per-frame 10 -o " + (folder / "direct") + common).exitCode, 0);
  const Result record = runPhysdbg("record bounce --frames 4 --steps-per-frame 10 -o " + (folder / "run.rec") + common);
  ASSERT_EQ(record.exitCode, 0) << record.output;
  const Result replay = runPhysdbg("replay " + (folder / "run.rec") + " --size 160x96 -o " + (folder / "replayed"));
  ASSERT_EQ(replay.exitCode, 0) << replay.output;
  expectSameFrames(folder, "direct", "replayed", 0, 4);
  // Frames must differ from each other, or the comparison proves nothing.
  EXPECT_TRUE(fileBytes(folder / "direct/frame_00000.png") != fileBytes(folder / "direct/frame_00003.png"));
}

TEST(RecordReplay, SplitRenderMatchesOneRun) {
  ScratchFolder folder;
  ASSERT_EQ(runPhysdbg("render bounce --frames 5 --steps-per-frame 6 -o " + (folder / "whole") + common).exitCode, 0);
  ASSERT_EQ(runPhysdbg("render bounce --frames 0:2 --steps-per-frame 6 -o " + (folder / "split") + common).exitCode, 0);
  ASSERT_EQ(runPhysdbg("render bounce --frames 2:5 --steps-per-frame 6 -o " + (folder / "split") + common).exitCode, 0);
  expectSameFrames(folder, "whole", "split", 0, 5);
}

TEST(RecordReplay, ReplayRangeWritesOnlyThoseFramesWithTheirNumbers) {
  ScratchFolder folder;
  ASSERT_EQ(runPhysdbg("record bounce --frames 5 --steps-per-frame 6 -o " + (folder / "run.rec") + common).exitCode, 0);
  ASSERT_EQ(runPhysdbg("replay " + (folder / "run.rec") + " --size 160x96 --frames 3:5 -o " + (folder / "part")).exitCode, 0);
  ASSERT_EQ(runPhysdbg("replay " + (folder / "run.rec") + " --size 160x96 -o " + (folder / "all")).exitCode, 0);
  EXPECT_FALSE(std::filesystem::exists(folder / "part/frame_00002.png"));
  expectSameFrames(folder, "all", "part", 3, 5);
}

TEST(RecordReplay, BadRecordingsAndArgumentsExitTwo) {
  ScratchFolder folder;
  std::ofstream(folder / "junk.rec") << "not a recording at all";
  struct Case {
    std::string arguments, mentions;
  };
  for (const Case& c : {Case{"replay " + (folder / "junk.rec") + " -o " + (folder / "out"), "not a physdbg recording"},
                        Case{"replay " + (folder / "missing.rec") + " -o " + (folder / "out"), "missing.rec"},
                        Case{"replay " + (folder / "junk.rec"), "-o DIR is required"},
                        Case{"record bounce", "-o FILE is required"},
                        Case{"record bounce -o /dev/null/x.rec", "/dev/null/x.rec"},
                        Case{"record bounce -o " + (folder / "a.rec") + " --frames 5:2", "--frames"}}) {
    const Result result = runPhysdbg(c.arguments);
    EXPECT_EQ(result.exitCode, 2) << c.arguments << "\n" << result.output;
    EXPECT_NE(result.output.find(c.mentions), std::string::npos) << c.arguments << "\n" << result.output;
  }
}

}  // namespace
