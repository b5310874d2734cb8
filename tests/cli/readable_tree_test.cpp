// The tree layer's depths read apart: `--tree-depth 0:0` and `2:2` on balls48
// (a chain of nodes near the root shares nearly one box) give visibly
// different pictures, and deeper nodes are paler.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "render/image.h"
#include "tests/support/render_test_support.h"
#include "tests/support/visual_test_support.h"

namespace {

using physdbg::render::Image;
using physdbg::visualtesting::runPhysdbg;
using physdbg::visualtesting::ScratchFolder;

Image renderTreeDepth(const ScratchFolder& folder, const std::string& depths) {
  const std::string out = folder / ("depth" + depths.substr(0, 1));
  const auto result = runPhysdbg("render balls48 --frames 30:31 --size 240x136 --layers tree --no-timing --tree-depth " +
                                 depths + " -o " + out);
  EXPECT_EQ(result.exitCode, 0) << result.output;
  return physdbg::render::readPng(out + "/frame_00030.png");
}

// Pixels where both pictures draw something and differ by more than `levels`
// on some channel: the same box drawn at two depths must not look alike.
int clearlyDifferentWhereBothDraw(const Image& a, const Image& b, int levels) {
  const auto background = [](const Image& image, std::size_t i) {
    return physdbg::render::testing::isBackground(
        {image.rgba[i], image.rgba[i + 1], image.rgba[i + 2], image.rgba[i + 3]});
  };
  int count = 0;
  for (std::size_t i = 0; i + 3 < a.rgba.size(); i += 4) {
    if (background(a, i) || background(b, i)) continue;
    for (int c = 0; c < 3; ++c)
      if (std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])) > levels) {
        ++count;
        break;
      }
  }
  return count;
}

// Mean red + green of the blue tree pixels: higher is paler.
double paleness(const Image& image) {
  double sum = 0;
  int count = 0;
  for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
    const int r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
    if (b < r + 40 || b < 120) continue;  // not a tree pixel (background, white legend title)
    sum += r + g;
    ++count;
  }
  EXPECT_GT(count, 50);
  return count ? sum / count : 0;
}

TEST(ReadableTree, DepthZeroAndDepthTwoOfBalls48LookDifferent) {
  ScratchFolder folder;
  const Image root = renderTreeDepth(folder, "0:0");
  const Image second = renderTreeDepth(folder, "2:2");
  ASSERT_EQ(root.rgba.size(), second.rgba.size());
  // Most of their edges coincide (depth 2 is the walls' box, depth 0 adds the
  // floor's slab); where they do, the colours must tell the depths apart.
  EXPECT_GT(clearlyDifferentWhereBothDraw(root, second, 40), 100);
}

TEST(ReadableTree, DeeperNodesArePaler) {
  ScratchFolder folder;
  const double root = paleness(renderTreeDepth(folder, "0:0"));
  const double third = paleness(renderTreeDepth(folder, "3:3"));
  const double sixth = paleness(renderTreeDepth(folder, "6:6"));
  EXPECT_GT(third, root + 40);
  EXPECT_GT(sixth, third + 20);
}

}  // namespace
