// Each debug layer's colour appears in the picture, inside the projected
// bounds of what the layer draws, and does not appear when the layer is off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/debug/world_debug_draw.h"
#include "engine/world.h"
#include "render/renderer.h"
#include "tests/support/render_test_support.h"
#include "scenes/scene.h"

namespace {

namespace dd = physdbg::debugdraw;
using physdbg::render::testing::pixelAt;
using physdbg::render::testing::projectToPixel;

constexpr int width = 240, height = 160;

struct Match {
  int count = 0;
  int minX = width, minY = height, maxX = -1, maxY = -1;
};

// Pixels within `tolerance` levels of `color` on every channel.
Match findColor(const physdbg::render::Image& image, dd::Color color, int tolerance = 30) {
  Match match;
  const int target[3] = {int(std::lround(color.r * 255)), int(std::lround(color.g * 255)), int(std::lround(color.b * 255))};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto pixel = pixelAt(image, x, y);
      bool close = true;
      for (int c = 0; c < 3; ++c) close = close && std::abs(pixel[c] - target[c]) <= tolerance;
      if (!close) continue;
      ++match.count;
      match.minX = std::min(match.minX, x), match.maxX = std::max(match.maxX, x);
      match.minY = std::min(match.minY, y), match.maxY = std::max(match.maxY, y);
    }
  return match;
}

// A translucent layer colour as it shows over the renderer's background.
dd::Color overBackground(dd::Color color) {
  const float background[3] = {0.11f, 0.12f, 0.14f};
  return {color.r * color.a + background[0] * (1 - color.a), color.g * color.a + background[1] * (1 - color.a),
          color.b * color.a + background[2] * (1 - color.a), 1};
}

struct LayerCase {
  const char* scene;
  int steps;
  const char* layer;
  dd::Color color;
};

void PrintTo(const LayerCase& c, std::ostream* out) { *out << c.layer << " in " << c.scene; }

class LayerColors : public ::testing::TestWithParam<LayerCase> {};

TEST_P(LayerColors, AppearInsideTheLayersBoundsAndOnlyWhenOn) {
  const LayerCase& c = GetParam();
  physdbg::World world = physdbg::buildWorld(physdbg::resolveScene(c.scene));
  for (int i = 0; i < c.steps; ++i) world.step();
  physdbg::render::Renderer renderer({width, height, 0});
  dd::Frame all;
  emitDebugDraw(world, dd::parseLayers("shapes,aabbs,fat,tree,contacts,velocities,pairs"), all);
  const physdbg::render::Camera camera =
      physdbg::render::frameBoundsCamera(physdbg::render::frameBounds(all), double(width) / height);

  dd::Frame on;
  emitDebugDraw(world, dd::parseLayers(c.layer), on);
  ASSERT_FALSE(on.empty()) << c.layer;
  on.texts.clear();  // the tree's depth legend is screen text, outside any world bounds
  const Match match = findColor(renderer.render(on, camera), c.color);
  EXPECT_GE(match.count, 10) << c.layer;
  // Every matching pixel lies inside the projection of the layer's own bounds.
  const physdbg::render::Bounds bounds = physdbg::render::frameBounds(on);
  double minX = 1e9, minY = 1e9, maxX = -1e9, maxY = -1e9;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d point((corner & 1) ? bounds.max.x() : bounds.min.x(), (corner & 2) ? bounds.max.y() : bounds.min.y(),
                                (corner & 4) ? bounds.max.z() : bounds.min.z());
    const Eigen::Vector2d pixel = projectToPixel(camera, width, height, point);
    minX = std::min(minX, pixel.x()), maxX = std::max(maxX, pixel.x());
    minY = std::min(minY, pixel.y()), maxY = std::max(maxY, pixel.y());
  }
  const double slack = 6;  // point sprites and arrow heads reach a few pixels past their position
  EXPECT_GE(match.minX, minX - slack) << c.layer;
  EXPECT_LE(match.maxX, maxX + slack) << c.layer;
  EXPECT_GE(match.minY, minY - slack) << c.layer;
  EXPECT_LE(match.maxY, maxY + slack) << c.layer;

  // All other non-shape layers on, this one off: the colour is gone.
  dd::LayerSet others = dd::parseLayers("aabbs,fat,tree,contacts,velocities,pairs");
  others.bits &= ~dd::parseLayers(c.layer).bits;
  dd::Frame off;
  emitDebugDraw(world, others, off);
  EXPECT_LE(findColor(renderer.render(off, camera), c.color).count, 2) << c.layer;
}

INSTANTIATE_TEST_SUITE_P(
    Layers, LayerColors,
    ::testing::Values(LayerCase{"stack", 5, "aabbs", dd::colors::colliding},
                      LayerCase{"stack", 5, "fat", overBackground(dd::colors::fatLayer)},
                      LayerCase{"stack", 5, "tree", dd::colors::treeNode},
                      LayerCase{"stack", 5, "contacts", dd::colors::contactPoint},
                      LayerCase{"bounce", 20, "velocities", {0.3f, 0.9f, 1.0f, 1}},
                      LayerCase{"stack", 5, "pairs", {0.9f, 0.5f, 0.9f, 1}}),
    [](const ::testing::TestParamInfo<LayerCase>& info) { return std::string(info.param.layer); });

}  // namespace

