#include "engine/colliders/sphere_collider.h"

#include <numbers>

namespace physdbg {

Vec3 SphereCollider::localSupport(const Vec3& direction) const {
  const double length = direction.norm();
  if (length == 0.0) return Vec3(radius_, 0.0, 0.0);
  return direction * (radius_ / length);
}

Aabb SphereCollider::localBounds() const {
  return Aabb::fromCenterHalfExtents(Vec3::Zero(), Vec3::Constant(radius_));
}

double SphereCollider::volume() const { return 4.0 / 3.0 * std::numbers::pi * radius_ * radius_ * radius_; }

Mat3 SphereCollider::unitInertia() const { return Mat3::Identity() * (0.4 * radius_ * radius_); }

Aabb SphereCollider::worldBounds(const Transform& transform) const {
  return Aabb::fromCenterHalfExtents(transform.position, Vec3::Constant(radius_));
}

}  // namespace physdbg
