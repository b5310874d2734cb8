#pragma once
// Convex mesh from a point cloud. The hull is built once; a support query
// takes the best of the few vertices its direction's cube-map cell lists
// (support_cube_map.h). Where a cell has no complete list, it hill-climbs
// over hull-vertex adjacency (a linear function on a convex polytope has no
// local maximum that is not global), starting from the better of the
// caller's warm-start hint and the support of the cell's centre. Small hulls
// are scanned by brute force, which is faster than either.
//
// The answer is the linear scan's, bit for bit, whatever the hints: the
// lowest-numbered vertex of largest p . d. Where the climb stops, neighbours
// within rounding of the top are settled by a short walk over that plateau
// (the vertices of a face seen head-on), so a warm start never changes which
// of several tied vertices comes back, and GJK/EPA results do not depend on
// the order of earlier queries.
//
// The local frame is the one the points are given in; centroid() is the centre
// of mass in that frame and unitInertia() is taken about the centroid. Both
// are exact for hulls of any size; volume() under- or overflows a double for
// hulls under about 1e-100 or over 1e100 across (it is m^3).
#include <array>
#include <vector>

#include "engine/colliders/collider.h"
#include "engine/colliders/convex_hull.h"
#include "engine/colliders/support_cube_map.h"

namespace physdbg {

class ConvexMeshCollider final : public Collider {
 public:
  // Throws std::invalid_argument for < 4 distinct points, a flat cloud or
  // non-finite values.
  explicit ConvexMeshCollider(std::vector<Vec3> points);

  const std::vector<Vec3>& hullVertices() const { return hull_.vertices; }
  const std::vector<HullFace>& hullFaces() const { return hull_.faces; }
  const std::vector<std::array<int, 3>>& hullTriangles() const { return hull_.triangles; }
  const Vec3& centroid() const { return centroid_; }
  const SupportCubeMap& startMap() const { return startMap_; }

  // Index of the support vertex: the lowest index of largest p . direction.
  // `hint` is a vertex to start climbing from, such as an earlier answer
  // along a nearby direction (any value is accepted; out-of-range hints are
  // ignored). It changes how fast the answer comes, never the answer.
  int supportIndex(const Vec3& direction, int hint = -1) const;

  ColliderKind kind() const override { return ColliderKind::ConvexMesh; }
  Vec3 localSupport(const Vec3& direction) const override { return hull_.vertices[supportIndex(direction)]; }
  Aabb localBounds() const override { return bounds_; }
  double volume() const override { return volume_; }
  Mat3 unitInertia() const override { return unitInertia_; }

 private:
  int scan(const Vec3& direction) const;
  int bestListed(const Vec3& direction, const SupportCubeMap::Entry& entry) const;
  int climb(const Vec3& direction, int start, double band) const;
  int settlePlateau(const Vec3& direction, int top, double floor) const;

  ConvexHull hull_;
  SupportCubeMap startMap_;  // climb starts by direction; empty for brute-force hulls
  double bandScale_ = 0.0;  // times |d|_1: the rounding band of p . d (see climb)
  Aabb bounds_;
  Vec3 centroid_ = Vec3::Zero();
  double volume_ = 0.0;
  Mat3 unitInertia_ = Mat3::Zero();
};

}  // namespace physdbg
