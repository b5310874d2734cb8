#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <set>
#include <stdexcept>

#include "render/renderer.h"
#include "tests/support/render_test_support.h"

namespace physdbg::render {
namespace {

using debugdraw::Color;
using debugdraw::Frame;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using testing::isBackground;
using testing::Pixel;
using testing::pixelAt;
using testing::pixelAtPoint;

constexpr int kWidth = 160, kHeight = 120;
constexpr Color kRed{1.0f, 0.1f, 0.1f, 1.0f};
constexpr Color kGreen{0.1f, 0.85f, 0.2f, 1.0f};

class RendererTest : public ::testing::Test {
 protected:
  Renderer renderer{RendererOptions{kWidth, kHeight, 0}};

  Camera cameraFor(const Frame& frame) { return frameBoundsCamera(frameBounds(frame), double(kWidth) / kHeight); }
};

Frame oneBox(const Vector3d& center, const Color& color) {
  Frame frame;
  frame.boxes.push_back({center, Quaterniond::Identity(), Vector3d(1, 1, 1), color});
  return frame;
}

bool isColor(const Pixel& pixel, const Color& color, int tolerance = 3) {
  return std::abs(pixel[0] - int(color.r * 255 + 0.5f)) <= tolerance &&
         std::abs(pixel[1] - int(color.g * 255 + 0.5f)) <= tolerance &&
         std::abs(pixel[2] - int(color.b * 255 + 0.5f)) <= tolerance;
}

int countPixels(const Image& image, const std::function<bool(const Pixel&)>& predicate) {
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) count += predicate(pixelAt(image, x, y)) ? 1 : 0;
  return count;
}

bool anyNear(const Image& image, const Eigen::Vector2d& at, const std::function<bool(const Pixel&)>& predicate) {
  bool found = false;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) found |= predicate(pixelAt(image, int(at.x()) + dx, int(at.y()) + dy));
  return found;
}

TEST_F(RendererTest, EmptyFrameIsAllBackground) {
  const Image image = renderer.render(Frame{}, Camera{});
  ASSERT_EQ(image.width, kWidth);
  ASSERT_EQ(image.height, kHeight);
  EXPECT_EQ(countPixels(image, [](const Pixel& pixel) { return !isBackground(pixel) || pixel[3] != 255; }), 0);
}

TEST_F(RendererTest, RedBoxIsLitInTheMiddleWithBackgroundCorners) {
  const Frame frame = oneBox(Vector3d::Zero(), kRed);
  const Image image = renderer.render(frame, cameraFor(frame));
  const Pixel centre = pixelAt(image, kWidth / 2, kHeight / 2);
  EXPECT_GT(centre[0], 2 * centre[1]);
  EXPECT_GT(centre[0], 2 * centre[2]);
  EXPECT_GT(centre[0], int(0.3 * 255) + 10);  // more than ambient alone: lit
  for (auto [x, y] : {std::pair{0, 0}, {kWidth - 1, 0}, {0, kHeight - 1}, {kWidth - 1, kHeight - 1}})
    EXPECT_TRUE(isBackground(pixelAt(image, x, y))) << x << "," << y;
}

// A see-through solid (a sensor) drawn before what is inside it must not
// hide it: the red box inside a large translucent grey box still shows red,
// whichever comes first in the frame.
TEST_F(RendererTest, TranslucentSolidsDoNotHideWhatIsInside) {
  for (const bool translucentFirst : {true, false}) {
    Frame frame;
    const auto add = [&](bool outer) {
      if (outer) frame.boxes.push_back({Vector3d::Zero(), Quaterniond::Identity(), Vector3d(3, 3, 3), {0.6f, 0.6f, 0.6f, 0.35f}});
      else frame.boxes.push_back({Vector3d::Zero(), Quaterniond::Identity(), Vector3d(1, 1, 1), kRed});
    };
    add(translucentFirst);
    add(!translucentFirst);
    const Image image = renderer.render(frame, cameraFor(frame));
    const Pixel centre = pixelAt(image, kWidth / 2, kHeight / 2);
    EXPECT_GT(centre[0], centre[1] + 40) << translucentFirst;  // red shows through the grey
    EXPECT_GT(centre[0], centre[2] + 40) << translucentFirst;
  }
}

