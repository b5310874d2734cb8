#pragma once
#include "engine/colliders/collider.h"

namespace physdbg {

class SphereCollider final : public Collider {
 public:
  explicit SphereCollider(double radius) : radius_(radius) {}

  double radius() const { return radius_; }

  ColliderKind kind() const override { return ColliderKind::Sphere; }
  Vec3 localSupport(const Vec3& direction) const override;
  Aabb localBounds() const override;
  double volume() const override;
  Mat3 unitInertia() const override;
  Aabb worldBounds(const Transform& transform) const override;

 private:
  double radius_;
};

}  // namespace physdbg
