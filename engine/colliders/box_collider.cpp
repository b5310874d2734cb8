#include "engine/colliders/box_collider.h"

namespace physdbg {

Vec3 BoxCollider::localSupport(const Vec3& direction) const {
  // Ties (a zero component) pick the positive corner so results are deterministic.
  return {direction.x() < 0.0 ? -halfExtents_.x() : halfExtents_.x(),
          direction.y() < 0.0 ? -halfExtents_.y() : halfExtents_.y(),
          direction.z() < 0.0 ? -halfExtents_.z() : halfExtents_.z()};
}

Aabb BoxCollider::localBounds() const { return Aabb::fromCenterHalfExtents(Vec3::Zero(), halfExtents_); }

Aabb BoxCollider::worldBounds(const Transform& transform) const {
  return Aabb::fromCenterHalfExtents(transform.position, transform.rotation.toRotationMatrix().cwiseAbs() * halfExtents_);
}

double BoxCollider::volume() const { return 8.0 * halfExtents_.prod(); }

Mat3 BoxCollider::unitInertia() const {
  const Vec3 size = 2.0 * halfExtents_;
  const Vec3 squared = size.cwiseProduct(size);
  return Vec3(squared.y() + squared.z(), squared.x() + squared.z(), squared.x() + squared.y()).asDiagonal() *
         (1.0 / 12.0);
}

}  // namespace physdbg