// Meshes are drawn from both sides: a level's floor seen from below is there.
TEST_F(RendererTest, MeshesShowBothFaces) {
  auto mesh = std::make_shared<debugdraw::TriangleMesh>();
  mesh->id = 7;
  mesh->vertices = {{-1, 0, -1}, {-1, 0, 1}, {1, 0, -1}, {1, 0, 1}};
  mesh->indices = {0, 1, 2, 2, 1, 3};  // counter-clockwise from above
  Frame frame;
  frame.meshes.push_back({Vector3d::Zero(), Quaterniond::Identity(), mesh, kGreen});
  Camera below;
  below.eye = Vector3d(0.5, -3, 0.4);
  below.target = Vector3d::Zero();
  const Image image = renderer.render(frame, below);
  EXPECT_FALSE(isBackground(pixelAt(image, kWidth / 2, kHeight / 2)));
}

TEST_F(RendererTest, VisibleBoxFacesHaveDistinctBrightness) {
  const Frame frame = oneBox(Vector3d::Zero(), Color{0.8f, 0.8f, 0.8f, 1.0f});
  const Camera camera = cameraFor(frame);  // looks down -x, -y, -z: sees +x, +y, +z faces
  const Image image = renderer.render(frame, camera);
  const int top = pixelAtPoint(image, camera, Vector3d(0, 1, 0))[0];
  const int side = pixelAtPoint(image, camera, Vector3d(1, 0, 0))[0];
  const int front = pixelAtPoint(image, camera, Vector3d(0, 0, 1))[0];
  EXPECT_GT(std::abs(top - side), 15);
  EXPECT_GT(std::abs(top - front), 15);
  EXPECT_GT(std::abs(side - front), 15);
}

TEST_F(RendererTest, WireBoxColoursItsEdgesOnly) {
  Frame frame;
  frame.wireBoxes.push_back({Vector3d::Zero(), Quaterniond::Identity(), Vector3d(1, 1, 1), kGreen});
  const Camera camera = cameraFor(frame);
  const Image image = renderer.render(frame, camera);
  // Midpoints of the twelve edges; a line may land on either side of a pixel boundary.
  int edgesSeen = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (double u : {-1.0, 1.0})
      for (double v : {-1.0, 1.0}) {
        Vector3d midpoint = Vector3d::Zero();
        midpoint[(axis + 1) % 3] = u;
        midpoint[(axis + 2) % 3] = v;
        const Eigen::Vector2d at = testing::projectToPixel(camera, kWidth, kHeight, midpoint);
        edgesSeen += anyNear(image, at, [](const Pixel& p) { return isColor(p, kGreen); }) ? 1 : 0;
      }
  EXPECT_EQ(edgesSeen, 12);
  for (const Vector3d& faceCentre : {Vector3d(0, 1, 0), Vector3d(1, 0, 0), Vector3d(0, 0, 1), Vector3d(0, 0, 0)})
    EXPECT_TRUE(isBackground(pixelAtPoint(image, camera, faceCentre))) << faceCentre.transpose();
}

TEST_F(RendererTest, PointsAreRoundDotsOfTheirSize) {
  Frame frame;
  frame.points.push_back({Vector3d::Zero(), 12.0f, debugdraw::colors::contactPoint});
  frame.lines.push_back({Vector3d(-1, -1, -1), Vector3d(1, 1, 1), {0.02f, 0.02f, 0.02f, 0}});  // invisible, sets the view
  const Camera camera = cameraFor(frame);
  const Image image = renderer.render(frame, camera);
  const Eigen::Vector2d at = testing::projectToPixel(camera, kWidth, kHeight, Vector3d::Zero());
  EXPECT_TRUE(isColor(pixelAt(image, int(at.x()), int(at.y())), debugdraw::colors::contactPoint));
  const int dotPixels = countPixels(image, [](const Pixel& p) { return isColor(p, debugdraw::colors::contactPoint); });
  EXPECT_NEAR(dotPixels, M_PI * 36, 20);  // a disc of radius 6, not a 144-pixel square
}

