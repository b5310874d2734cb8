#pragma once
// A manifest case's frames, drawn exactly as `physdbg render SCENE --frames
// F:F+1 --no-timing --size WxH --layers LIST [camera] [--solver]` draws frame
// F, so a user can reproduce an approved or failing frame with render. One
// simulation serves all of a case's frames (they are increasing).
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "golden/manifest.h"
#include "render/image.h"
#include "render/renderer.h"

namespace physdbg::golden {

// One renderer per image size, made when first asked for: a GL context is
// costly, and most manifests use one size.
class RendererPool {
 public:
  render::Renderer& forSize(int width, int height);
  // The renderer key (golden_store.h) of this machine's renderer.
  std::string key();
  render::GlIdentity identity();

 private:
  std::map<std::pair<int, int>, std::unique_ptr<render::Renderer>> renderers_;
};

// Throws std::invalid_argument for a view the viewer refuses (a degenerate camera).
std::vector<render::Image> renderCaseFrames(const ManifestCase& golden, RendererPool& renderers);

}  // namespace physdbg::golden
