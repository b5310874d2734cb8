#pragma once
// Helpers for renderer tests: pixel access and projection of world points to
// pixel coordinates with the renderer's own matrices.
#include <array>
#include <cstdint>
#include <cstdlib>

#include <Eigen/Core>

#include "render/camera.h"
#include "render/image.h"

namespace physdbg::render::testing {

using Pixel = std::array<int, 4>;

inline Pixel pixelAt(const Image& image, int x, int y) {
  const std::size_t offset = (static_cast<std::size_t>(y) * image.width + x) * 4;
  return {image.rgba[offset], image.rgba[offset + 1], image.rgba[offset + 2], image.rgba[offset + 3]};
}

// The clear colour (0.11, 0.12, 0.14) in 8 bits.
inline bool isBackground(const Pixel& pixel) {
  return std::abs(pixel[0] - 28) <= 1 && std::abs(pixel[1] - 31) <= 1 && std::abs(pixel[2] - 36) <= 1;
}

// Pixel position (x right, y down, pixel centres at .5) of a world point.
inline Eigen::Vector2d projectToPixel(const Camera& camera, int width, int height, const Eigen::Vector3d& point) {
  const Eigen::Matrix4d transform =
      projectionMatrix(camera, static_cast<double>(width) / height, 0.01, 1000.0) * relativeViewMatrix(camera);
  const Eigen::Vector4d clip = transform * (point - camera.target).homogeneous();
  const Eigen::Vector2d ndc = clip.head<2>() / clip.w();
  return {(ndc.x() + 1) * 0.5 * width, (1 - ndc.y()) * 0.5 * height};
}

inline Pixel pixelAtPoint(const Image& image, const Camera& camera, const Eigen::Vector3d& point) {
  const Eigen::Vector2d pixel = projectToPixel(camera, image.width, image.height, point);
  return pixelAt(image, static_cast<int>(pixel.x()), static_cast<int>(pixel.y()));
}

}  // namespace physdbg::render::testing
