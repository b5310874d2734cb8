// End-to-end tests of physdbg golden: approve then check, a shifted approved
// frame and a changed layer list fail with the report and JUnit naming the
// case, bad manifests exit 2 naming file and key, a renderer key without
// approved frames is skipped (not passed), and -j 2 through GNU parallel
// gives the verdicts -j 1 gives. Small frames (96x72) keep each test short.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>

#include "reports/child_process.h"
#include "render/image.h"
#include "tests/cli/cli_test_support.h"
#include "tests/support/visual_test_support.h"

namespace physdbg {
namespace {

namespace fs = std::filesystem;
using clitesting::writeFile;
using visualtesting::fileBytes;
using visualtesting::runPhysdbg;
using visualtesting::ScratchFolder;

// Two cases: a scene file beside the manifest, and a built-in scene.
const char kManifest[] = R"({"cases": [
  {"name": "stack", "scene": "scenes/stack.json", "frames": [0, 12], "size": "96x72",
   "layers": "shapes,aabbs,contacts"},
  {"name": "tumble", "scene": "default", "frames": [6], "size": "96x72", "layers": "shapes,overlay",
   "camera": {"eye": [6, 4, 8], "target": [0, 1, 0]}, "solver": "seed"}]})";

const char kStackScene[] = R"({"name": "stack", "steps": 20, "bodies": [
  {"shape": {"box": {"half_extents": [4, 0.25, 4]}}, "position": [0, -0.25, 0], "static": true},
  {"shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}}, "position": [0, 0.6, 0]},
  {"shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}}, "position": [0.2, 1.8, 0]}]})";

// A manifest case with 65 frames, one more than allowed.
std::string tooManyFrames() {
  std::string frames = "0";
  for (int frame = 1; frame <= 64; ++frame) frames.append(",").append(std::to_string(frame));
  return R"({"cases": [{"name": "a", "scene": "default", "frames": [)" + frames + "]}]}";
}

class GoldenCommand : public ::testing::Test {
 protected:
  ScratchFolder folder;
  std::string manifest = folder / "golden.json";

  void SetUp() override {
    fs::create_directories(folder / "scenes");
    writeFile(folder / "scenes/stack.json", kStackScene);
    writeFile(manifest, kManifest);
  }

  visualtesting::Result golden(const std::string& arguments) { return runPhysdbg("golden " + arguments); }

  // The one renderer-key folder approve made.
  fs::path keyFolder() {
    for (const fs::directory_entry& entry : fs::directory_iterator(folder / "golden")) return entry.path();
    return {};
  }

  void approve() { ASSERT_EQ(golden("approve " + manifest).exitCode, 0); }
};

// The verdicts of a JUnit file, without the measured times.
std::string verdicts(const std::string& junit) {
  return std::regex_replace(fileBytes(junit), std::regex(" time=\"[0-9.]+\""), "");
}

TEST_F(GoldenCommand, ApproveThenCheckPasses) {
  const visualtesting::Result approved = golden("approve " + manifest);
  ASSERT_EQ(approved.exitCode, 0) << approved.output;
  const fs::path stack = keyFolder() / "stack";
  EXPECT_TRUE(fs::exists(stack / "frame_00000.png"));
  EXPECT_TRUE(fs::exists(stack / "frame_00012.png"));
  const std::string record = fileBytes(stack / "approved.json");
  for (const char* key : {"\"renderer_key\"", "\"physdbg_version\"", "\"scene_hash\"", "\"layers\""})
    EXPECT_NE(record.find(key), std::string::npos) << key << " in " << record;

  const visualtesting::Result checked =
      golden("check " + manifest + " --report " + (folder / "report") + " --junit " + (folder / "junit.xml"));
  EXPECT_EQ(checked.exitCode, 0) << checked.output;
  EXPECT_NE(checked.output.find("2 passed, 0 failed, 0 skipped"), std::string::npos) << checked.output;
  EXPECT_NE(fileBytes(folder / "junit.xml").find("tests=\"3\" failures=\"0\" errors=\"0\" skipped=\"0\""),
            std::string::npos);
  EXPECT_TRUE(fs::exists(folder / "report/index.html"));
}

// Every row of an approved picture moved right by `pixels`.
void shiftApproved(const fs::path& approved, int pixels) {
  render::Image image = render::readPng(approved.string());
  const std::ptrdiff_t row = std::ptrdiff_t(image.width) * 4;
  for (int y = 0; y < image.height; ++y) {
    const auto start = image.rgba.begin() + y * row;
    std::rotate(start, start + row - 4 * pixels, start + row);
  }
  render::writePng(approved.string(), image);
}

// The project's rule accepts a pixel that has a match within one pixel (a
// thin line moved by a pixel, render/image_compare.h), so a frame shifted by
// one pixel passes, as in the golden tests; three pixels fail.
TEST_F(GoldenCommand, ShiftedApprovedFrameFailsWithReportAndJunit) {
  approve();
  const fs::path approved = keyFolder() / "stack/frame_00012.png";
  const std::string original = fileBytes(approved.string());
  shiftApproved(approved, 1);
  EXPECT_EQ(golden("check " + manifest + " --case stack").exitCode, 0);
  writeFile(approved.string(), original);
  shiftApproved(approved, 3);

  const visualtesting::Result checked =
      golden("check " + manifest + " --report " + (folder / "report") + " --junit " + (folder / "junit.xml"));
  EXPECT_EQ(checked.exitCode, 1) << checked.output;
  EXPECT_NE(checked.output.find("stack: failed"), std::string::npos) << checked.output;
  const std::string page = fileBytes(folder / "report/index.html");
  EXPECT_NE(page.find("stack, frame 12"), std::string::npos);
  EXPECT_TRUE(fs::exists(folder / "report/cases/stack/frame_00012/diff.png"));
  const std::string junit = fileBytes(folder / "junit.xml");
  EXPECT_NE(junit.find("<testcase classname=\"stack\" name=\"frame 12\""), std::string::npos) << junit;
  EXPECT_NE(junit.find("<failure message=\"DIFFERENT"), std::string::npos) << junit;
  EXPECT_NE(junit.find("failures=\"1\""), std::string::npos) << junit;
}

TEST_F(GoldenCommand, ChangedLayerInManifestFails) {
  approve();
  std::string text = kManifest;
  text.replace(text.find("shapes,aabbs,contacts"), 21, "shapes,contacts");
  writeFile(manifest, text);
  const visualtesting::Result checked = golden("check " + manifest + " --junit " + (folder / "junit.xml"));
  EXPECT_EQ(checked.exitCode, 1) << checked.output;
  EXPECT_NE(checked.output.find("layers was 'shapes,aabbs,contacts' at approval, now 'shapes,contacts'"),
            std::string::npos)
      << checked.output;
  EXPECT_NE(fileBytes(folder / "junit.xml").find("classname=\"stack\""), std::string::npos);
}

TEST_F(GoldenCommand, BadManifestsExitTwoNamingFileAndKey) {
  const std::string file = folder / "bad.json";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"cases": [{"name": "a", "scene": "default"}]})", "cases[0]: missing key frames"},
      {R"({"cases": [{"name": "a", "scene": "default", "frames": "0"}]})", "cases[0].frames: must be an array"},
      {R"({"cases": [{"name": "a/b", "scene": "default", "frames": [0]}]})", "cases[0].name: 'a/b' is not a plain"},
      {R"({"cases": [{"name": "../../x", "scene": "default", "frames": [0]}]})", "cases[0].name: '../../x'"},
      {tooManyFrames(), "cases[0].frames: must have 1 to 64 elements, got 65"},
      {R"({"cases": [{"name": "a", "scene": "nowhere.json", "frames": [0]}]})",
       "cases[0].scene: 'nowhere.json' is neither a built-in scene"},
      {R"({"cases": [{"name": "a", "scene": "default", "frames": [0], "layer": "shapes"}]})",
       "cases[0].layer: unknown key"},
      {R"({"cases": [{"name": "a", "scene": "default", "frames": [0], "size": "100000x16"}]})",
       "cases[0].size: must be"},
  };
  for (const auto& [text, message] : cases) {
    writeFile(file, text);
    const visualtesting::Result checked = golden("check " + file);
    EXPECT_EQ(checked.exitCode, 2) << text << "\n" << checked.output;
    EXPECT_NE(checked.output.find(file + ": " + message), std::string::npos) << text << "\n" << checked.output;
  }
  EXPECT_FALSE(fs::exists(folder / "golden"));  // nothing drawn or written
}