TEST_F(RendererTest, LinesAndArrowsShowUp) {
  Frame frame;
  const Color blue{0.15f, 0.35f, 1.0f, 1.0f};
  frame.lines.push_back({Vector3d(-2, 0, 0), Vector3d(2, 0, 0), blue});
  frame.arrows.push_back({Vector3d(0, -2, 0), Vector3d(0, 2, 0), debugdraw::colors::contactNormal});
  const Camera camera = frameBoundsCamera(frameBounds(frame), double(kWidth) / kHeight, Vector3d(0, 0, -1));
  const Image image = renderer.render(frame, camera);
  EXPECT_GT(countPixels(image, [&](const Pixel& p) { return isColor(p, blue); }), 60);
  // The head is a lit cone: orange-ish pixels with red above green above blue near the tip.
  const Pixel head = pixelAtPoint(image, camera, Vector3d(0, 1.75, 0));
  EXPECT_GT(head[0], head[1]);
  EXPECT_GT(head[1], head[2]);
  EXPECT_FALSE(isBackground(head));
  // The shaft lies on a pixel boundary here: either neighbour may carry it.
  const Eigen::Vector2d shaft = testing::projectToPixel(camera, kWidth, kHeight, Vector3d(0, -1, 0));
  EXPECT_TRUE(anyNear(image, shaft, [](const Pixel& p) { return isColor(p, debugdraw::colors::contactNormal); }));
}

TEST_F(RendererTest, TextIsPixelAlignedWithADarkOutline) {
  Frame frame;
  frame.texts.push_back({10, 10, 2, "HELLO", Color{1, 1, 1, 1}});
  const Image image = renderer.render(frame, Camera{});
  const int white = countPixels(image, [](const Pixel& p) { return p[0] == 255 && p[1] == 255 && p[2] == 255; });
  const int dark = countPixels(image, [](const Pixel& p) { return p[0] < 20 && p[1] < 20 && p[2] < 20; });
  const int blended = countPixels(image, [](const Pixel& p) {
    return !isBackground(p) && !(p[0] == 255 && p[1] == 255 && p[2] == 255) && !(p[0] < 20 && p[1] < 20 && p[2] < 20);
  });
  EXPECT_GT(white, 100);
  EXPECT_GT(dark, 100);
  EXPECT_EQ(blended, 0);  // whole-pixel quads: no partially covered pixels
  EXPECT_TRUE(isBackground(pixelAt(image, kWidth - 1, kHeight - 1)));
}

TEST_F(RendererTest, NonAsciiTextDrawsQuestionMarks) {
  Frame accented, questions;
  accented.texts.push_back({10, 10, 2, "caf\xC3\xA9\t", Color{1, 1, 1, 1}});  // UTF-8 e-acute, then a tab
  questions.texts.push_back({10, 10, 2, "caf???", Color{1, 1, 1, 1}});
  EXPECT_EQ(renderer.render(accented, Camera{}).rgba, renderer.render(questions, Camera{}).rgba);
}

TEST_F(RendererTest, RenderingTwiceGivesIdenticalBytes) {
  Frame frame = oneBox(Vector3d::Zero(), kRed);
  frame.spheres.push_back({Vector3d(2, 0, 0), Quaterniond::Identity(), 0.8, kGreen});
  frame.wireBoxes.push_back({Vector3d::Zero(), Quaterniond::Identity(), Vector3d(1.1, 1.1, 1.1), kGreen});
  frame.texts.push_back({4, 4, 1, "frame 1", Color{}});
  const Camera camera = cameraFor(frame);
  const Image first = renderer.render(frame, camera);
  const Image second = renderer.render(frame, camera);
  EXPECT_EQ(first.rgba, second.rgba);
  Renderer other(RendererOptions{kWidth, kHeight, 0});
  EXPECT_EQ(other.render(frame, camera).rgba, first.rgba);
}

