#include "cli/scene_camera.h"

namespace physdbg::cli {

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

}  // namespace physdbg::cli
