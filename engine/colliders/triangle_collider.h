#pragma once
// One triangle of a mesh, as a convex shape of its own: the narrow phase
// tests a body against a mesh one nearby triangle at a time, through the same
// GJK/EPA and face clipping as any convex pair. Made on the stack for each
// test, in the mesh's frame; it has no volume and no mass.
#include <array>

#include "engine/colliders/collider.h"

namespace physdbg {

class TriangleCollider final : public Collider {
 public:
  // `normal` is the unit normal of a b c (counter-clockwise seen from it).
  TriangleCollider(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal)
      : corners_{a, b, c}, normal_(normal) {}

  const std::array<Vec3, 3>& corners() const { return corners_; }
  const Vec3& normal() const { return normal_; }

  ColliderKind kind() const override { return ColliderKind::Triangle; }
  Vec3 localSupport(const Vec3& direction) const override {
    const double da = corners_[0].dot(direction), db = corners_[1].dot(direction), dc = corners_[2].dot(direction);
    if (da >= db && da >= dc) return corners_[0];
    return db >= dc ? corners_[1] : corners_[2];
  }
  Aabb localBounds() const override {
    return {corners_[0].cwiseMin(corners_[1]).cwiseMin(corners_[2]), corners_[0].cwiseMax(corners_[1]).cwiseMax(corners_[2])};
  }
  double volume() const override { return 0.0; }
  Mat3 unitInertia() const override { return Mat3::Zero(); }

 private:
  std::array<Vec3, 3> corners_;
  Vec3 normal_;
};

}  // namespace physdbg
