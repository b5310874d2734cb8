#include "viewer/scene_camera.h"

#include <cmath>
#include <numbers>
#include <stdexcept>


namespace physdbg::viewer {

render::Camera chooseCamera(const SceneDescription& scene, const debugdraw::Frame& firstFrame, double aspect) {
  const render::Bounds bounds = render::frameBounds(firstFrame);
  render::Camera camera = render::frameBoundsCamera(bounds, aspect);
  if (!scene.camera) return camera;
  const SceneCamera& wanted = *scene.camera;
  const Eigen::Vector3d offset = camera.eye - camera.target;
  if (wanted.target) camera.target = *wanted.target;
  camera.eye = wanted.eye ? *wanted.eye : camera.target + offset;
  camera.fovYDegrees = wanted.fovYDegrees;
  camera.orthographic = wanted.orthographic;
  if (camera.orthographic && !bounds.empty()) camera.orthoHeight = 1.1 * (bounds.max - bounds.min).norm();
  // An eye straight above the target would make "up" degenerate.
  const Eigen::Vector3d view = (camera.target - camera.eye).normalized();
  if (std::abs(view.dot(camera.up)) > 0.999) camera.up = Eigen::Vector3d::UnitZ();
  render::validateCamera(camera);
  return camera;
}

namespace {

// A view of the body from a few of its sizes away, so it fills about a third of the picture.
render::Camera followCamera(const debugdraw::BodyInfo& body, double aspect) {
  const Eigen::Vector3d centre = 0.5 * (body.boundsMin + body.boundsMax);
  const Eigen::Vector3d half = (0.5 * (body.boundsMax - body.boundsMin)).cwiseMax(Eigen::Vector3d::Constant(0.5)) * 3.0;
  render::Bounds bounds;
  bounds.extend(centre - half);
  bounds.extend(centre + half);
  return render::frameBoundsCamera(bounds, aspect);
}

}  // namespace

render::Camera applyCameraOptions(render::Camera camera, const CameraOptions& options,
                                  const debugdraw::BodyInfo* followed, double aspect) {
  if (options.follow && followed) camera = followCamera(*followed, aspect);
  const Eigen::Vector3d offset = camera.eye - camera.target;
  if (options.target) camera.target = *options.target;
  camera.eye = options.eye ? *options.eye : camera.target + offset;
  if (options.fovYDegrees) camera.fovYDegrees = *options.fovYDegrees;
  if (options.orthographic) {
    camera.orthographic = true;
    // Same visible height at the target as the perspective view had.
    camera.orthoHeight =
        2.0 * (camera.eye - camera.target).norm() * std::tan(camera.fovYDegrees * std::numbers::pi / 360.0);
  }
  if (std::abs((camera.target - camera.eye).normalized().dot(camera.up)) > 0.999) camera.up = Eigen::Vector3d::UnitZ();
  try {
    render::validateCamera(camera);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(std::string("camera: ") + error.what());
  }
  return camera;
}

render::Camera followBody(render::Camera camera, const debugdraw::BodyInfo& followed) {
  if (!followed.position.allFinite()) return camera;
  camera.eye += followed.position - camera.target;
  camera.target = followed.position;
  return camera;
}

}  // namespace physdbg::viewer
