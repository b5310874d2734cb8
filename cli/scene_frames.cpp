#include "cli/scene_frames.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "cli/arguments.h"
#include "cli/scene_camera.h"
#include "cli/scene_overlay.h"
#include "engine/broadphase/dynamic_aabb_tree.h"
#include "engine/broadphase/tree_debug_draw.h"

namespace physdbg::cli {
namespace {

namespace dd = debugdraw;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// A view of the body from a few of its sizes away, so it fills about a third of the picture.
render::Camera followCamera(const RigidBody& body, double aspect) {
  const Aabb box = body.collider().worldBounds(body.transform());
  const Vec3 half = box.halfExtents().cwiseMax(Vec3::Constant(0.5)) * 3.0;
  render::Bounds bounds;
  bounds.extend(box.center() - half);
  bounds.extend(box.center() + half);
  return render::frameBoundsCamera(bounds, aspect);
}

}  // namespace

render::Camera toCamera(const dd::View& view) {
  render::Camera camera;
  camera.eye = view.eye;
  camera.target = view.target;
  camera.up = view.up;
  camera.fovYDegrees = view.fovYDegrees;
  camera.orthographic = view.orthographic;
  camera.orthoHeight = view.orthoHeight;
  return camera;
}

dd::View toView(const render::Camera& camera) {
  return {camera.eye, camera.target, camera.up, camera.fovYDegrees, camera.orthographic, camera.orthoHeight};
}

SceneFrames::SceneFrames(const SceneDescription& scene, const ViewOptions& options)
    : scene_(scene), options_(options), world_(buildWorld(scene)) {
  world_.keepContactHistory(true);
}

// Each frame shows the contacts of every step since the previous frame (a
// bounce can begin and end between two frames), so the history starts over
// with each frame's steps, drawn or not.
void SceneFrames::advanceTo(int index) {
  if (index < current_) throw std::invalid_argument("SceneFrames: frames must be asked for in order");
  while (current_ < index) {
    const auto start = Clock::now();
    world_.clearContactHistory();
    for (int step = 0; step < options_.stepsPerFrame; ++step) world_.step();
    const double seconds = secondsSince(start);
    simulateSeconds_ += seconds;
    lastStepMs_ = 1e3 * seconds / options_.stepsPerFrame;
    ++current_;
  }
}

render::Camera SceneFrames::camera() {
  const double aspect = static_cast<double>(options_.width) / options_.height;
  if (!initialCamera_) {
    dd::Frame framing;
    world_.emitDebugDraw(dd::parseLayers("shapes"), framing);
    render::Camera camera = options_.follow ? followCamera(world_.body(*options_.follow), aspect)
                                            : chooseCamera(scene_, framing, aspect);
    const Vec3 offset = camera.eye - camera.target;
    if (options_.target) camera.target = *options_.target;
    camera.eye = options_.eye ? *options_.eye : camera.target + offset;
    if (options_.fovYDegrees) camera.fovYDegrees = *options_.fovYDegrees;
    if (options_.orthographic) {
      camera.orthographic = true;
      // Same visible height at the target as the perspective view had.
      camera.orthoHeight = 2.0 * (camera.eye - camera.target).norm() * std::tan(camera.fovYDegrees * std::numbers::pi / 360.0);
    }
    if (std::abs((camera.target - camera.eye).normalized().dot(camera.up)) > 0.999) camera.up = Vec3::UnitZ();
    try {
      render::validateCamera(camera);
    } catch (const std::invalid_argument& error) {
      throw UsageError(std::string("camera: ") + error.what());
    }
    initialCamera_ = camera;
  }
  render::Camera camera = *initialCamera_;
  if (options_.follow) {
    const Vec3 position = world_.body(*options_.follow).position();
    if (position.allFinite()) {
      camera.eye += position - camera.target;
      camera.target = position;
    }
  }
  return camera;
}

// The engine's layers, and the tree limited to --tree-depth drawn here.
void SceneFrames::drawLayers(dd::Frame& out) {
  dd::LayerSet layers = options_.layers;
  const bool limitTree = layers.has(dd::Layer::Tree) && (options_.treeMinDepth > 0 || options_.treeMaxDepth < (1 << 30));
  if (limitTree) layers.bits &= ~static_cast<std::uint32_t>(dd::Layer::Tree);
  world_.emitDebugDraw(layers, out, &layerCounts_);
  if (limitTree && world_.tree()) {
    TreeDrawOptions tree;
    tree.leaves = false;
    tree.minDepth = options_.treeMinDepth;
    tree.maxDepth = options_.treeMaxDepth;
    const std::size_t before = out.primitiveCount();
    drawTree(*world_.tree(), tree, out);
    layerCounts_.add(dd::Layer::Tree, out.primitiveCount() - before);
  }
}

void SceneFrames::drawOverlay(int index, dd::Frame& out) {
  if (!options_.layers.has(dd::Layer::Overlay)) return;
  const std::size_t before = out.primitiveCount();
  addOverlay(
      scene_, world_,
      {index, options_.runFrames, options_.timing ? std::optional<double>(lastStepMs_) : std::nullopt, options_.width},
      out);
  layerCounts_.add(dd::Layer::Overlay, out.primitiveCount() - before);
}

dd::RecordedFrame SceneFrames::frame(int index) {
  advanceTo(index);
  const auto start = Clock::now();
  dd::RecordedFrame out;
  out.index = index;
  drawLayers(out.frame);
  drawOverlay(index, out.frame);
  out.view = toView(camera());
  drawSeconds_ += secondsSince(start);
  return out;
}

void reportBlankLayers(const std::string& command, const ViewOptions& options, const dd::LayerCounts& counts) {
  const std::string frames = options.frames.count() == 1 ? "frame " + std::to_string(options.frames.first)
                                                         : "frames " + std::to_string(options.frames.first) + ".." +
                                                               std::to_string(options.frames.last - 1);
  for (const auto& [name, layer] : dd::allLayers()) {
    if (options.layers.has(layer) && counts.of(layer) == 0)
      std::fprintf(stderr, "physdbg %s: layer '%s' drew nothing in %s\n", command.c_str(), name.c_str(),
                   frames.c_str());
  }
}

}  // namespace physdbg::cli
