#include "render/mesh_cache.h"

namespace physdbg::render {

InstancedMesh& MeshCache::get(const debugdraw::TriangleMesh& mesh) {
  if (mesh.id == 0) {
    anonymous_ = uploadInstancedMesh(flatShadedMesh(mesh), GL_TRIANGLES);
    return *anonymous_;
  }
  auto found = entries_.find(mesh.id);
  if (found == entries_.end() || found->second.vertexCount != mesh.vertices.size() ||
      found->second.indexCount != mesh.indices.size()) {
    Entry entry{uploadInstancedMesh(flatShadedMesh(mesh), GL_TRIANGLES), mesh.vertices.size(), mesh.indices.size(),
                frame_};
    found = entries_.insert_or_assign(mesh.id, std::move(entry)).first;
  }
  found->second.lastUsedFrame = frame_;
  return found->second.gpu;
}

void MeshCache::endFrame() {
  std::erase_if(entries_, [this](const auto& item) { return item.second.lastUsedFrame + kFramesKept < frame_; });
  anonymous_.reset();
  ++frame_;
}

}  // namespace physdbg::render
