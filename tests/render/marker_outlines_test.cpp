// Markers' dark outlines are drawn the fast way: arrows laid over the frame
// from a layer (render/outline_layer.h) instead of after four shifted dark
// copies, points with their ring in one pass instead of after a grown dark
// copy of each. The copies are the reference. Arrows must come out byte for
// byte with their outline where the copies put it, whether the footprint is a
// few tiles or, with arrows reaching behind the eye, the whole image; points
// and rings byte for byte.
#include <gtest/gtest.h>

#include <random>

#include "render/renderer.h"
#include "tests/render/test_pictures.h"
#include "tests/support/render_test_support.h"

namespace {

namespace dd = physdbg::debugdraw;
using Eigen::Vector3d;
using physdbg::render::Camera;
using physdbg::render::Image;
using physdbg::render::Renderer;
using physdbg::render::RendererOptions;
using physdbg::render::testing::Pixel;
using physdbg::render::testing::pixelAt;

constexpr int kWidth = 320, kHeight = 240;
// The outline layer's colour; the copies of arrow heads were lit, darker.
constexpr Pixel kOutline{10, 10, 12, 255};

bool isDark(const Pixel& pixel) { return pixel[0] <= 13 && pixel[1] <= 13 && pixel[2] <= 13; }

// Coloured boxes to lie over, and arrows every way at random, some inside the
// boxes, some crossing each other, some leaving the view.
dd::Frame arrowCloud(unsigned seed, int arrows, double alpha) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1, 1), channel(0.2, 1);
  dd::Frame frame;
  for (int box = 0; box < 6; ++box)
    frame.boxes.push_back({Vector3d(2 * unit(random), 2 * unit(random), unit(random)),
                           Eigen::Quaterniond::Identity(),
                           Vector3d(0.5, 0.4, 0.3),
                           {float(channel(random)), float(channel(random)), float(channel(random)), 1}});
  for (int arrow = 0; arrow < arrows; ++arrow) {
    const Vector3d from(3.5 * unit(random), 2.6 * unit(random), 2 * unit(random));
    const Vector3d along = Vector3d(unit(random), unit(random), unit(random)) * (0.05 + 0.8 * (unit(random) + 1));
    frame.arrows.push_back(
        {from, from + along, {float(channel(random)), float(channel(random)), float(channel(random)), float(alpha)}});
  }
  return frame;
}

Image render(const dd::Frame& frame, const Camera& camera, bool byCopies) {
  RendererOptions options{kWidth, kHeight, 0};
  options.outlineMarkersByCopies = byCopies;
  return Renderer(options).render(frame, camera);
}

struct Comparison {
  int arrowPixels = 0, outlinePixels = 0, flipped = 0, other = 0;
};

// A pixel whose centre lies on an edge (to rounding) may fall either side of
// it: a point's ring and inside come from different sprite sizes, and a
// shifted copy clipped at the near plane is rounded apart from its arrow. So
// where two pictures differ, one's colour must be in the other a pixel away.
bool nearby(const Image& reference, int x, int y, const Pixel& want) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if (nx >= 0 && ny >= 0 && nx < kWidth && ny < kHeight && pixelAt(reference, nx, ny) == want) return true;
    }
  return false;
}

// Pixels off the image's edge are left out: a copy shifted in from an arrow
// just outside the view darkened the edge row, the layer has no such pixels.
Comparison compareInside(const Image& layer, const Image& copies, const Image& withoutArrows) {
  Comparison result;
  for (int y = 1; y + 1 < kHeight; ++y)
    for (int x = 1; x + 1 < kWidth; ++x) {
      const Pixel got = pixelAt(layer, x, y), want = pixelAt(copies, x, y);
      if (got == kOutline)
        ++result.outlinePixels;
      else if (got != pixelAt(withoutArrows, x, y))
        ++result.arrowPixels;
      if (got == want || (got == kOutline && isDark(want))) continue;
      ++result.flipped;
      if (!nearby(copies, x, y, got) && !nearby(layer, x, y, want)) ++result.other;
    }
  return result;
}

void expectSamePicture(const dd::Frame& frame, const Camera& camera, const std::string& name) {
  const Image layer = render(frame, camera, false), copies = render(frame, camera, true);
  dd::Frame bare = frame;
  bare.arrows.clear();
  const Comparison result = compareInside(layer, copies, render(bare, camera, false));
  physdbg::render::testing::keepPicture(layer, name + "_layer.png");
  physdbg::render::testing::keepPicture(copies, name + "_copies.png");
  EXPECT_EQ(result.other, 0)
      << "pixels that differ from the shifted copies other than in the outline's shade or at an edge";
  EXPECT_LE(result.flipped, 3) << "pixels at an edge that rounding put on the other side";
  EXPECT_GT(result.arrowPixels, 2000);
  EXPECT_GT(result.outlinePixels, 1000);
}

TEST(MarkerOutlines, OpaqueArrowsComeOutAsWithShiftedCopies) {
  Camera camera;
  camera.eye = {3, 2.5, 9};
  expectSamePicture(arrowCloud(11, 400, 1.0), camera, "outline_cloud");
}

