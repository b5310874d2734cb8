// physdbg plot and the accuracy report's plots: PNGs with no gnuplot (or
// anything else) on PATH, and bad input exits 2 naming the file or option.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "bench/bullet_world.h"
#include "render/image.h"
#include "tests/cli/cli_test_support.h"

namespace {

using physdbg::clitesting::writeFile;
using physdbg::visualtesting::runPhysdbg;
using physdbg::visualtesting::ScratchFolder;

constexpr char noTools[] = "PATH=/nonexistent";

TEST(PlotCommand, DrawsSeriesColumnsWithNothingOnPath) {
  ScratchFolder folder;
  ASSERT_EQ(runPhysdbg("simulate stack --steps 30 --series " + folder / "s.csv").exitCode, 0);
  const auto result = runPhysdbg("plot " + folder / "s.csv" + " --x time --y kinetic_energy,linear_momentum --log-y "
                                 "--size 480x320 -o " + folder / "p.png", noTools);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const physdbg::render::Image image = physdbg::render::readPng(folder / "p.png");
  EXPECT_EQ(image.width, 480);
  EXPECT_EQ(image.height, 320);
}

TEST(PlotCommand, BadInputExitsTwoNamingIt) {
  ScratchFolder folder;
  writeFile(folder / "s.csv", "step,value\n0,1\n1,inf\n");
  const std::pair<std::string, std::string> cases[] = {
      {"--y value -o " + folder / "p.png", "s.csv:3: column 2 ('value'): 'inf' is not finite"},
      {"--y missing -o " + folder / "p.png", "--y: 'missing' is not a column of"},
      {"--y value, -o " + folder / "p.png", "--y: expected COLUMN[,COLUMN...]"},
      {"--y value", "-o FILE.png is required"}};
  for (const auto& [arguments, message] : cases) {
    const auto result = runPhysdbg("plot " + folder / "s.csv" + " " + arguments);
    EXPECT_EQ(result.exitCode, 2) << arguments << ": " << result.output;
    EXPECT_NE(result.output.find(message), std::string::npos) << result.output;
  }
}

// The quick sweep takes about a second; every reference gets its PNG and the
// summary gives orders a meaning (the tumbling box is exact to round-off).
TEST(PlotCommand, AccuracyReportPlotsWithoutGnuplot) {
  ScratchFolder folder;
  const auto result = runPhysdbg("report accuracy --quick -o " + folder / "acc", noTools);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (const char* reference : {"free_fall", "bounce", "tumbling_box", "depth_box_box"})
    EXPECT_GT(physdbg::render::readPng(folder / ("acc/" + std::string(reference) + ".png")).width, 0) << reference;
  EXPECT_NE(result.output.find("| tumbling_box | seed | exact (error at round-off"), std::string::npos)
      << result.output;
  EXPECT_EQ(result.output.find("| nan |"), std::string::npos) << result.output;
  std::ifstream indexFile(folder / "acc/index.html");
  const std::string index(std::istreambuf_iterator<char>(indexFile), {});
  EXPECT_NE(index.find("<img src=\"free_fall.png\""), std::string::npos) << index;
  const bool bullet = physdbg::bench::BulletWorld::available();
  EXPECT_EQ(result.output.find("| free_fall | bullet (own solver) |") != std::string::npos, bullet) << result.output;
  EXPECT_EQ(result.output.find("bullet: not built") != std::string::npos, !bullet) << result.output;
}

}  // namespace