TEST_F(RendererTest, FarFromTheOriginRendersLikeAtTheOrigin) {
  Frame frame = oneBox(Vector3d(0.3, 0, 0), kRed);
  frame.spheres.push_back({Vector3d(-1.7, 0.2, 0.1), Quaterniond::Identity(), 0.6, kGreen});
  frame.lines.push_back({Vector3d(-2, 1.5, 0), Vector3d(2, 1.5, 0.5), Color{}});
  const Camera camera = cameraFor(frame);
  const Vector3d offset(1e7, -1e7, 1e7);
  Frame moved = frame;
  for (auto& box : moved.boxes) box.center += offset;
  for (auto& sphere : moved.spheres) sphere.center += offset;
  for (auto& line : moved.lines) line.from += offset, line.to += offset;
  Camera movedCamera = camera;
  movedCamera.eye += offset;
  movedCamera.target += offset;
  const Image near = renderer.render(frame, camera);
  const Image far = renderer.render(moved, movedCamera);
  int largestDifference = 0;
  for (std::size_t i = 0; i < near.rgba.size(); ++i)
    largestDifference = std::max(largestDifference, std::abs(int(near.rgba[i]) - int(far.rgba[i])));
  EXPECT_LE(largestDifference, 1);
}

TEST_F(RendererTest, ConvexMeshIsDrawnAndReuploadedWhenItChanges) {
  auto octahedron = std::make_shared<debugdraw::TriangleMesh>();
  octahedron->id = 77;
  octahedron->vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  octahedron->indices = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  Frame frame;
  frame.meshes.push_back({Vector3d::Zero(), Quaterniond::Identity(), octahedron, kGreen});
  const Camera camera = frameBoundsCamera(Bounds{Vector3d::Constant(-2), Vector3d::Constant(2)}, 4.0 / 3.0);
  const Image first = renderer.render(frame, camera);
  const Pixel centre = pixelAt(first, kWidth / 2, kHeight / 2);
  EXPECT_GT(centre[1], 2 * centre[0]);
  // Same id, other geometry (only the half facing away): the cache notices.
  auto half = std::make_shared<debugdraw::TriangleMesh>(*octahedron);
  half->indices.erase(half->indices.begin(), half->indices.begin() + 12);
  frame.meshes[0].mesh = half;
  EXPECT_NE(renderer.render(frame, camera).rgba, first.rgba);
}

TEST(RendererMultisampling, IsRepeatableAndBlendsEdges) {
  const Frame frame = oneBox(Vector3d::Zero(), kRed);
  const Camera camera = frameBoundsCamera(frameBounds(frame), double(kWidth) / kHeight);
  Renderer plain(RendererOptions{kWidth, kHeight, 0});
  Renderer smooth(RendererOptions{kWidth, kHeight, 4});
  const Image aliased = plain.render(frame, camera);
  const Image first = smooth.render(frame, camera);
  EXPECT_EQ(smooth.render(frame, camera).rgba, first.rgba);
  // Edge pixels mix box and background: more distinct colours than without MSAA.
  auto distinctColours = [](const Image& image) {
    std::set<std::array<int, 4>> colours;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) colours.insert(pixelAt(image, x, y));
    return colours.size();
  };
  EXPECT_GT(distinctColours(first), distinctColours(aliased) + 10);
}

TEST(RendererInput, BadOptionsAndPrimitivesAreRejected) {
  EXPECT_THROW(Renderer(RendererOptions{0, 10, 0}), std::invalid_argument);
  EXPECT_THROW(Renderer(RendererOptions{10, 10, -1}), std::invalid_argument);
  Renderer renderer(RendererOptions{16, 16, 0});
  Frame frame;
  frame.texts.push_back({0, 0, 0, "x", Color{}});
  EXPECT_THROW(renderer.render(frame, Camera{}), std::invalid_argument);
  frame = Frame{};
  frame.boxes.push_back({Vector3d(std::nan(""), 0, 0), Quaterniond::Identity(), Vector3d::Ones(), Color{}});
  EXPECT_THROW(renderer.render(frame, Camera{}), std::invalid_argument);
  frame = Frame{};
  auto broken = std::make_shared<debugdraw::TriangleMesh>();
  broken->id = 5;
  broken->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  broken->indices = {0, 1, 3};
  frame.meshes.push_back({Vector3d::Zero(), Quaterniond::Identity(), broken, Color{}});
  EXPECT_THROW(renderer.render(frame, Camera{}), std::invalid_argument);
  Camera bad;
  bad.eye = bad.target;
  EXPECT_THROW(renderer.render(Frame{}, bad), std::invalid_argument);
}

}  // namespace
}  // namespace physdbg::render
