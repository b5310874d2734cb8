#pragma once
// Chooses the render camera: the scene's own camera where it gives one,
// otherwise a 3/4 view that frames the scene's first frame.
#include "debugdraw/primitives.h"
#include "render/camera.h"
#include "scenes/scene.h"
#include "viewer/view_options.h"

namespace physdbg::viewer {

render::Camera chooseCamera(const SceneDescription& scene, const debugdraw::Frame& firstFrame, double aspect);

// The camera options applied to a base view (the framed scene for `render`,
// the recorded view for `replay`), so both give one camera for one set of
// options. With --follow the base is a view of the followed body from a few of
// its sizes away. Throws std::invalid_argument for a degenerate
// result (cli/ reports it as a usage error).
render::Camera applyCameraOptions(render::Camera base, const CameraOptions& options,
                                  const debugdraw::BodyInfo* followed, double aspect);

// The camera moved (not turned) so it looks at the followed body's position.
render::Camera followBody(render::Camera camera, const debugdraw::BodyInfo& followed);

}  // namespace physdbg::viewer
