#include "engine/colliders/collider.h"

namespace physdbg {

const char* colliderKindName(ColliderKind kind) {
  switch (kind) {
    case ColliderKind::Sphere: return "sphere";
    case ColliderKind::Box: return "box";
    case ColliderKind::Capsule: return "capsule";
    case ColliderKind::ConvexMesh: return "convex";
    case ColliderKind::Triangle: return "triangle";
    case ColliderKind::TriangleMesh: return "mesh";
    case ColliderKind::Heightfield: return "heightfield";
  }
  return "unknown";
}

Aabb Collider::worldBounds(const Transform& transform) const {
  const Aabb local = localBounds();
  const Mat3 rotation = transform.rotation.toRotationMatrix();
  const Vec3 center = transform.apply(local.center());
  const Vec3 half = rotation.cwiseAbs() * local.halfExtents();
  return Aabb::fromCenterHalfExtents(center, half);
}

}  // namespace physdbg
