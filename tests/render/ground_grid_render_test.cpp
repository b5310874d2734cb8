// The grid layer's primitives draw: lines, the scale labels and the red,
// green and blue gizmo arrows all show in a small picture.
#include <gtest/gtest.h>

#include "debugdraw/ground_grid.h"
#include "render/renderer.h"
#include "tests/support/render_test_support.h"
#include "test_pictures.h"

namespace {

namespace dd = physdbg::debugdraw;
using physdbg::render::testing::isBackground;
using physdbg::render::testing::Pixel;
using physdbg::render::testing::pixelAt;

struct Counts {
  int drawn = 0, red = 0, green = 0, blue = 0;
};

Counts countColours(const physdbg::render::Image& image) {
  Counts counts;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const Pixel pixel = pixelAt(image, x, y);
      counts.drawn += !isBackground(pixel);
      counts.red += pixel[0] > 180 && pixel[1] < 120 && pixel[2] < 120;
      counts.green += pixel[1] > 180 && pixel[0] < 140 && pixel[2] < 140;
      counts.blue += pixel[2] > 200 && pixel[0] < 140 && pixel[1] < 170;
    }
  return counts;
}

TEST(GroundGridRender, GridLinesLabelsAndGizmoDraw) {
  for (const dd::Vec3& up : {dd::Vec3(0, 1, 0), dd::Vec3(0, 0, 1)}) {
    dd::Frame frame;
    dd::emitGroundGrid({-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}, up, frame);
    const physdbg::render::Bounds bounds = physdbg::render::frameBounds(frame);
    const physdbg::render::Camera camera = physdbg::render::frameBoundsCamera(bounds, 320.0 / 240);
    const physdbg::render::Image image = physdbg::render::Renderer({320, 240, 0}).render(frame, camera);
    physdbg::render::testing::keepPicture(image, up.z() > 0 ? "grid_z_up.png" : "grid_y_up.png");
    const Counts counts = countColours(image);
    EXPECT_GT(counts.drawn, 320 * 240 / 50) << up.transpose();
    EXPECT_GT(counts.red, 5) << up.transpose();
    EXPECT_GT(counts.green, 5) << up.transpose();
    EXPECT_GT(counts.blue, 5) << up.transpose();
  }
}

}  // namespace
