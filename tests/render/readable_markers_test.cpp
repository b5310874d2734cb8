// The debugger's markers read at small sizes: an arrow inside a body shows,
// outlined, and a resting contact normal spans the minimum on screen.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "engine/debug/world_debug_draw.h"
#include "engine/world.h"
#include "render/frame_batches.h"
#include "render/renderer.h"
#include "tests/support/render_test_support.h"
#include "scenes/scene.h"

namespace {

namespace dd = physdbg::debugdraw;
using physdbg::render::Image;
using physdbg::render::testing::isBackground;
using physdbg::render::testing::pixelAt;
using physdbg::render::testing::projectToPixel;

bool isOrange(const physdbg::render::testing::Pixel& pixel) {
  return pixel[0] > 200 && pixel[1] > 90 && pixel[1] < 170 && pixel[2] < 60;
}

// Looking down -z at the origin, 40 px per metre on a 160x120 image.
physdbg::render::Camera frontCamera() {
  physdbg::render::Camera camera;
  camera.orthographic = true;
  camera.orthoHeight = 3;
  return camera;
}

TEST(ReadableMarkers, AnArrowWhoseShaftIsInsideASolidBodyIsVisible) {
  dd::Frame frame;
  frame.boxes.push_back({Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity(), Eigen::Vector3d(1, 1, 1),
                         {0.9f, 0.85f, 0.2f, 1}});  // a yellow body: the colour markers used to vanish on
  frame.arrows.push_back({{-0.8, 0, 0}, {0.8, 0, 0}, dd::colors::contactNormal});
  const physdbg::render::Camera camera = frontCamera();
  const Image image = physdbg::render::Renderer({160, 120, 0}).render(frame, camera);
  int orange = 0, dark = 0;
  for (double x = -0.6; x <= 0.3; x += 0.025) {  // along the shaft, short of the head
    const Eigen::Vector2d pixel = projectToPixel(camera, image.width, image.height, {x, 0, 0});
    for (int dy = -2; dy <= 2; ++dy) {
      const auto sample = pixelAt(image, int(pixel.x()), int(pixel.y()) + dy);
      orange += isOrange(sample);
      dark += sample[0] + sample[1] + sample[2] < 60;  // the outline
    }
  }
  EXPECT_GT(orange, 20);
  EXPECT_GT(dark, 20);
}

// Vertical extent in pixels of everything that is not background.
int drawnHeight(const Image& image) {
  int top = image.height, bottom = -1;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (!isBackground(pixelAt(image, x, y))) top = std::min(top, y), bottom = std::max(bottom, y);
  return bottom < top ? 0 : bottom - top + 1;
}

TEST(ReadableMarkers, ARestingContactNormalSpansTheMinimumOnScreen) {
  // A small box resting on a wide floor: the camera frames the floor, so the
  // box's resting normal (a quarter of its size) is a pixel or two long in world terms.
  const physdbg::SceneDescription scene = physdbg::parseScene(
      R"({"name": "rest", "bodies": [
        {"shape": {"box": {"half_extents": [20, 0.5, 20]}}, "position": [0, -0.5, 0], "static": true},
        {"shape": {"box": {"half_extents": [0.2, 0.2, 0.2]}}, "position": [0, 0.2, 0]}]})",
      "rest");
  physdbg::World world = physdbg::buildWorld(scene);
  for (int step = 0; step < 30; ++step) world.step();
  dd::Frame all, arrows;
  emitDebugDraw(world, dd::parseLayers("shapes,contacts"), all);
  emitDebugDraw(world, dd::parseLayers("contacts"), arrows);
  arrows.points.clear();
  ASSERT_FALSE(arrows.arrows.empty());
  const physdbg::render::Camera camera = physdbg::render::frameBoundsCamera(physdbg::render::frameBounds(all), 160.0 / 120);
  const Image image = physdbg::render::Renderer({160, 120, 0}).render(arrows, camera);
  EXPECT_GE(drawnHeight(image), physdbg::render::kMinimumArrowPixels);
}

}  // namespace