TEST(MarkerOutlines, ArrowsReachingBehindTheEyeComeOutAsWithShiftedCopies) {
  Camera camera;  // among the arrows: some start in front of the eye and end behind it
  camera.eye = {0.3, 0.2, 1.2};
  camera.target = {0, 0, -3};
  expectSamePicture(arrowCloud(12, 400, 1.0), camera, "outline_behind_eye");
}

// A translucent arrow lies over its outline once; the copies overlapped and
// darkened the pixels under it up to four times. Looked at from the front,
// the shaft spans pixel columns 40 to 232, where the lit head starts.
TEST(MarkerOutlines, ATranslucentArrowLiesOverItsOutlineOnce) {
  dd::Frame frame;
  frame.arrows.push_back({{-1.5, 0, 0}, {1.5, 0, 0}, {1.0f, 1.0f, 1.0f, 0.5f}});
  Camera camera;
  camera.orthographic = true;
  camera.orthoHeight = 3;
  const Image image = render(frame, camera, false);
  const Pixel background = pixelAt(render({}, camera, false), 0, 0);
  auto over = [](double top, double alpha, int below) { return top * 255 * alpha + below * (1 - alpha); };
  int outline = 0, shaft = 0, other = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < 225; ++x) {
      const Pixel pixel = pixelAt(image, x, y);
      if (pixel == background) continue;
      bool isOutline = true, isShaft = true;
      for (int c = 0; c < 3; ++c) {
        const double outlined = over(kOutline[c] / 255.0, 0.5, background[c]);
        isOutline = isOutline && std::abs(pixel[c] - outlined) <= 2;
        isShaft = isShaft && std::abs(pixel[c] - over(1.0, 0.5, static_cast<int>(std::lround(outlined)))) <= 2;
      }
      outline += isOutline;
      shaft += isShaft && !isOutline;
      other += !isOutline && !isShaft;
    }
  EXPECT_GT(outline, 100);
  EXPECT_GT(shaft, 100);
  EXPECT_EQ(other, 0);
}

// Points of every size over bodies and over each other, some centred on
// pixel centres and corners, where a disc's edge passes through pixel centres.
dd::Frame pointCloud(unsigned seed, int points) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1, 1), channel(0.2, 1);
  std::uniform_int_distribution<int> size(1, 14);
  dd::Frame frame = arrowCloud(seed, 0, 1.0);
  for (int point = 0; point < points; ++point) {
    Vector3d at(3.5 * unit(random), 2.6 * unit(random), 2 * unit(random));
    if (point % 4 == 0) at = Vector3d(std::round(at.x() * 16) / 16, std::round(at.y() * 16) / 16, 0);
    frame.points.push_back({at,
                            float(size(random)) + (point % 3 == 0 ? 0.5f : 0.0f),
                            {float(channel(random)), float(channel(random)), float(channel(random)), 1}});
  }
  return frame;
}

TEST(MarkerOutlines, PointsAndTheirRingsInOnePassComeOutAsWithGrownCopies) {
  Camera camera;
  camera.orthographic = true;  // 40 px per metre: 1/16 m steps land on pixel corners and centres
  camera.orthoHeight = 6;
  const dd::Frame frame = pointCloud(13, 1500);
  const Image onePass = render(frame, camera, false), copies = render(frame, camera, true);
  physdbg::render::testing::keepPicture(onePass, "points_one_pass.png");
  int different = 0, unexplained = 0, ring = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const Pixel got = pixelAt(onePass, x, y);
      ring += isDark(got);
      if (got == pixelAt(copies, x, y)) continue;
      ++different;
      unexplained += !nearby(copies, x, y, got) && !nearby(onePass, x, y, pixelAt(copies, x, y));
    }
  EXPECT_EQ(unexplained, 0);
  EXPECT_LT(different, 200) << "of 76800; points off the pixel grid alone differ in one pixel";
  EXPECT_GT(ring, 2000);
}

TEST(MarkerOutlines, PointsOffThePixelGridComeOutAsWithGrownCopies) {
  Camera camera;
  camera.eye = {1, 2, 9};
  dd::Frame frame = pointCloud(14, 1500);
  for (auto& point : frame.points) point.position.z() += 0.001;  // off every grid
  const Image onePass = render(frame, camera, false), copies = render(frame, camera, true);
  int different = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) different += pixelAt(onePass, x, y) != pixelAt(copies, x, y);
  EXPECT_LE(different, 3);
}

// Multisampled, markers keep the copies drawn first: the layer needs single
// coverage, and a point's ring stays under the samples its edge pixels share.
TEST(MarkerOutlines, MultisampledMarkersKeepTheCopies) {
  Camera camera;
  camera.eye = {3, 2.5, 9};
  dd::Frame frame = arrowCloud(15, 60, 1.0);
  const dd::Frame points = pointCloud(16, 200);
  frame.points = points.points;
  RendererOptions options{kWidth, kHeight, 4};
  const Image multisampled = Renderer(options).render(frame, camera);
  options.outlineMarkersByCopies = true;
  EXPECT_EQ(multisampled.rgba, Renderer(options).render(frame, camera).rgba);
  options.samples = 0;
  EXPECT_NE(multisampled.rgba, Renderer(options).render(frame, camera).rgba) << "the samples must show";
}

}  // namespace
