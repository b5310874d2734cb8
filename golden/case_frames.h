#pragma once
// A manifest case's frames, drawn exactly as `physdbg render SCENE --frames
// F:F+1 --no-timing --size WxH --layers LIST [camera] [--solver]` draws frame
// F, so a user can reproduce an approved or failing frame with render. One
// simulation serves all of a case's frames (they are increasing). The one
// difference: the overlay's "frame i of N" counts to the case's last frame
// when the case reaches past the scene's own run (render: to F + 1).
#include <vector>

#include "golden/manifest.h"
#include "golden/renderer_pool.h"
#include "render/image.h"

namespace physdbg::golden {

// Throws std::invalid_argument for a view the viewer refuses (a degenerate camera).
std::vector<render::Image> renderCaseFrames(const ManifestCase& golden, RendererPool& renderers);

}  // namespace physdbg::golden
