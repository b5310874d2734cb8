// World-anchored labels: drawn just above their projected anchor and nowhere
// else, nothing for anchors behind the camera or out of view, and counted in
// the frame's text budget like screen text.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "render/frame_batches.h"
#include "render/renderer.h"
#include "tests/support/render_test_support.h"
#include "test_pictures.h"

namespace {

namespace dd = physdbg::debugdraw;
using Eigen::Vector2d;
using Eigen::Vector3d;
using physdbg::render::Image;
using physdbg::render::testing::isBackground;
using physdbg::render::testing::pixelAt;

constexpr int kWidth = 160, kHeight = 120;

// Perspective, looking down -z at the origin from 10 m.
physdbg::render::Camera frontCamera() { return physdbg::render::Camera{}; }

dd::Frame labelFrame(const Vector3d& position, const std::string& text = "Ab") {
  dd::Frame frame;
  frame.labels.push_back({position, 2, text, {1, 1, 1, 1}, {}});
  return frame;
}

Image render(const dd::Frame& frame) {
  return physdbg::render::Renderer({kWidth, kHeight, 0}).render(frame, frontCamera());
}

struct Drawn {
  int pixels = 0, white = 0;
  int left = kWidth, right = -1, top = kHeight, bottom = -1;  // of every drawn pixel
  double whiteX = 0;                                          // mean column of the glyphs
};

Drawn drawnPixels(const Image& image) {
  Drawn drawn;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto pixel = pixelAt(image, x, y);
      if (isBackground(pixel)) continue;
      ++drawn.pixels;
      drawn.left = std::min(drawn.left, x), drawn.right = std::max(drawn.right, x);
      drawn.top = std::min(drawn.top, y), drawn.bottom = std::max(drawn.bottom, y);
      if (pixel[0] > 240 && pixel[1] > 240 && pixel[2] > 240) ++drawn.white, drawn.whiteX += x + 0.5;
    }
  if (drawn.white > 0) drawn.whiteX /= drawn.white;
  return drawn;
}

TEST(Label, DrawsCentredJustAboveItsAnchorAndNowhereElse) {
  const Vector3d anchor(1, -0.5, 0);
  const Image image = render(labelFrame(anchor));
  physdbg::render::testing::keepPicture(image, "label.png");
  const Vector2d pixel = physdbg::render::testing::projectToPixel(frontCamera(), kWidth, kHeight, anchor);
  const Drawn drawn = drawnPixels(image);
  ASSERT_GT(drawn.white, 10);
  EXPECT_NEAR(drawn.whiteX, pixel.x(), 3);  // centred
  EXPECT_LE(drawn.bottom, pixel.y());       // above the anchor...
  EXPECT_GE(drawn.bottom, pixel.y() - 8);   // ...by a few pixels
  EXPECT_GE(drawn.top, pixel.y() - 30);     // one line of scale-2 glyphs and the outline
  EXPECT_GE(drawn.left, pixel.x() - 20);
  EXPECT_LE(drawn.right, pixel.x() + 20);
}

TEST(Label, IsOutlinedLikeText) {
  const Image image = render(labelFrame({0, 0, 0}));
  int dark = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto pixel = pixelAt(image, x, y);
      dark += pixel[0] + pixel[1] + pixel[2] < 40;
    }
  EXPECT_GT(dark, 10);
}

TEST(Label, AnchorsBehindTheCameraOrOutOfViewDrawNothing) {
  for (const Vector3d& anchor : {Vector3d(0, 0, 20), Vector3d(0, 0, 10), Vector3d(30, 0, 0), Vector3d(0, -30, 0)})
    EXPECT_EQ(drawnPixels(render(labelFrame(anchor))).pixels, 0) << anchor.transpose();
}

TEST(Label, SameFrameSameBytes) {
  dd::Frame frame = labelFrame({0.5, 0.5, 0}, "body 3");
  frame.labels.push_back({{-1, -1, 1}, 1, "x", {1, 0.3f, 0.3f, 1}, {}});
  physdbg::render::Renderer renderer({kWidth, kHeight, 0});
  EXPECT_EQ(renderer.render(frame, frontCamera()).rgba, renderer.render(frame, frontCamera()).rgba);
}

// Spaces count as characters but build no geometry: the budget is checked
// by count, before any text is built.
TEST(Label, CountTowardTheFrameTextBudget) {
  dd::Frame frame;
  for (std::size_t used = 0; used < dd::maxFrameTextCharacters - 10; used += dd::maxTextCharacters)
    frame.texts.push_back({0, 0, 1, std::string(std::min(dd::maxTextCharacters, dd::maxFrameTextCharacters - 10 - used), ' '), {}});
  frame.labels.push_back({{0, 0, 0}, 1, std::string(10, 'x'), {}, {}});
  EXPECT_NO_THROW(physdbg::render::buildFrameBatches(frame, Vector3d::Zero()));
  frame.labels.back().text += 'x';
  EXPECT_THROW(physdbg::render::buildFrameBatches(frame, Vector3d::Zero()), std::invalid_argument);
  EXPECT_THROW(render(frame), std::invalid_argument);
  frame.texts.clear();
  frame.labels.assign(1, {{0, 0, 0}, 1, std::string(dd::maxTextCharacters + 1, 'x'), {}, {}});
  EXPECT_THROW(physdbg::render::buildFrameBatches(frame, Vector3d::Zero()), std::invalid_argument);
}

// Refused whether or not the label would be seen, so a frame fails the same
// way from every camera.
TEST(Label, BadLabelsAreRefusedInOrOutOfView) {
  for (const Vector3d& anchor : {Vector3d(0, 0, 0), Vector3d(0, 0, 20)}) {
    dd::Frame frame = labelFrame(anchor);
    frame.labels[0].scale = 0;
    EXPECT_THROW(render(frame), std::invalid_argument);
    frame.labels[0].scale = NAN;
    EXPECT_THROW(render(frame), std::invalid_argument);
  }
  EXPECT_THROW(render(labelFrame({NAN, 0, 0})), std::invalid_argument);
  EXPECT_THROW(render(labelFrame({0, INFINITY, 0})), std::invalid_argument);
}

}  // namespace
