#pragma once
// A collider as GJK/EPA see it: a polytope core plus a margin radius, placed
// in the query frame (body A's local frame, so A's supports are exact and far
// translations cancel before any arithmetic). Spheres are a point plus radius
// and capsules a segment plus radius: every core is a polytope, GJK and EPA
// terminate exactly on them, and curved surfaces come back analytically via
// the margin.
#include "engine/colliders/collider.h"

namespace physdbg {

class SupportShape {
 public:
  SupportShape(const Collider& collider, const Mat3& rotation, const Vec3& position);

  // Farthest core point along `direction`, in the query frame.
  Vec3 support(const Vec3& direction);

  double margin() const { return margin_; }
  const Vec3& centre() const { return centre_; }
  // Radius of a ball around centre() holding the whole shape; sets tolerances.
  double size() const { return size_; }

 private:
  const Collider& collider_;
  ColliderKind kind_;  // asked once: kind() is virtual and support() is GJK/EPA's inner call
  Mat3 rotation_;
  Vec3 position_;
  Vec3 centre_;
  double margin_ = 0.0;
  double size_ = 0.0;
  Vec3 halfExtents_ = Vec3::Zero();  // boxes: support inlined, no virtual call
  bool rotated_ = true;              // false for body A, whose frame this is
  int hint_ = -1;                    // warm start for convex meshes, valid for one query
};

}  // namespace physdbg
