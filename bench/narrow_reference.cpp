#include "bench/narrow_reference.h"

#include <algorithm>
#include <limits>

#include "engine/colliders/convex_hull.h"

namespace physdbg::bench {

double sphereSphereDepth(double radiusA, const Vec3& centreA, double radiusB, const Vec3& centreB) {
  return std::max(0.0, radiusA + radiusB - (centreB - centreA).norm());
}

double boxSphereDepth(const BoxCollider& box, const Transform& boxTransform, double radius, const Vec3& centre) {
  const Vec3 local = boxTransform.applyInverse(centre);
  const Vec3& half = box.halfExtents();
  const Vec3 outside = local - local.cwiseMax(-half).cwiseMin(half);
  if (outside.squaredNorm() > 0.0) return std::max(0.0, radius - outside.norm());
  return radius + (half - local.cwiseAbs()).minCoeff();
}

double polytopeDepth(const std::vector<Vec3>& verticesA, const std::vector<Vec3>& verticesB) {
  std::vector<Vec3> differences;
  differences.reserve(verticesA.size() * verticesB.size());
  const Vec3 origin = verticesA.front();  // keeps the hull arithmetic near zero
  for (const Vec3& a : verticesA) {
    for (const Vec3& b : verticesB) differences.push_back((a - origin) - (b - origin));
  }
  const ConvexHull hull = buildConvexHull(differences);
  double depth = std::numeric_limits<double>::infinity();
  for (const HullFace& face : hull.faces) depth = std::min(depth, face.offset);
  return std::max(0.0, depth);
}

}  // namespace physdbg::bench
