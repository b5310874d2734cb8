#include "engine/narrowphase/support_shape.h"

#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/sphere_collider.h"

namespace physdbg {

SupportShape::SupportShape(const Collider& collider, const Mat3& rotation, const Vec3& position)
    : collider_(collider), kind_(collider.kind()), rotation_(rotation), position_(position) {
  const Aabb bounds = collider.localBounds();
  centre_ = position + rotation * bounds.center();
  size_ = bounds.halfExtents().norm();
  if (kind_ == ColliderKind::Sphere) margin_ = static_cast<const SphereCollider&>(collider).radius();
  if (kind_ == ColliderKind::Box) halfExtents_ = static_cast<const BoxCollider&>(collider).halfExtents();
  rotated_ = !(rotation == Mat3::Identity() && position == Vec3::Zero());
  if (kind_ == ColliderKind::Capsule) margin_ = static_cast<const CapsuleCollider&>(collider).radius();
}

Vec3 SupportShape::support(const Vec3& direction) {
  const Vec3 local = rotated_ ? Vec3(rotation_.transpose() * direction) : direction;
  Vec3 point;
  switch (kind_) {
    case ColliderKind::Sphere: return position_;
    case ColliderKind::Box:  // same corner choice as BoxCollider::localSupport
      point = Vec3(local.x() < 0.0 ? -halfExtents_.x() : halfExtents_.x(),
                   local.y() < 0.0 ? -halfExtents_.y() : halfExtents_.y(),
                   local.z() < 0.0 ? -halfExtents_.z() : halfExtents_.z());
      break;
    case ColliderKind::Capsule: point = static_cast<const CapsuleCollider&>(collider_).localCoreSupport(local); break;
    case ColliderKind::ConvexMesh: {
      const auto& mesh = static_cast<const ConvexMeshCollider&>(collider_);
      hint_ = mesh.supportIndex(local, hint_);
      point = mesh.hullVertices()[hint_];
      break;
    }
    default: point = collider_.localSupport(local);
  }
  return rotated_ ? Vec3(position_ + rotation_ * point) : point;
}

}  // namespace physdbg
