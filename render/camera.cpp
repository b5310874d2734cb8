#include "render/camera.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace physdbg::render {

using Eigen::Matrix4d;
using Eigen::Vector3d;

bool Bounds::empty() const { return !(min.array() <= max.array()).all(); }

void Bounds::extend(const Vector3d& point) {
  min = min.cwiseMin(point);
  max = max.cwiseMax(point);
}

void Bounds::extend(const Bounds& other) {
  if (other.empty()) return;
  extend(other.min);
  extend(other.max);
}

namespace {

// Box with the given local half extents, rotated and centred.
Bounds orientedBounds(const Vector3d& center, const Eigen::Quaterniond& orientation, const Vector3d& half) {
  const Vector3d reach = orientation.normalized().toRotationMatrix().cwiseAbs() * half.cwiseAbs();
  Bounds bounds;
  bounds.extend(center - reach);
  bounds.extend(center + reach);
  return bounds;
}

Bounds meshBounds(const debugdraw::SolidMesh& solid) {
  if (!solid.mesh) throw std::invalid_argument("frameBounds: solid mesh has no mesh");
  const Eigen::Matrix3d rotation = solid.orientation.normalized().toRotationMatrix();
  Bounds bounds;
  for (const Eigen::Vector3f& vertex : solid.mesh->vertices)
    bounds.extend(solid.center + rotation * vertex.cast<double>());
  return bounds;
}

}  // namespace

Bounds frameBounds(const debugdraw::Frame& frame) {
  Bounds bounds;
  for (const auto& box : frame.boxes) bounds.extend(orientedBounds(box.center, box.orientation, box.halfExtents));
  for (const auto& sphere : frame.spheres) {
    bounds.extend(sphere.center - Vector3d::Constant(std::abs(sphere.radius)));
    bounds.extend(sphere.center + Vector3d::Constant(std::abs(sphere.radius)));
  }
  for (const auto& capsule : frame.capsules) {
    const Vector3d axis = capsule.orientation.normalized() * Vector3d::UnitY();
    const Vector3d reach = axis.cwiseAbs() * std::abs(capsule.halfHeight) +
                           Vector3d::Constant(std::abs(capsule.radius));
    bounds.extend(capsule.center - reach);
    bounds.extend(capsule.center + reach);
  }
  for (const auto& mesh : frame.meshes) bounds.extend(meshBounds(mesh));
  for (const auto& box : frame.wireBoxes)
    bounds.extend(orientedBounds(box.center, box.orientation, box.halfExtents));
  for (const auto& line : frame.lines) {
    bounds.extend(line.from);
    bounds.extend(line.to);
  }
  for (const auto& point : frame.points) bounds.extend(point.position);
  for (const auto& arrow : frame.arrows) {
    bounds.extend(arrow.from);
    bounds.extend(arrow.to);
  }
  for (const auto& label : frame.labels) bounds.extend(label.position);
  return bounds;
}

namespace {

std::array<Vector3d, 8> corners(const Bounds& bounds) {
  std::array<Vector3d, 8> result;
  for (int corner = 0; corner < 8; ++corner)
    result[corner] = Vector3d((corner & 1 ? bounds.max : bounds.min).x(), (corner & 2 ? bounds.max : bounds.min).y(),
                              (corner & 4 ? bounds.max : bounds.min).z());
  return result;
}

// Fraction of the view the framed bounds may fill, leaving a small border.
constexpr double kFill = 0.92;

}  // namespace

