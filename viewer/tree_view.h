#pragma once
// The tree-rotation view as `physdbg tree` writes it: for each rotating event
// (tree_events.h) a before and an after frame, each two panels side by side
// (3D boxes, hierarchy diagram), and a plot of SAR and height against
// insertion count with and without rotations.
#include "render/camera.h"
#include "render/image.h"
#include "render/renderer.h"
#include "scenes/scene.h"
#include "viewer/tree_events.h"

namespace physdbg::viewer {

// The size of each panel: the renderer's.
struct TreePanels {
  render::Renderer& renderer;
  int width = 640, height = 480;
  double margin = 0.1;  // the tree's fat-box margin
};

// Frames the pivots' boxes (everything a rotation touched lies inside them),
// so a small swap is not lost next to a large floor.
render::Camera treeEventCamera(const TreeEvent& event, double aspect);

// The event's before or after frame, two panels side by side.
render::Image renderTreeEventFrame(TreePanels& panels, const TreeEvent& event, bool after,
                                   const render::Camera& camera);

// SAR and height against insertion count, with and without rotations, two
// panels side by side.
struct TreePlot {
  render::Image image;
  TreeCurves withRotations, withoutRotations;
};
TreePlot renderTreePlot(TreePanels& panels, const std::vector<Aabb>& boxes);

// The before or after frame of the `eventIndex`-th insertion of `scene`'s
// bodies that rotates the tree: two panels of the renderer's size side by
// side (3D boxes, hierarchy diagram). Throws std::invalid_argument when the
// scene has fewer rotating insertions.
render::Image renderTreeRotationFrame(const SceneDescription& scene, int eventIndex, bool after,
                                      render::Renderer& renderer);

}  // namespace physdbg::viewer
