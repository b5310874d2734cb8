#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "render/camera.h"

namespace physdbg::render {
namespace {

using debugdraw::Frame;
using Eigen::Vector3d;

TEST(FrameBounds, EmptyFrameHasEmptyBounds) { EXPECT_TRUE(frameBounds(Frame{}).empty()); }

TEST(FrameBounds, CoversRotatedBoxSphereCapsuleAndLines) {
  Frame frame;
  const Eigen::Quaterniond quarterTurnZ(Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitZ()));
  frame.boxes.push_back({Vector3d(0, 0, 0), quarterTurnZ, Vector3d(2, 1, 0.5), {}});
  frame.spheres.push_back({Vector3d(10, 0, 0), Eigen::Quaterniond::Identity(), 1.5, {}});
  frame.capsules.push_back({Vector3d(0, 0, -5), quarterTurnZ, 0.5, 2.0, {}});  // axis along -x
  frame.lines.push_back({Vector3d(0, 7, 0), Vector3d(0, 8, 0), {}});
  const Bounds bounds = frameBounds(frame);
  EXPECT_NEAR(bounds.min.x(), -2.5, 1e-12);  // capsule: half height 2 + radius 0.5 along x
  EXPECT_NEAR(bounds.max.x(), 11.5, 1e-12);
  EXPECT_NEAR(bounds.min.y(), -2.0, 1e-12);  // rotated box: x extent 2 now along y
  EXPECT_NEAR(bounds.max.y(), 8.0, 1e-12);
  EXPECT_NEAR(bounds.min.z(), -5.5, 1e-12);
  EXPECT_NEAR(bounds.max.z(), 1.5, 1e-12);
}

TEST(FrameBounds, SolidMeshWithoutMeshIsRejected) {
  Frame frame;
  frame.meshes.push_back({Vector3d::Zero(), Eigen::Quaterniond::Identity(), nullptr, {}});
  EXPECT_THROW(frameBounds(frame), std::invalid_argument);
}

// Every corner of the framed bounds projects inside the view, for random
// scenes, aspects and view directions.
TEST(FrameBoundsCamera, KeepsAllCornersInsideTheFrustum) {
  std::mt19937 generator(42);
  std::uniform_real_distribution<double> coordinate(-50, 50), size(0.01, 20), aspect(0.3, 3.0), unit(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    Bounds bounds;
    const Vector3d center(coordinate(generator), coordinate(generator), coordinate(generator));
    const Vector3d half(size(generator), size(generator), size(generator));
    bounds.extend(center - half);
    bounds.extend(center + half);
    Vector3d direction(unit(generator), unit(generator), unit(generator));
    if (direction.norm() < 0.1) direction = Vector3d(-0.6, -0.45, -1);
    const double ratio = aspect(generator);
    for (bool orthographic : {false, true}) {
      Camera camera = frameBoundsCamera(bounds, ratio, direction);
      camera.orthographic = orthographic;
      ASSERT_NO_THROW(validateCamera(camera));
      const double distance = (camera.eye - camera.target).norm();
      const Eigen::Matrix4d transform =
          projectionMatrix(camera, ratio, 1e-3, 4 * distance) * relativeViewMatrix(camera);
      for (int corner = 0; corner < 8; ++corner) {
        const Vector3d point((corner & 1 ? bounds.max : bounds.min).x(), (corner & 2 ? bounds.max : bounds.min).y(),
                             (corner & 4 ? bounds.max : bounds.min).z());
        const Eigen::Vector4d clip = transform * (point - camera.target).homogeneous();
        ASSERT_GT(clip.w(), 0) << "trial " << trial;
        EXPECT_LE(std::abs(clip.x() / clip.w()), 1.0) << "trial " << trial;
        EXPECT_LE(std::abs(clip.y() / clip.w()), 1.0) << "trial " << trial;
        EXPECT_LE(std::abs(clip.z() / clip.w()), 1.0) << "trial " << trial;
      }
    }
  }
}

TEST(FrameBoundsCamera, LooksAlongTheGivenDirectionAtTheCentre) {
  Bounds bounds{Vector3d(1, 2, 3), Vector3d(3, 4, 5)};
  const Camera camera = frameBoundsCamera(bounds, 16.0 / 9.0, Vector3d(0, -1, 0));  // straight down
  EXPECT_TRUE(camera.target.isApprox(Vector3d(2, 3, 4)));
  EXPECT_TRUE((camera.target - camera.eye).normalized().isApprox(Vector3d(0, -1, 0)));
  EXPECT_NO_THROW(validateCamera(camera));  // up was chosen off the view axis
}

TEST(FrameBoundsCamera, RejectsBadArguments) {
  Bounds bounds{Vector3d::Zero(), Vector3d::Ones()};
  EXPECT_THROW(frameBoundsCamera(bounds, 0.0), std::invalid_argument);
  EXPECT_THROW(frameBoundsCamera(bounds, 1.0, Vector3d::Zero()), std::invalid_argument);
}

TEST(Camera, DegenerateCamerasAreRejected) {
  Camera camera;
  camera.eye = camera.target;
  EXPECT_THROW(validateCamera(camera), std::invalid_argument);
  camera = Camera{};
  camera.up = Vector3d(0, 0, 1);  // along the view
  EXPECT_THROW(validateCamera(camera), std::invalid_argument);
  camera = Camera{};
  camera.fovYDegrees = 180;
  EXPECT_THROW(validateCamera(camera), std::invalid_argument);
  camera = Camera{};
  camera.orthographic = true;
  camera.orthoHeight = 0;
  EXPECT_THROW(validateCamera(camera), std::invalid_argument);
}

}  // namespace
}  // namespace physdbg::render