// The `wire` layer draws a sphere as circles, not as the box around it: seen
// head-on, a lone sphere's outline covers its silhouette circle and leaves
// the corners of its bounding square dark (a box outline would light them).
namespace {

TEST(WireLayer, DrawsASphereAsACircleNotItsBoundingBox) {
  const physdbg::SceneDescription scene = physdbg::parseScene(
      R"({"name": "lone sphere", "bodies": [{"shape": {"sphere": {"radius": 1}}, "position": [0, 0, 0]}]})",
      "lone sphere");
  const physdbg::World world = physdbg::buildWorld(scene);
  dd::Frame frame;
  emitDebugDraw(world, dd::parseLayers("wire"), frame);
  constexpr int smallWidth = 160, smallHeight = 120;
  physdbg::render::Camera camera;  // looking down -z at the origin
  camera.orthographic = true;
  camera.orthoHeight = 3;  // 40 px per metre: the sphere is 80 px across
  const physdbg::render::Image image = physdbg::render::Renderer({smallWidth, smallHeight, 0}).render(frame, camera);
  const auto wireNear = [&](const Eigen::Vector3d& point, int reach) {
    const Eigen::Vector2d pixel = projectToPixel(camera, smallWidth, smallHeight, point);
    int count = 0;
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dx = -reach; dx <= reach; ++dx)
        count += physdbg::render::testing::isBackground(
                     pixelAt(image, int(pixel.x()) + dx, int(pixel.y()) + dy)) ? 0 : 1;
    return count;
  };
  for (const Eigen::Vector3d& corner : {Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(-1, 1, 0),
                                       Eigen::Vector3d(1, -1, 0), Eigen::Vector3d(-1, -1, 0)})
    EXPECT_EQ(wireNear(corner, 3), 0) << "bounding-square corner " << corner.transpose();
  for (int step = 0; step < 16; ++step) {
    const double angle = 2 * M_PI * (step + 0.5) / 16;  // between the circle's own vertices
    EXPECT_GT(wireNear({std::cos(angle), std::sin(angle), 0}, 1), 0) << "circle at angle " << angle;
  }
}

}  // namespace

// The contacts and aabbs layers show what the engine saw since the previous
// frame: the initial contacts in frame 0, an impact that began and ended
// between two frames, and the contacts a sleeping pile rests on (dimmed).
// Frames come from the debugger's own frame source.
#include "viewer/scene_frames.h"

namespace {

constexpr int smallWidth = 160, smallHeight = 120;

physdbg::render::Image renderSceneFrame(const physdbg::SceneDescription& scene, const char* layers, int index,
                                        int stepsPerFrame = 1) {
  physdbg::viewer::ViewOptions options;
  options.frames = {0, index + 1};
  options.runFrames = index + 1;
  options.stepsPerFrame = stepsPerFrame;
  options.width = smallWidth;
  options.height = smallHeight;
  options.layers = dd::parseLayers(layers);
  options.timing = false;
  physdbg::viewer::SceneFrames frames(scene, options);
  const dd::RecordedFrame frame = frames.frame(index);
  return physdbg::render::Renderer({smallWidth, smallHeight, 0}).render(frame.frame, physdbg::viewer::toCamera(frame.view));
}

dd::Color dimmed(dd::Color color) { return {color.r * 0.5f, color.g * 0.5f, color.b * 0.5f, color.a}; }

TEST(ContactsAsTheEngineSawThem, FrameZeroOfStackShowsRedBoxesAndContactDots) {
  const physdbg::SceneDescription scene = physdbg::resolveScene("stack");
  const physdbg::render::Image image = renderSceneFrame(scene, "aabbs,contacts", 0);
  EXPECT_GE(findColor(image, dd::colors::colliding).count, 50);
  EXPECT_GE(findColor(image, dd::colors::contactPoint).count, 10);
}

// A ball of restitution 1 hits the floor at about step 27 and is back in the
// air by step 30: the frame of steps 1..30 ends with nothing touching.
TEST(ContactsAsTheEngineSawThem, AFrameSpanningABounceShowsTheImpact) {
  const physdbg::SceneDescription scene = physdbg::parseScene(
      R"({"name": "one bounce", "bodies": [
          {"shape": {"box": {"half_extents": [2, 0.25, 2]}}, "position": [0, -0.25, 0], "static": true},
          {"shape": {"sphere": {"radius": 0.5}}, "position": [0, 1.5, 0], "restitution": 1}]})",
      "one bounce");
  const physdbg::render::Image image = renderSceneFrame(scene, "aabbs,contacts", 1, 30);
  EXPECT_GE(findColor(image, dd::colors::colliding).count, 20);
  EXPECT_GE(findColor(image, dd::colors::contactPoint).count, 5);
}

TEST(ContactsAsTheEngineSawThem, ASleepingStackStillShowsItsContactDotsDimmed) {
  const physdbg::SceneDescription scene = physdbg::resolveScene("stack");
  const physdbg::render::Image image = renderSceneFrame(scene, "contacts", 240);
  EXPECT_GE(findColor(image, dimmed(dd::colors::contactPoint), 12).count, 10);
}

}  // namespace
