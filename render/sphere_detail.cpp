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

namespace {

// An instance's radius (scale.x) round its translation, in pixels.
class RadiusOnScreen {
 public:
  RadiusOnScreen(const Camera& camera, int heightPixels)
      : camera_(camera),
        eye_(camera.eye - camera.target),  // instances are relative to the target
        forward_(-eye_.normalized()),
        halfHeight_(0.5 * heightPixels),
        focalPixels_(halfHeight_ / std::tan(camera.fovYDegrees * std::numbers::pi / 360.0)) {}

  double operator()(const Instance& instance) const {
    const double radius = instance.scale[0];
    if (camera_.orthographic) return radius * halfHeight_ / (0.5 * camera_.orthoHeight);
    const Eigen::Vector3d center(instance.translation[0], instance.translation[1], instance.translation[2]);
    const double depth = (center - eye_).dot(forward_);
    return depth > radius ? radius * focalPixels_ / depth : 1e9;  // camera inside or close: finest
  }

 private:
  const Camera& camera_;
  Eigen::Vector3d eye_, forward_;
  double halfHeight_, focalPixels_;
};

}  // namespace

std::array<std::vector<Instance>, kSphereSegments.size()> splitByDetail(const std::vector<Instance>& instances,
                                                                         const Camera& camera, int heightPixels) {
  std::array<std::vector<Instance>, kSphereSegments.size()> levels;
  const RadiusOnScreen radiusPixels(camera, heightPixels);
  for (const Instance& instance : instances) levels[sphereDetailLevel(radiusPixels(instance))].push_back(instance);
  return levels;
}

ConesByDetail splitConesByDetail(const std::vector<Instance>& heads, const Camera& camera, int heightPixels) {
  ConesByDetail split;
  const RadiusOnScreen radiusPixels(camera, heightPixels);
  for (const Instance& head : heads)
    (radiusPixels(head) <= kCoarseConeRadiusPixels ? split.coarse : split.fine).push_back(head);
  return split;
}

}  // namespace physdbg::render
