#pragma once
// One frame of the tree-rotation view, as `physdbg tree` writes it, for
// callers other than the command (the golden tests).
#include "render/image.h"
#include "render/renderer.h"
#include "scenes/scene.h"

namespace physdbg::cli {

// The before or after frame of the `eventIndex`-th insertion of `scene`'s
// bodies that rotates the tree: two panels of the renderer's size side by
// side (3D boxes, hierarchy diagram). Throws std::invalid_argument when the
// scene has fewer rotating insertions.
render::Image renderTreeRotationFrame(const SceneDescription& scene, int eventIndex, bool after,
                                      render::Renderer& renderer);

}  // namespace physdbg::cli
