#pragma once
// Camera description, framing of a Frame's 3D content, and the view and
// projection matrices the renderer uses (exposed so tests can check framing).
#include <limits>

#include <Eigen/Core>

#include "debugdraw/primitives.h"

namespace physdbg::render {

// Axis-aligned bounds; default-constructed bounds are empty (min > max).
struct Bounds {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  bool empty() const;
  void extend(const Eigen::Vector3d& point);
  void extend(const Bounds& other);
};

// Bounds of every 3D primitive and label anchor (text is screen-space and
// excluded): the depth range then encloses the labels, so one in front of the
// eye is never cut by the near plane.
// Throws std::invalid_argument for a solid mesh without a mesh.
Bounds frameBounds(const debugdraw::Frame& frame);

struct Camera {
  Eigen::Vector3d eye{0, 0, 10}, target{0, 0, 0}, up{0, 1, 0};
  double fovYDegrees = 45;
  bool orthographic = false;
  double orthoHeight = 10;  // world height of the view when orthographic
};

// Camera that frames `bounds` from a 3/4 view above, looking along
// `viewDirection`: the bounding sphere fits inside the narrower field of view.
// Empty bounds give a view of the unit cube at the origin.
Camera frameBoundsCamera(const Bounds& bounds, double aspect,
                         Eigen::Vector3d viewDirection = {-0.6, -0.45, -1.0});

// Throws std::invalid_argument for a degenerate camera (eye at target, up along
// the view, field of view outside (0, 180), non-positive ortho height, NaN).
void validateCamera(const Camera& camera);

// View matrix with the camera target at the origin: the renderer subtracts the
// target (in double) from every position before converting to float.
Eigen::Matrix4d relativeViewMatrix(const Camera& camera);
// GL clip-space projection (depth -1..1); near and far are view distances.
Eigen::Matrix4d projectionMatrix(const Camera& camera, double aspect, double nearDistance,
                                 double farDistance);

}  // namespace physdbg::render
