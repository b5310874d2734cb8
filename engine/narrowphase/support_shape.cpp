#include "engine/narrowphase/support_shape.h"

#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/sphere_collider.h"

namespace physdbg {

SupportShape::SupportShape(const Collider& collider, const Mat3& rotation, const Vec3& position)
    : collider_(collider), rotation_(rotation), position_(position) {
  const Aabb bounds = collider.localBounds();
  centre_ = position + rotation * bounds.center();
  size_ = bounds.halfExtents().norm();
  if (collider.kind() == ColliderKind::Sphere) margin_ = static_cast<const SphereCollider&>(collider).radius();
  if (collider.kind() == ColliderKind::Capsule) margin_ = static_cast<const CapsuleCollider&>(collider).radius();
}

Vec3 SupportShape::support(const Vec3& direction) {
  const Vec3 local = rotation_.transpose() * direction;
  switch (collider_.kind()) {
    case ColliderKind::Sphere: return position_;
    case ColliderKind::Capsule:
      return position_ + rotation_ * static_cast<const CapsuleCollider&>(collider_).localCoreSupport(local);
    case ColliderKind::ConvexMesh: {
      const auto& mesh = static_cast<const ConvexMeshCollider&>(collider_);
      hint_ = mesh.supportIndex(local, hint_);
      return position_ + rotation_ * mesh.hullVertices()[hint_];
    }
    case ColliderKind::Box: break;
  }
  return position_ + rotation_ * collider_.localSupport(local);
}

}  // namespace physdbg
