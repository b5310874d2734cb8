#pragma once
// Reference penetration depths for the narrow-phase benchmark, computed
// independently of GJK/EPA: closed forms for spheres, and for polytopes the
// smallest face offset of the explicit Minkowski difference hull (exact: the
// minimum translation leaves through a face of A - B).
#include <vector>

#include "engine/colliders/box_collider.h"
#include "engine/math.h"

namespace physdbg::bench {

double sphereSphereDepth(double radiusA, const Vec3& centreA, double radiusB, const Vec3& centreB);

double boxSphereDepth(const BoxCollider& box, const Transform& boxTransform, double radius, const Vec3& centre);

// Vertices in world space; 0 when the hulls do not overlap.
double polytopeDepth(const std::vector<Vec3>& verticesA, const std::vector<Vec3>& verticesB);

}  // namespace physdbg::bench
