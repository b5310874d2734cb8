#pragma once
// The feature of a shape that faces a direction: a face polygon for boxes and
// hulls, a segment for a capsule lying across the direction, else a point.
// Clipping one shape's feature against the other's face gives the manifold.
#include <vector>

#include "engine/colliders/collider.h"

namespace physdbg {

struct SupportingFeature {
  std::vector<Vec3> points;  // world; 1 (point), 2 (segment) or >= 3 (face, counter-clockwise from outside)
  Vec3 normal = Vec3::UnitY();  // outward face normal (faces only)
  int index = 0;               // face or segment id, stable per shape, for feature ids
  bool isFace() const { return points.size() >= 3; }
};

// Fills `feature` (its storage is reused). `direction` points out of the shape.
// A face is chosen only when its normal is within about 3 degrees of the
// direction's best face, so tilted contacts fall back to fewer points.
void findSupportingFeature(const Collider& collider, const Transform& transform, const Vec3& direction,
                           SupportingFeature& feature);

}  // namespace physdbg
