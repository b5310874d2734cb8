// The footprint of a frame's arrows (render/marker_footprint.h) must hold
// every pixel an arrow can reach and its neighbours, in rectangles that never
// overlap: a pixel left out loses its arrow, a pixel in two rectangles is
// laid over twice.
#include "render/marker_footprint.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

#include "render/camera.h"
#include "render/frame_batches.h"

namespace {

namespace dd = physdbg::debugdraw;
using Eigen::Vector3d;
using physdbg::render::PixelRect;

constexpr int kWidth = 640, kHeight = 360;

struct View {
  Eigen::Matrix4f viewProjection;
  physdbg::render::ScreenMapping screen;
};

View viewOf(const physdbg::render::Camera& camera) {
  const Eigen::Matrix4d transform = physdbg::render::projectionMatrix(camera, double(kWidth) / kHeight, 0.05, 100) *
                                    physdbg::render::relativeViewMatrix(camera);
  return {transform.cast<float>(), {transform, kWidth, kHeight}};
}

int rectsHolding(const std::vector<PixelRect>& rects, int x, int y) {
  int count = 0;
  for (const PixelRect& rect : rects) count += x >= rect.x0 && x < rect.x1 && y >= rect.y0 && y < rect.y1;
  return count;
}

// Points on the shaft and on the head's cone as the shaders place them.
std::vector<Vector3d> surfaceOf(const physdbg::render::FrameBatches& batches, std::size_t arrow) {
  std::vector<Vector3d> points;
  const float* from = batches.arrowShafts[2 * arrow].position;
  const float* to = batches.arrowShafts[2 * arrow + 1].position;
  for (int step = 0; step <= 16; ++step) {
    const double t = step / 16.0;
    points.push_back(Vector3d(from[0], from[1], from[2]) * (1 - t) + Vector3d(to[0], to[1], to[2]) * t);
  }
  const auto& head = batches.arrowHeads[arrow];
  const Eigen::Quaterniond rotation(head.rotation[3], head.rotation[0], head.rotation[1], head.rotation[2]);
  const Vector3d base(head.translation[0], head.translation[1], head.translation[2]);
  points.push_back(base + rotation * Vector3d(0, head.scale[1], 0));
  for (int step = 0; step < 64; ++step) {
    const double angle = 2 * std::numbers::pi * step / 64;
    points.push_back(base + rotation * Vector3d(head.scale[0] * std::cos(angle), 0, head.scale[2] * std::sin(angle)));
  }
  return points;
}

TEST(ArrowFootprint, HoldsEveryPixelOfEveryArrowAndItsNeighboursOnce) {
  std::mt19937 random(21);
  std::uniform_real_distribution<double> unit(-1, 1);
  physdbg::render::Camera camera;
  camera.eye = {2, 3, 12};
  const View view = viewOf(camera);
  dd::Frame frame;
  for (int arrow = 0; arrow < 120; ++arrow) {  // sparse, so the tiles leave little slack
    const Vector3d from(8 * unit(random), 4.5 * unit(random), 3 * unit(random));
    frame.arrows.push_back({from, from + Vector3d(unit(random), unit(random), unit(random)) * 0.6, {1, 1, 1, 1}});
  }
  const auto batches = physdbg::render::buildFrameBatches(frame, camera.target, &view.screen);
  const auto rects = physdbg::render::arrowFootprint(batches, view.viewProjection, kWidth, kHeight, 3);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) ASSERT_LE(rectsHolding(rects, x, y), 1) << x << ", " << y;
  int checked = 0;
  for (std::size_t arrow = 0; arrow < batches.arrowHeads.size(); ++arrow)
    for (const Vector3d& point : surfaceOf(batches, arrow)) {
      const Eigen::Vector4d clip = view.screen.viewProjection * point.homogeneous();
      ASSERT_GT(clip.w(), 0);
      const double x = (clip.x() / clip.w() + 1) * 0.5 * kWidth, y = (clip.y() / clip.w() + 1) * 0.5 * kHeight;
      // The pixel holding the point, the pixels a one-pixel line through it
      // may light, and their outline.
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
          const int px = static_cast<int>(std::floor(x)) + dx, py = static_cast<int>(std::floor(y)) + dy;
          if (px < 0 || py < 0 || px >= kWidth || py >= kHeight) continue;
          ++checked;
          EXPECT_EQ(rectsHolding(rects, px, py), 1) << "arrow " << arrow << " at pixel " << px << ", " << py;
        }
    }
  EXPECT_GT(checked, 20000);
  int covered = 0;
  for (const PixelRect& rect : rects) covered += (rect.x1 - rect.x0) * (rect.y1 - rect.y0);
  EXPECT_LT(covered, kWidth * kHeight / 2) << "the footprint of sparse arrows is most of the image";
}

