#pragma once
// One repeatable frame of a scene: simulate a number of steps, emit the chosen
// debug layers (with an overlay free of wall-clock values) and render them.
// Shared by golden-image tests and their update tool; the pieces are separate
// so tests can perturb the world or the frame before drawing.
#include "viewer/scene_frames.h"
#include "debugdraw/primitives.h"
#include "render/camera.h"
#include "render/image.h"
#include "render/renderer.h"
#include "scenes/scene.h"

namespace physdbg::viewer {

// Throws std::invalid_argument for negative steps, SceneError for a bad scene.
World simulateScene(const SceneDescription& scene, int steps);

// The camera `render` uses: framed on the scene's initial shapes.
render::Camera sceneCamera(const SceneDescription& scene, double aspect);

// The world's primitives for `layers`, through the viewer's selection as
// `render` draws them; the overlay (when asked for) names the scene, step,
// simulated time and body count.
debugdraw::Frame sceneFrame(const SceneDescription& scene, const World& world, debugdraw::LayerSet layers,
                            int imageWidth = 320);

// Frame `frameIndex` exactly as `physdbg render` draws it with `options`
// (frames, size and timing are set here: the renderer's size, no timing);
// a caption, when given, at the top right (which run a picture shows).
render::Image renderViewFrame(render::Renderer& renderer, const SceneDescription& scene, int frameIndex,
                              ViewOptions options, const std::string& caption = "");

// All of the above at the renderer's size.
render::Image renderSceneFrame(render::Renderer& renderer, const SceneDescription& scene, int steps,
                               debugdraw::LayerSet layers);

}  // namespace physdbg::viewer
