// "No silent blanks": a command line that would draw nothing, or a picture
// that could mislead (a stale frame, a layer with nothing in it, a frame
// count that is not the run's), is refused or said out loud.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_support.h"
#include "debugdraw/recording.h"

namespace {

namespace fs = std::filesystem;

using namespace physdbg::clitesting;
using physdbg::visualtesting::Result;
using physdbg::visualtesting::runPhysdbg;
using physdbg::visualtesting::ScratchFolder;

// One still sphere: 60 frames, never a contact.
const char* stillSphere = R"({"name": "still", "gravity": [0, 0, 0], "steps": 59,
    "bodies": [{"shape": {"sphere": {"radius": 0.5}}}]})";

std::string readText(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

void expectUsageError(const std::string& arguments, const std::vector<std::string>& mentions) {
  const Result result = runPhysdbg(arguments);
  EXPECT_EQ(result.exitCode, 2) << arguments << "\n" << result.output;
  for (const std::string& mention : mentions)
    EXPECT_NE(result.output.find(mention), std::string::npos) << arguments << "\n" << result.output;
}

TEST(NoSilentBlanks, EmptyLayerListsAreRefused) {
  ScratchFolder folder;
  for (const char* list : {"''", "','", "',,'"}) {
    expectUsageError(std::string("render default --frames 1 --size 64x48 -o ") + (folder / "f") + " --layers " + list,
                     {"--layers", "no layer"});
    expectUsageError(std::string("record default --frames 1 -o ") + (folder / "x.rec") + " --layers " + list,
                     {"--layers", "no layer"});
  }
  writeFile(folder / "blank.json", R"({"layers": "", "bodies": [{"shape": {"sphere": {"radius": 1}}}]})");
  expectUsageError("render " + (folder / "blank.json") + " --frames 1 -o " + (folder / "f"), {"blank.json", "layers"});
}

TEST(NoSilentBlanks, EmptyFrameRangesAreRefused) {
  ScratchFolder folder;
  expectUsageError("render default --frames 5:5 -o " + (folder / "f"), {"--frames", "5:5"});
  writeFile(folder / "still.json", stillSphere);
  ASSERT_EQ(runPhysdbg("record " + (folder / "still.json") + " --layers shapes -o " + (folder / "still.rec")).exitCode,
            0);
  expectUsageError("replay " + (folder / "still.rec") + " -o " + (folder / "r") + " --frames 100:120",
                   {"--frames", "100:120", "frames 0..59 (60 frames)"});
  EXPECT_FALSE(fs::exists(folder / "r/frame_00100.png"));
}

TEST(NoSilentBlanks, TreeDepthNeedsTheTreeLayer) {
  ScratchFolder folder;
  expectUsageError("render default --frames 1 --tree-depth 1:3 --layers shapes,aabbs -o " + (folder / "f"),
                   {"--tree-depth", "'tree'", "--layers", "shapes,aabbs"});
  expectUsageError("render default --frames 1 --tree-depth 1:3 -o " + (folder / "f"), {"--tree-depth", "'tree'"});
  EXPECT_EQ(
      runPhysdbg("render default --frames 1 --size 64x48 --tree-depth 1:3 --layers shapes,tree -o " + (folder / "f"))
          .exitCode,
      0);
}

TEST(NoSilentBlanks, ALayerThatDrewNothingIsNamedOnce) {
  ScratchFolder folder;
  writeFile(folder / "still.json", stillSphere);
  const Result render = runPhysdbg("render " + (folder / "still.json") +
                                   " --size 64x48 --layers shapes,contacts,overlay -o " + (folder / "f"));
  EXPECT_EQ(render.exitCode, 0) << render.output;
  const std::string message = "physdbg render: layer 'contacts' drew nothing in frames 0..59";
  const std::size_t found = render.output.find(message);
  EXPECT_NE(found, std::string::npos) << render.output;
  EXPECT_EQ(render.output.find(message, found + 1), std::string::npos) << render.output;
  EXPECT_EQ(render.output.find("'shapes'"), std::string::npos) << render.output;
  EXPECT_EQ(render.output.find("'overlay'"), std::string::npos) << render.output;

  const Result record =
      runPhysdbg("record " + (folder / "still.json") + " --frames 4:6 --layers shapes,pairs -o " + (folder / "x.rec"));
  EXPECT_EQ(record.exitCode, 0) << record.output;
  EXPECT_NE(record.output.find("physdbg record: layer 'pairs' drew nothing in frames 4..5"), std::string::npos)
      << record.output;
}

// A whole run clears every frame file; a slice clears only its own frames,
// since other processes draw the other slices into the same folder.
TEST(NoSilentBlanks, RenderClearsFramesOfAnEarlierRun) {
  ScratchFolder folder;
  writeFile(folder / "still.json", stillSphere);
  const std::string frames = folder / "f";
  fs::create_directories(frames + "/frame_00007.png");  // a folder, not a frame file
  for (const char* name : {"frame_00003.png", "frame_00009.png", "frame_123456.png", "frame_9.png", "frame_000009.png",
                           "frame_00009.png.bak", "notes.txt"})
    writeFile(frames + "/" + name, "old");
  const Result whole = runPhysdbg("render " + (folder / "still.json") + " --frames 3 --size 64x48 -o " + frames);
  ASSERT_EQ(whole.exitCode, 0) << whole.output;
  EXPECT_NE(whole.output.find("removed 3 frame files of an earlier run"), std::string::npos) << whole.output;
  for (const char* gone : {"frame_00003.png", "frame_00009.png", "frame_123456.png"})
    EXPECT_FALSE(fs::exists(frames + "/" + gone)) << gone;
  for (const char* kept : {"frame_9.png", "frame_000009.png", "frame_00009.png.bak", "notes.txt"})
    EXPECT_EQ(readText(frames + "/" + kept), "old") << kept;
  EXPECT_TRUE(fs::is_directory(frames + "/frame_00007.png"));

  for (int index = 0; index < 6; ++index) writeFile(frames + "/frame_0000" + std::to_string(index) + ".png", "old");
  const Result slice = runPhysdbg("render " + (folder / "still.json") + " --frames 2:4 --size 64x48 -o " + frames);
  ASSERT_EQ(slice.exitCode, 0) << slice.output;
  EXPECT_NE(slice.output.find("removed 2 frame files of an earlier run"), std::string::npos) << slice.output;
  for (const char* other : {"frame_00000.png", "frame_00001.png", "frame_00004.png", "frame_00005.png"})
    EXPECT_EQ(readText(frames + "/" + other), "old") << other;
  EXPECT_NE(readText(frames + "/frame_00002.png"), "old");
}

TEST(NoSilentBlanks, VideoTakesOnlyThisRunsFrames) {
  ScratchFolder folder;
  writeFile(folder / "still.json", stillSphere);
  const std::string log = folder / "ffmpeg-arguments.txt";
  const PathPrefix path(fakeFfmpegFolder(folder, log));
  ASSERT_TRUE(physdbgIn(folder / "",
                        {"render", "still.json", "--frames", "2:5", "--size", "64x48", "-o", "f", "--video", "v.mp4"})
                  .succeeded());
  const std::vector<std::string> arguments = readLines(log);
  const auto frames = std::find(arguments.begin(), arguments.end(), "-frames:v");
  ASSERT_NE(frames, arguments.end());
  ASSERT_NE(frames + 1, arguments.end());
  EXPECT_EQ(*(frames + 1), "3");
  const auto start = std::find(arguments.begin(), arguments.end(), "-start_number");
  ASSERT_NE(start, arguments.end());
  EXPECT_EQ(*(start + 1), "2");
}

TEST(NoSilentBlanks, RecordCreatesTheFolderOfItsFile) {
  ScratchFolder folder;
  const std::string path = folder / "missing/dir/x.rec";
  const Result result = runPhysdbg("record default --frames 2 --layers shapes -o " + path);
  EXPECT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(fs::is_regular_file(path));
}

// "frame i of N": N is the whole run's frame count, whichever slice is drawn.
TEST(NoSilentBlanks, OverlayCountsTheWholeRun) {
  ScratchFolder folder;
  writeFile(folder / "still.json", stillSphere);
  struct Case {
    const char* frames;
    const char* text;
  };
  for (const Case& c : {Case{"10:12", "frame 10 of 60"}, Case{"3", "frame 0 of 3"}, Case{"58:70", "frame 58 of 70"}}) {
    const std::string recording = folder / "overlay.rec";
    ASSERT_EQ(runPhysdbg("record " + (folder / "still.json") + " --layers shapes,overlay --frames " + c.frames +
                         " -o " + recording)
                  .exitCode,
              0);
    physdbg::debugdraw::RecordingReader reader(recording);
    physdbg::debugdraw::RecordedFrame frame;
    ASSERT_TRUE(reader.next(frame));
    ASSERT_FALSE(frame.frame.texts.empty());
    EXPECT_NE(frame.frame.texts[0].text.find(c.text), std::string::npos)
        << c.frames << ": " << frame.frame.texts[0].text;
  }
}

}  // namespace
