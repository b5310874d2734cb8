#pragma once
// The frames of a simulated scene as `render` and `record` see them: the
// world advanced to a frame, its debug-draw primitives for the requested
// layers, the overlay text and the view. Frames before the requested range
// are simulated but not drawn, so a split run matches one long run.
#include <optional>

#include "debugdraw/recording.h"
#include "render/camera.h"
#include "engine/world.h"
#include "scenes/scene.h"
#include "viewer/view_options.h"

namespace physdbg::viewer {

// Show: the frame as drawn, with the options' layers, focus and labels applied.
// Record: every layer, tagged, with each body's state, so a replay can choose
// layers, focus, labels and camera later (debugdraw/frame_view.h).
enum class FramePurpose { Show, Record };

class SceneFrames {
 public:
  // `collision`: the stage for a scene whose collision device is gpu (cli/collision_device.h).
  SceneFrames(const SceneDescription& scene, const ViewOptions& options, FramePurpose purpose = FramePurpose::Show,
              std::shared_ptr<CollisionOffload> collision = nullptr);

  // Frame `index` (>= every earlier call's): simulates up to it and draws it.
  debugdraw::RecordedFrame frame(int index);
  // Labels the text budget left out, most in any frame so far (0: all drawn).
  int labelsLeftOut() const { return labelsLeftOut_; }

  const World& world() const { return world_; }
  // Primitives each layer drew in the frames asked for so far.
  const debugdraw::LayerCounts& layerCounts() const { return layerCounts_; }
  double simulateSeconds() const { return simulateSeconds_; }
  double drawSeconds() const { return drawSeconds_; }

 private:
  void advanceTo(int index);
  void drawLayers(debugdraw::Frame& out);
  void drawBodies(debugdraw::Frame& out);
  void drawGrid(debugdraw::Frame& out);
  void drawOverlay(int index, debugdraw::Frame& out);
  void countShownTree(const debugdraw::Frame& shown);
  render::Camera camera(const debugdraw::Frame& tagged) const;

  const SceneDescription& scene_;
  ViewOptions options_;
  FramePurpose purpose_;
  debugdraw::ViewSelection selection_;
  debugdraw::LayerSet emitted_;  // what the engine is asked for: more than shown for --highlight and recordings
  World world_;
  int current_ = 0;
  double lastStepMs_ = 0, simulateSeconds_ = 0, drawSeconds_ = 0;
  // Framed on the initial state, so every slice of a run (--frames A:B) has the same view.
  render::Camera initialCamera_;
  debugdraw::Frame grid_;  // the grid layer, the same every frame
  debugdraw::LayerCounts layerCounts_;
  int labelsLeftOut_ = 0;
};

// After a run: one line on stderr per requested layer that drew nothing in
// any of the frames, e.g. "physdbg render: layer 'contacts' drew nothing in
// frames 0..59". A blank layer is a fact about the scene, not a failure.
void reportBlankLayers(const std::string& command, const ViewOptions& options, const debugdraw::LayerCounts& counts);

// Every layer, for recordings.
debugdraw::LayerSet allLayerSet();

// One line on stderr when --labels could not label every body in some frame.
void reportLabelsLeftOut(const std::string& command, int leftOut);

render::Camera toCamera(const debugdraw::View& view);
debugdraw::View toView(const render::Camera& camera);

}  // namespace physdbg::viewer
