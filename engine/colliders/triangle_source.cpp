#include "engine/colliders/triangle_source.h"

#include "engine/colliders/heightfield_collider.h"
#include "engine/colliders/triangle_mesh_collider.h"

namespace physdbg {

const TriangleSource* triangleSourceOf(const Collider& collider) {
  switch (collider.kind()) {
    case ColliderKind::TriangleMesh: return &static_cast<const TriangleMeshCollider&>(collider);
    case ColliderKind::Heightfield: return &static_cast<const HeightfieldCollider&>(collider);
    default: return nullptr;
  }
}

}  // namespace physdbg
