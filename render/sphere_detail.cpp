#include "render/sphere_detail.h"

#include <cmath>
#include <numbers>

namespace physdbg::render {

int sphereDetailLevel(double radiusPixels) {
  constexpr double kMaxErrorPixels = 0.75;
  for (int level = 0; level < static_cast<int>(kSphereSegments.size()); ++level) {
    const double segments = kSphereSegments[level];
    if (radiusPixels * (1.0 - std::cos(std::numbers::pi / segments)) <= kMaxErrorPixels) return level;
  }
  return static_cast<int>(kSphereSegments.size()) - 1;
}

std::array<std::vector<Instance>, kSphereSegments.size()> splitByDetail(const std::vector<Instance>& instances,
                                                                         const Camera& camera, int heightPixels) {
  std::array<std::vector<Instance>, kSphereSegments.size()> levels;
  const Eigen::Vector3d eye = camera.eye - camera.target;  // instances are relative to the target
  const Eigen::Vector3d forward = -eye.normalized();
  const double halfHeight = 0.5 * heightPixels;
  const double focalPixels = halfHeight / std::tan(camera.fovYDegrees * std::numbers::pi / 360.0);
  for (const Instance& instance : instances) {
    const double radius = instance.scale[0];
    double radiusPixels = radius * halfHeight / (0.5 * camera.orthoHeight);
    if (!camera.orthographic) {
      const Eigen::Vector3d center(instance.translation[0], instance.translation[1], instance.translation[2]);
      const double depth = (center - eye).dot(forward);
      radiusPixels = depth > radius ? radius * focalPixels / depth : 1e9;  // camera inside or close: finest
    }
    levels[sphereDetailLevel(radiusPixels)].push_back(instance);
  }
  return levels;
}

}  // namespace physdbg::render