Camera frameBoundsCamera(const Bounds& bounds, double aspect, Vector3d viewDirection) {
  if (!(aspect > 0) || !std::isfinite(aspect)) throw std::invalid_argument("frameBoundsCamera: aspect must be positive");
  if (!viewDirection.allFinite() || viewDirection.norm() < 1e-12)
    throw std::invalid_argument("frameBoundsCamera: view direction must be a finite non-zero vector");
  const Bounds framed = bounds.empty() ? Bounds{Vector3d::Constant(-1), Vector3d::Constant(1)} : bounds;
  if (!framed.min.allFinite() || !framed.max.allFinite())
    throw std::invalid_argument("frameBoundsCamera: bounds must be finite");
  Camera camera;
  const Vector3d forward = viewDirection.normalized();
  camera.up = std::abs(forward.y()) > 0.999 ? Vector3d(0, 0, -1) : Vector3d(0, 1, 0);
  camera.target = 0.5 * (framed.min + framed.max);
  const Vector3d right = forward.cross(camera.up).normalized(), up = right.cross(forward);
  // A point-like scene still gets a view of some size around it.
  const double radius =
      std::max(0.5 * (framed.max - framed.min).norm(), 1e-3 * (1.0 + framed.max.cwiseAbs().maxCoeff()));
  const double tanY = kFill * std::tan(camera.fovYDegrees * std::numbers::pi / 360.0), tanX = tanY * aspect;
  // Tight fit: the nearest eye distance along `forward` at which every corner
  // lies inside the frustum, and a little in front of the eye.
  double distance = 0, halfWidth = 0, halfHeight = 0;
  for (const Vector3d& corner : corners(framed)) {
    const Vector3d offset = corner - camera.target;
    const double x = std::abs(offset.dot(right)), y = std::abs(offset.dot(up)), z = offset.dot(forward);
    distance = std::max({distance, x / tanX - z, y / tanY - z, 0.1 * radius - z});
    halfWidth = std::max(halfWidth, x);
    halfHeight = std::max(halfHeight, y);
  }
  camera.eye = camera.target - forward * distance;
  camera.orthoHeight = std::max({2 * halfHeight, 2 * halfWidth / aspect, 0.1 * radius}) / kFill;
  return camera;
}

void validateCamera(const Camera& camera) {
  if (!camera.eye.allFinite() || !camera.target.allFinite() || !camera.up.allFinite())
    throw std::invalid_argument("camera: eye, target and up must be finite");
  const Vector3d forward = camera.target - camera.eye;
  const double scale = std::max({1.0, camera.eye.cwiseAbs().maxCoeff(), camera.target.cwiseAbs().maxCoeff()});
  if (forward.norm() <= 1e-12 * scale) throw std::invalid_argument("camera: eye and target coincide");
  if (camera.up.norm() < 1e-12 || forward.normalized().cross(camera.up.normalized()).norm() < 1e-9)
    throw std::invalid_argument("camera: up must not be parallel to the view direction");
  if (!(camera.fovYDegrees > 0 && camera.fovYDegrees < 180))
    throw std::invalid_argument("camera: fovYDegrees must be in (0, 180), got " + std::to_string(camera.fovYDegrees));
  if (camera.orthographic && !(camera.orthoHeight > 0 && std::isfinite(camera.orthoHeight)))
    throw std::invalid_argument("camera: orthoHeight must be positive");
}

Matrix4d relativeViewMatrix(const Camera& camera) {
  const Vector3d eye = camera.eye - camera.target;  // target sits at the origin
  const Vector3d forward = (-eye).normalized();
  const Vector3d right = forward.cross(camera.up).normalized();
  const Vector3d up = right.cross(forward);
  Matrix4d view = Matrix4d::Identity();
  view.block<1, 3>(0, 0) = right.transpose();
  view.block<1, 3>(1, 0) = up.transpose();
  view.block<1, 3>(2, 0) = -forward.transpose();
  view(0, 3) = -right.dot(eye);
  view(1, 3) = -up.dot(eye);
  view(2, 3) = forward.dot(eye);
  return view;
}

Matrix4d projectionMatrix(const Camera& camera, double aspect, double nearDistance, double farDistance) {
  Matrix4d projection = Matrix4d::Zero();
  const double depth = farDistance - nearDistance;
  if (camera.orthographic) {
    const double halfHeight = 0.5 * camera.orthoHeight;
    projection(0, 0) = 1.0 / (halfHeight * aspect);
    projection(1, 1) = 1.0 / halfHeight;
    projection(2, 2) = -2.0 / depth;
    projection(2, 3) = -(farDistance + nearDistance) / depth;
    projection(3, 3) = 1.0;
    return projection;
  }
  const double focal = 1.0 / std::tan(camera.fovYDegrees * std::numbers::pi / 360.0);
  projection(0, 0) = focal / aspect;
  projection(1, 1) = focal;
  projection(2, 2) = -(farDistance + nearDistance) / depth;
  projection(2, 3) = -2.0 * farDistance * nearDistance / depth;
  projection(3, 2) = -1.0;
  return projection;
}

}  // namespace physdbg::render
