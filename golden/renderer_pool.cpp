#include "golden/renderer_pool.h"

#include "golden/golden_store.h"

namespace physdbg::golden {

render::Renderer& RendererPool::forSize(int width, int height) {
  std::unique_ptr<render::Renderer>& renderer = renderers_[{width, height}];
  if (!renderer) renderer = std::make_unique<render::Renderer>(render::RendererOptions{width, height, 0});
  return *renderer;
}

render::GlIdentity RendererPool::identity() {
  return renderers_.empty() ? forSize(64, 64).glIdentity() : renderers_.begin()->second->glIdentity();
}

std::string RendererPool::key() { return goldenKey(identity()); }

}  // namespace physdbg::golden