TEST_F(GoldenCommand, RendererKeyWithoutApprovedFramesIsSkipped) {
  approve();
  fs::rename(keyFolder(), folder / "golden/mesa-0.0-otherpipe");
  const visualtesting::Result checked =
      golden("check " + manifest + " --report " + (folder / "report") + " --junit " + (folder / "junit.xml"));
  EXPECT_EQ(checked.exitCode, 0) << checked.output;
  EXPECT_NE(checked.output.find("0 passed, 0 failed, 2 skipped"), std::string::npos) << checked.output;
  EXPECT_NE(checked.output.find("no approved frames for renderer key"), std::string::npos) << checked.output;
  const std::string junit = fileBytes(folder / "junit.xml");
  EXPECT_NE(junit.find("skipped=\"3\""), std::string::npos) << junit;
  EXPECT_NE(junit.find("<skipped message=\"no approved frames"), std::string::npos) << junit;
  EXPECT_NE(fileBytes(folder / "report/index.html").find("<td class=skipped>skipped</td>"), std::string::npos);
  EXPECT_EQ(golden("check " + manifest + " --fail-on-skip").exitCode, 1);
}

TEST_F(GoldenCommand, ParallelJobsGiveTheSameVerdictsAsOne) {
  if (!findExecutable("parallel")) GTEST_SKIP() << "GNU parallel is not installed (bash scripts/setup.sh)";
  approve();
  fs::copy_file(keyFolder() / "stack/frame_00000.png", keyFolder() / "stack/frame_00012.png",
                fs::copy_options::overwrite_existing);  // stack fails, tumble passes
  const visualtesting::Result one =
      golden("check " + manifest + " -j 1 --junit " + (folder / "one.xml") + " --report " + (folder / "report1"));
  const visualtesting::Result two =
      golden("check " + manifest + " -j 2 --junit " + (folder / "two.xml") + " --report " + (folder / "report"));
  EXPECT_EQ(one.exitCode, 1) << one.output;
  EXPECT_EQ(two.exitCode, 1) << two.output;
  EXPECT_EQ(verdicts(folder / "one.xml"), verdicts(folder / "two.xml"));
  EXPECT_NE(two.output.find("1 passed, 1 failed, 0 skipped"), std::string::npos) << two.output;
  EXPECT_TRUE(fs::exists(folder / "report/cases/stack/frame_00012/diff.png"));
}

TEST_F(GoldenCommand, ParallelJobsWithoutGnuParallelExitTwo) {
  const visualtesting::Result hidden = runPhysdbg("golden check " + manifest + " -j 2", "PATH=/nonexistent");
  EXPECT_EQ(hidden.exitCode, 2) << hidden.output;
  EXPECT_NE(hidden.output.find("-j 2: the cases run through GNU parallel, which is not on PATH"), std::string::npos)
      << hidden.output;
}

}  // namespace
}  // namespace physdbg
