// File names derived from a scene's name: scene files come from other
// people, so the name must not lead a command's output out of out/.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/output_folder.h"
#include "cli_test_support.h"

namespace {

namespace fs = std::filesystem;

using physdbg::cli::safeFileName;
using physdbg::cli::sceneOutputFolder;

TEST(OutputNames, PlainNamesAreKept) {
  EXPECT_EQ(safeFileName("default"), "default");
  EXPECT_EQ(safeFileName("stack-3_v2.0"), "stack-3_v2.0");
}

TEST(OutputNames, PathsAndShellCharactersBecomeUnderscores) {
  EXPECT_EQ(safeFileName("../../x"), "_._.__x");
  EXPECT_EQ(safeFileName("/etc/passwd"), "_etc_passwd");
  EXPECT_EQ(safeFileName("x';touch F;'"), "x__touch_F__");
  EXPECT_EQ(safeFileName("a b\tc\nd"), "a_b_c_d");
  EXPECT_EQ(safeFileName("caf\xc3\xa9"), "caf__");  // each byte of another alphabet
}

TEST(OutputNames, NoLeadingDotAndNoDotDot) {
  EXPECT_EQ(safeFileName("."), "_");
  EXPECT_EQ(safeFileName(".."), "_.");
  EXPECT_EQ(safeFileName(".hidden"), "_hidden");
  EXPECT_EQ(safeFileName("a..b...c"), "a._b._.c");
}

TEST(OutputNames, EmptyNamesGetADefaultAndLongOnesAreCut) {
  EXPECT_EQ(safeFileName(""), "scene");
  EXPECT_EQ(safeFileName(std::string(1000, 'x')), std::string(64, 'x'));
}

TEST(OutputNames, SceneFoldersStayDirectlyInsideOut) {
  for (const std::string& name : {std::string("../../x"), std::string(".."), std::string("/abs"),
                                  std::string("a/../../b"), std::string(300, '/')}) {
    const std::filesystem::path folder = sceneOutputFolder(name, "tree_");
    EXPECT_EQ(folder.parent_path(), "out") << name;
    EXPECT_EQ(folder.filename().string().rfind("tree_", 0), 0u) << name;
  }
  EXPECT_EQ(sceneOutputFolder("default"), "out/default");
}

// render and tree, run in A/B on a scene named "../../escaped", write below A/B/out only.
TEST(OutputNames, CommandsKeepASceneNamedWithDotsInsideOut) {
  physdbg::visualtesting::ScratchFolder folder;
  const std::string work = folder / "a/b";
  fs::create_directories(work);
  physdbg::clitesting::writeFile(work + "/escape.json", R"({"name": "../../escaped", "steps": 1, "bodies": [
      {"shape": {"sphere": {"radius": 0.5}}}, {"shape": {"box": {"half_extents": [1, 1, 1]}}, "position": [3, 0, 0]},
      {"shape": {"sphere": {"radius": 0.5}}, "position": [0, 3, 0]}]})");
  using physdbg::clitesting::physdbgIn;
  EXPECT_TRUE(physdbgIn(work, {"render", "escape.json", "--size", "64x48"}).succeeded());
  EXPECT_TRUE(physdbgIn(work, {"tree", "escape.json", "--size", "400x300", "--max-events", "1"}).succeeded());
  EXPECT_FALSE(fs::exists(folder / "escaped"));
  EXPECT_FALSE(fs::exists(folder / "a/tree_"));
  EXPECT_TRUE(fs::exists(work + "/" + sceneOutputFolder("../../escaped") + "/frame_00000.png"));
  EXPECT_TRUE(fs::exists(work + "/" + sceneOutputFolder("../../escaped", "tree_") + "/sar_height.png"));
  for (const auto& entry : fs::directory_iterator(work + "/out"))
    EXPECT_EQ(entry.path().filename().string().find(".."), std::string::npos) << entry.path();
}

}  // namespace
