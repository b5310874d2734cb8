// scripts/render-parallel.sh: a render split into chunks through GNU parallel
// writes byte for byte the files of one run, overlay included (its "frame i
// of N" needs --of-run), and render --of-run refuses what cannot be a slice
// of the run it names.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "reports/child_process.h"
#include "tests/support/visual_test_support.h"

namespace physdbg {
namespace {

namespace fs = std::filesystem;
using visualtesting::fileBytes;
using visualtesting::runPhysdbg;
using visualtesting::ScratchFolder;

const std::string kView = " --size 96x72 --layers shapes,aabbs,overlay --no-timing";

TEST(RenderParallel, ChunksWriteTheFilesOfOneRun) {
  if (!findExecutable("parallel")) GTEST_SKIP() << "GNU parallel is not installed (bash scripts/setup.sh)";
  ScratchFolder folder;
  ASSERT_EQ(runPhysdbg("render default -o " + (folder / "one") + " --frames 8" + kView).exitCode, 0);
  fs::create_directories(folder / "split");
  std::ofstream(folder / "split/frame_00099.png") << "left by an earlier run";
  ::setenv("PHYSDBG", PHYSDBG_BINARY, 1);
  ::setenv("LP_NUM_THREADS", "1", 1);
  ChildCommand split{"bash", {std::string(PHYSDBG_SOURCE_DIR) + "/scripts/render-parallel.sh", "-j", "2", "--chunks",
                              "2", "default", "-o", folder / "split", "--frames", "8", "--size", "96x72", "--layers",
                              "shapes,aabbs,overlay", "--no-timing"},
                     "", true};
  ASSERT_TRUE(runChild(split).succeeded());
  int frames = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder / "one")) {
    ++frames;
    EXPECT_EQ(fileBytes(entry.path().string()), fileBytes(folder / "split/" + entry.path().filename().string()))
        << entry.path().filename();
  }
  EXPECT_EQ(frames, 8);
  EXPECT_FALSE(fs::exists(folder / "split/frame_00099.png"));  // one run --frames N owns the folder
}

TEST(RenderParallel, OfRunMustHoldTheSlice) {
  ScratchFolder folder;
  const auto run = [&](const std::string& frames) {
    return runPhysdbg("render default -o " + (folder / "out") + " " + frames + kView);
  };
  EXPECT_EQ(run("--frames 10 --of-run 20").exitCode, 2);
  const visualtesting::Result outside = run("--frames 5:25 --of-run 20");
  EXPECT_EQ(outside.exitCode, 2);
  EXPECT_NE(outside.output.find("--of-run: the slice --frames 5:25 is not inside the run '20'"), std::string::npos)
      << outside.output;
}

}  // namespace
}  // namespace physdbg
