#pragma once
// GPU copies of TriangleMeshes, keyed by TriangleMesh::id (stable for a mesh's
// life). A cached entry whose sizes no longer match is uploaded again; id 0 is
// treated as "no identity" and uploaded every frame. Entries unused for a
// while are dropped so a long run with changing hulls does not grow forever.
#include <cstdint>
#include <map>
#include <optional>

#include "render/gpu_mesh.h"

namespace physdbg::render {

class MeshCache {
 public:
  // The mesh ready to draw for this frame; valid until the next get() or endFrame().
  InstancedMesh& get(const debugdraw::TriangleMesh& mesh);
  void endFrame();

 private:
  struct Entry {
    InstancedMesh gpu;
    std::size_t vertexCount = 0, indexCount = 0;
    std::uint64_t lastUsedFrame = 0;
  };
  static constexpr std::uint64_t kFramesKept = 120;
  std::map<std::uint64_t, Entry> entries_;
  std::optional<InstancedMesh> anonymous_;
  std::uint64_t frame_ = 0;
};

}  // namespace physdbg::render
