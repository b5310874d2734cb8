#pragma once
// The frames of a simulated scene as `render` and `record` see them: the
// world advanced to a frame, its debug-draw primitives for the requested
// layers, the overlay text and the view. Frames before the requested range
// are simulated but not drawn, so a split run matches one long run.
#include <optional>

#include "cli/view_options.h"
#include "debugdraw/recording.h"
#include "render/camera.h"
#include "scenes/scene.h"

namespace physdbg::cli {

class SceneFrames {
 public:
  SceneFrames(const SceneDescription& scene, const ViewOptions& options);

  // Frame `index` (>= every earlier call's): simulates up to it and draws it.
  debugdraw::RecordedFrame frame(int index);

  const World& world() const { return world_; }
  // Primitives each layer drew in the frames asked for so far.
  const debugdraw::LayerCounts& layerCounts() const { return layerCounts_; }
  double simulateSeconds() const { return simulateSeconds_; }
  double drawSeconds() const { return drawSeconds_; }

 private:
  void advanceTo(int index);
  void drawLayers(debugdraw::Frame& out);
  void drawOverlay(int index, debugdraw::Frame& out);
  render::Camera camera();

  const SceneDescription& scene_;
  ViewOptions options_;
  World world_;
  int current_ = 0;
  double lastStepMs_ = 0, simulateSeconds_ = 0, drawSeconds_ = 0;
  std::optional<render::Camera> initialCamera_;
  debugdraw::LayerCounts layerCounts_;
};

// After a run: one line on stderr per requested layer that drew nothing in
// any of the frames, e.g. "physdbg render: layer 'contacts' drew nothing in
// frames 0..59". A blank layer is a fact about the scene, not a failure.
void reportBlankLayers(const std::string& command, const ViewOptions& options, const debugdraw::LayerCounts& counts);

render::Camera toCamera(const debugdraw::View& view);
debugdraw::View toView(const render::Camera& camera);

}  // namespace physdbg::cli
