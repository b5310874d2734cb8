#include "viewer/frame_renderer.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "debugdraw/frame_view.h"
#include "engine/debug/world_debug_draw.h"
#include "render/text_geometry.h"
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
  emitDebugDraw(initial, debugdraw::parseLayers("shapes"), framing);
  return chooseCamera(scene, framing, aspect);
}

debugdraw::Frame sceneFrame(const SceneDescription& scene, const World& world, debugdraw::LayerSet layers,
                            int imageWidth) {
  debugdraw::ViewSelection selection;
  selection.layers = layers;
  selection.imageWidth = imageWidth;
  debugdraw::Frame frame;
  emitDebugDraw(world, debugdraw::layersNeeded(selection), frame);
  emitBodies(world, frame);
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
                              ViewOptions options, const std::string& caption) {
  options.frames = {frameIndex, frameIndex + 1, false};
  options.runFrames = frameIndex + 1;
  options.width = renderer.options().width;
  options.height = renderer.options().height;
  options.timing = false;
  SceneFrames frames(scene, options);
  debugdraw::RecordedFrame frame = frames.frame(frameIndex);
  if (!caption.empty()) {
    const std::array<float, 4> extent = render::textExtent({0, 0, 2, caption, {1, 1, 1, 1}});
    const float x = std::max(8.0f, static_cast<float>(options.width) - (extent[2] - extent[0]) - 8.0f);
    frame.frame.texts.push_back({x, 8, 2, caption, {1.0f, 0.85f, 0.3f, 1}});
  }
  return renderer.render(frame.frame, toCamera(frame.view));
}

render::Image renderSceneFrame(render::Renderer& renderer, const SceneDescription& scene, int steps,
                               debugdraw::LayerSet layers) {
  const World world = simulateScene(scene, steps);
  const double aspect = double(renderer.options().width) / renderer.options().height;
  return renderer.render(sceneFrame(scene, world, layers, renderer.options().width), sceneCamera(scene, aspect));
}

}  // namespace physdbg::viewer
