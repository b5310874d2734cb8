#include "viewer/scene_frames.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>
#include <stdexcept>

#include "debugdraw/frame_view.h"
#include "debugdraw/ground_grid.h"
#include "engine/debug/world_debug_draw.h"
#include "viewer/scene_camera.h"
#include "viewer/scene_overlay.h"

namespace physdbg::viewer {
namespace {

namespace dd = debugdraw;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Bounds for the ground grid: the scene's footprint, with the bottom raised to
// the ground the moving bodies start above (the top of the highest static body
// entirely below them), so a floor slab does not hide the grid; a hair above
// it, so the lines do not fight the floor's face for depth.
std::pair<Vec3, Vec3> groundGridBounds(const std::vector<dd::BodyInfo>& bodies, const Vec3& up) {
  int axis = 0;
  up.cwiseAbs().maxCoeff(&axis);
  const double sign = up[axis] < 0 ? -1.0 : 1.0;
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  double movingBottom = std::numeric_limits<double>::infinity();
  for (const dd::BodyInfo& body : bodies) {
    if (!body.boundsMin.allFinite() || !body.boundsMax.allFinite()) continue;
    low = low.cwiseMin(body.boundsMin);
    high = high.cwiseMax(body.boundsMax);
    if (!body.isStatic) movingBottom = std::min(movingBottom, sign > 0 ? body.boundsMin[axis] : -body.boundsMax[axis]);
  }
  if (!low.allFinite()) return {Vec3::Zero(), Vec3::Zero()};
  double ground = sign > 0 ? low[axis] : -high[axis];
  for (const dd::BodyInfo& body : bodies) {
    const double top = sign > 0 ? body.boundsMax[axis] : -body.boundsMin[axis];
    if (body.isStatic && std::isfinite(top) && top <= movingBottom + 1e-9) ground = std::max(ground, top);
  }
  ground += 1e-3 * (high - low).norm();
  if (sign > 0) low[axis] = std::min(ground, high[axis]);
  else high[axis] = std::max(-ground, low[axis]);
  return {low, high};
}

}  // namespace

void reportLabelsLeftOut(const std::string& command, int leftOut) {
  if (leftOut > 0)
    std::fprintf(stderr,
                 "physdbg %s: --labels: %d bodies left unlabelled in some frames (the text of a frame is limited to "
                 "%zu characters); --highlight the ones you need, they are labelled first\n",
                 command.c_str(), leftOut, dd::maxFrameTextCharacters);
}

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

dd::LayerSet allLayerSet() {
  dd::LayerSet all;
  for (const auto& [name, layer] : dd::allLayers()) all.add(layer);
  return all;
}

SceneFrames::SceneFrames(const SceneDescription& scene, const ViewOptions& options, FramePurpose purpose,
                         std::shared_ptr<CollisionOffload> collision)
    : scene_(scene),
      options_(options),
      purpose_(purpose),
      selection_(selectionOf(options)),
      emitted_(purpose == FramePurpose::Record ? allLayerSet() : dd::layersNeeded(selection_)),
      world_(buildWorld(scene, std::move(collision))) {
  world_.keepContactHistory(true);
  dd::Frame framing;
  emitDebugDraw(world_, dd::parseLayers("shapes"), framing);
  const double aspect = static_cast<double>(options_.width) / options_.height;
  dd::Frame bodies;
  if (options_.camera.follow) emitBodies(world_, bodies);
  const dd::BodyInfo* followed = options_.camera.follow ? &bodies.bodies.at(*options_.camera.follow) : nullptr;
  initialCamera_ = applyCameraOptions(chooseCamera(scene_, framing, aspect), options_.camera, followed, aspect);
  if (emitted_.has(dd::Layer::Grid)) {
    if (bodies.bodies.empty()) emitBodies(world_, bodies);
    const auto [low, high] = groundGridBounds(bodies.bodies, initialCamera_.up);
    dd::emitGroundGrid(low, high, initialCamera_.up, grid_);
  }
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

render::Camera SceneFrames::camera(const dd::Frame& tagged) const {
  if (!options_.camera.follow) return initialCamera_;
  for (const dd::BodyInfo& body : tagged.bodies)
    if (body.index == *options_.camera.follow) return followBody(initialCamera_, body);
  return initialCamera_;
}

void SceneFrames::drawLayers(dd::Frame& out) {
  dd::LayerCounts emitted;
  emitDebugDraw(world_, emitted_, out, &emitted);
  // A shown tree is counted after --tree-depth (countShownTree).
  for (const auto& [name, layer] : dd::allLayers())
    if (layer != dd::Layer::Tree || purpose_ == FramePurpose::Record) layerCounts_.add(layer, emitted.of(layer));
}

// Body states (with the scene's names) for labels, --highlight, --follow and
// the sleep layer, and always in a recording so its replay can use them.
void SceneFrames::drawBodies(dd::Frame& out) {
  const bool needed = purpose_ == FramePurpose::Record || selection_.labels || !selection_.highlight.empty() ||
                      selection_.follow || emitted_.has(dd::Layer::Sleep);
  if (!needed) return;
  emitBodies(world_, out);
  for (dd::BodyInfo& body : out.bodies) {
    if (static_cast<std::size_t>(body.index) < scene_.bodyNames.size()) body.name = scene_.bodyNames[body.index];
  }
}

// The grid is fixed for the run: built once, copied into each frame.
void SceneFrames::drawGrid(dd::Frame& out) {
  if (!emitted_.has(dd::Layer::Grid)) return;
  const std::size_t before = out.primitiveCount();
  out.lines.insert(out.lines.end(), grid_.lines.begin(), grid_.lines.end());
  out.arrows.insert(out.arrows.end(), grid_.arrows.begin(), grid_.arrows.end());
  out.labels.insert(out.labels.end(), grid_.labels.begin(), grid_.labels.end());
  out.texts.insert(out.texts.end(), grid_.texts.begin(), grid_.texts.end());
  layerCounts_.add(dd::Layer::Grid, out.primitiveCount() - before);
}

void SceneFrames::drawOverlay(int index, dd::Frame& out) {
  if (!emitted_.has(dd::Layer::Overlay)) return;
  const std::size_t before = out.primitiveCount();
  const dd::FrameMark mark = dd::markOf(out);
  addOverlay(
      scene_, world_,
      {index, options_.runFrames, options_.timing ? std::optional<double>(lastStepMs_) : std::nullopt, options_.width},
      out);
  dd::fillTagsSince(out, mark, dd::tagOf(dd::Layer::Overlay));
  layerCounts_.add(dd::Layer::Overlay, out.primitiveCount() - before);
}

// The tree's count is of what --tree-depth lets through.
void SceneFrames::countShownTree(const dd::Frame& shown) {
  std::size_t tree = 0;
  for (const dd::WireBox& box : shown.wireBoxes) tree += box.tag.layer == static_cast<std::uint32_t>(dd::Layer::Tree);
  layerCounts_.add(dd::Layer::Tree, tree);
}

dd::RecordedFrame SceneFrames::frame(int index) {
  advanceTo(index);
  const auto start = Clock::now();
  dd::RecordedFrame out;
  out.index = index;
  out.shownLayers = options_.layers;
  drawGrid(out.frame);
  drawLayers(out.frame);
  drawOverlay(index, out.frame);
  drawBodies(out.frame);
  out.view = toView(camera(out.frame));
  if (purpose_ == FramePurpose::Show) {
    dd::ViewReport report;
    out.frame = dd::selectView(out.frame, selection_, &report);
    labelsLeftOut_ = std::max(labelsLeftOut_, report.labelsLeftOut);
    countShownTree(out.frame);
  }
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

}  // namespace physdbg::viewer
