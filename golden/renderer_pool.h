#pragma once
// One renderer per image size for a run over many cases, made when first
// asked for: a GL context is costly, and most manifests use one size. The
// renderer key (golden_store.h) comes from the first one.
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "render/renderer.h"

namespace physdbg::golden {

class RendererPool {
 public:
  // Throws std::runtime_error when no GL context can be created.
  render::Renderer& forSize(int width, int height);
  render::GlIdentity identity();
  // This machine's renderer key, e.g. "mesa-22.3.6-llvmpipe".
  std::string key();

 private:
  std::map<std::pair<int, int>, std::unique_ptr<render::Renderer>> renderers_;
};

}  // namespace physdbg::golden
