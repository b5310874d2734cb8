#pragma once
// A segment of half-length halfHeight along local y, swept by a sphere of
// radius. The narrow phase treats it as that segment plus a margin, which
// keeps GJK/EPA on polytopes and the answer exact.
#include "engine/colliders/collider.h"

namespace physdbg {

class CapsuleCollider final : public Collider {
 public:
  // Throws std::invalid_argument unless radius > 0 and halfHeight >= 0 (finite).
  CapsuleCollider(double radius, double halfHeight);

  double radius() const { return radius_; }
  double halfHeight() const { return halfHeight_; }

  // End point of the core segment facing `direction` (the top one on ties).
  Vec3 localCoreSupport(const Vec3& direction) const {
    return {0.0, direction.y() < 0.0 ? -halfHeight_ : halfHeight_, 0.0};
  }

  ColliderKind kind() const override { return ColliderKind::Capsule; }
  Vec3 localSupport(const Vec3& direction) const override;
  Aabb localBounds() const override;
  double volume() const override;
  Mat3 unitInertia() const override;

 private:
  double radius_;
  double halfHeight_;
};

}  // namespace physdbg
