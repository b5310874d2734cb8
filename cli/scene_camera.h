#pragma once
// Chooses the render camera: the scene's own camera where it gives one,
// otherwise a 3/4 view that frames the scene's first frame.
#include "debugdraw/primitives.h"
#include "render/camera.h"
#include "scenes/scene.h"

namespace physdbg::cli {

render::Camera chooseCamera(const SceneDescription& scene, const debugdraw::Frame& firstFrame, double aspect);

}  // namespace physdbg::cli
