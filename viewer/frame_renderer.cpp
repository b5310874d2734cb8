#include "viewer/frame_renderer.h"

#include <stdexcept>
#include <string>

#include "debugdraw/frame_view.h"
#include "viewer/scene_camera.h"
#include "viewer/scene_overlay.h"

namespace physdbg::viewer {

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
  debugdraw::ViewSelection selection;
  selection.layers = layers;
  selection.imageWidth = imageWidth;
  debugdraw::Frame frame;
  world.emitDebugDraw(debugdraw::layersNeeded(selection), frame);
  world.emitBodies(frame);
  if (layers.has(debugdraw::Layer::Overlay)) {
    OverlayCounters counters;
    counters.imageWidth = imageWidth;
    const debugdraw::FrameMark mark = debugdraw::markOf(frame);
    addOverlay(scene, world, counters, frame);
    debugdraw::fillTagsSince(frame, mark, debugdraw::tagOf(debugdraw::Layer::Overlay));
  }
  return debugdraw::selectView(frame, selection);
}

render::Image renderViewFrame(render::Renderer& renderer, const SceneDescription& scene, int frameIndex,
                              ViewOptions options) {
  options.frames = {frameIndex, frameIndex + 1, false};
  options.runFrames = frameIndex + 1;
  options.width = renderer.options().width;
  options.height = renderer.options().height;
  options.timing = false;
  SceneFrames frames(scene, options);
  const debugdraw::RecordedFrame frame = frames.frame(frameIndex);
  return renderer.render(frame.frame, toCamera(frame.view));
}

render::Image renderSceneFrame(render::Renderer& renderer, const SceneDescription& scene, int steps,
                               debugdraw::LayerSet layers) {
  const World world = simulateScene(scene, steps);
  const double aspect = double(renderer.options().width) / renderer.options().height;
  return renderer.render(sceneFrame(scene, world, layers, renderer.options().width), sceneCamera(scene, aspect));
}

}  // namespace physdbg::viewer