TEST(ArrowFootprint, IsTheWholeImageWhenAnArrowReachesBehindTheEye) {
  physdbg::render::Camera camera;
  const View view = viewOf(camera);
  dd::Frame frame;
  frame.arrows.push_back({{0.2, 0, 5}, {0.2, 0, 15}, {1, 1, 1, 1}});  // from before the eye (z = 10) to behind it
  const auto batches = physdbg::render::buildFrameBatches(frame, camera.target, &view.screen);
  const auto rects = physdbg::render::arrowFootprint(batches, view.viewProjection, kWidth, kHeight, 3);
  ASSERT_EQ(rects.size(), 1u);
  EXPECT_EQ(rects[0].x0, 0);
  EXPECT_EQ(rects[0].y0, 0);
  EXPECT_EQ(rects[0].x1, kWidth);
  EXPECT_EQ(rects[0].y1, kHeight);
}

// An arrow whose end is a hair in front of the eye plane (w ~ 6e-11) while
// its shaft starts on screen: the end projects 1e12 pixels out, past any
// int, and the footprint must still stay in the image. Built by hand with
// floats that hold the hair exactly (the eye is at z = 2^-10, the end at
// 2^-10 - 2^-34), the head pointing away from the eye so no corner is behind it.
TEST(ArrowFootprint, StaysInTheImageForAnArrowEndingJustInFrontOfTheEye) {
  physdbg::render::Camera camera;
  camera.eye = {0, 0, std::ldexp(1.0, -10)};
  const View view = viewOf(camera);
  const float nearEye = static_cast<float>(std::ldexp(1.0, -10) - std::ldexp(1.0, -34));
  for (float side : {1.0f, -1.0f}) {
    physdbg::render::FrameBatches batches;
    batches.arrowShafts.push_back({{0.1f * side, 0.05f, -1}, {1, 1, 1, 1}});
    batches.arrowShafts.push_back({{0.5f * side, 0.25f, nearEye}, {1, 1, 1, 1}});
    physdbg::render::Instance head{};
    head.translation[0] = 0.5f * side, head.translation[1] = 0.25f, head.translation[2] = nearEye;
    head.rotation[0] = -std::sqrt(0.5f), head.rotation[3] = std::sqrt(0.5f);  // y to -z: away from the eye
    head.scale[0] = head.scale[1] = head.scale[2] = 1e-3f;
    batches.arrowHeads.push_back(head);
    const auto rects = physdbg::render::arrowFootprint(batches, view.viewProjection, kWidth, kHeight, 3);
    ASSERT_FALSE(rects.empty());
    for (const PixelRect& rect : rects) {
      EXPECT_TRUE(rect.x0 >= 0 && rect.x0 < rect.x1 && rect.x1 <= kWidth) << rect.x0 << " " << rect.x1;
      EXPECT_TRUE(rect.y0 >= 0 && rect.y0 < rect.y1 && rect.y1 <= kHeight) << rect.y0 << " " << rect.y1;
    }
  }
}

TEST(ArrowFootprint, IsEmptyForArrowsOutOfView) {
  physdbg::render::Camera camera;
  const View view = viewOf(camera);
  dd::Frame frame;
  frame.arrows.push_back({{100, 0, 0}, {101, 0, 0}, {1, 1, 1, 1}});
  frame.arrows.push_back({{0, -80, 0}, {0, -81, 0}, {1, 1, 1, 1}});
  const auto batches = physdbg::render::buildFrameBatches(frame, camera.target, &view.screen);
  EXPECT_TRUE(physdbg::render::arrowFootprint(batches, view.viewProjection, kWidth, kHeight, 3).empty());
  EXPECT_TRUE(physdbg::render::arrowFootprint({}, view.viewProjection, kWidth, kHeight, 3).empty());
}

}  // namespace
