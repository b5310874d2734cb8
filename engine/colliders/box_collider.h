#pragma once
#include "engine/colliders/collider.h"

namespace physdbg {

class BoxCollider final : public Collider {
 public:
  explicit BoxCollider(const Vec3& halfExtents) : halfExtents_(halfExtents) {}

  const Vec3& halfExtents() const { return halfExtents_; }

  ColliderKind kind() const override { return ColliderKind::Box; }
  Vec3 localSupport(const Vec3& direction) const override;
  Aabb localBounds() const override;
  // The box's own centre and |rotation| times its half extents: what the
  // default computes, bit for bit, without the virtual localBounds call or
  // rotating the (zero) local centre. The world asks this for every pair.
  Aabb worldBounds(const Transform& transform) const override;
  double volume() const override;
  Mat3 unitInertia() const override;

 private:
  Vec3 halfExtents_;
};

}  // namespace physdbg
