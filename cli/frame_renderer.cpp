#include "cli/frame_renderer.h"

#include <stdexcept>
#include <string>

#include "cli/scene_camera.h"
#include "cli/scene_overlay.h"

namespace physdbg::cli {

World simulateScene(const SceneDescription& scene, int steps) {
  if (steps < 0) throw std::invalid_argument("simulateScene: steps must be >= 0, got " + std::to_string(steps));
  World world = buildWorld(scene);
  for (int step = 0; step < steps; ++step) world.step();
  return world;
}

render::Camera sceneCamera(const SceneDescription& scene, double aspect) {
  const World initial = buildWorld(scene);
  debugdraw::Frame framing;
  initial.emitDebugDraw(debugdraw::parseLayers("shapes"), framing);
  return chooseCamera(scene, framing, aspect);
}

debugdraw::Frame sceneFrame(const SceneDescription& scene, const World& world, debugdraw::LayerSet layers,
                            int imageWidth) {
  debugdraw::Frame frame;
  world.emitDebugDraw(layers, frame);
  if (layers.has(debugdraw::Layer::Overlay)) {
    OverlayCounters counters;
    counters.imageWidth = imageWidth;
    addOverlay(scene, world, counters, frame);
  }
  return frame;
}

render::Image renderSceneFrame(render::Renderer& renderer, const SceneDescription& scene, int steps,
                               debugdraw::LayerSet layers) {
  const World world = simulateScene(scene, steps);
  const double aspect = double(renderer.options().width) / renderer.options().height;
  return renderer.render(sceneFrame(scene, world, layers, renderer.options().width), sceneCamera(scene, aspect));
}

}  // namespace physdbg::cli
