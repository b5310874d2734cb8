#pragma once
// Convex hull of a point cloud, built once per convex-mesh collider by
// quickhull with conflict lists (O(n log n) expected: 100k points on a sphere
// take well under a second). The work is done on the cloud moved to its own
// centre and scaled to unit size, so a cloud far from the origin, or 1e-150 or
// 1e150 across, is as exact as one of 1 m at the origin, and which side of a
// triangle a point lies on is decided exactly, so nearly coplanar points can
// never fold the hull over itself. A point within 1e-10 of the cloud's size
// of the hull is left out (duplicates, points on faces). Triangles within
// that, or within the rounding of the coordinates (8 steps of DBL_EPSILON
// times the largest) if more, of one plane make one face, and points inside
// a face or on a straight edge are not vertices.
#include <array>
#include <vector>

#include "engine/math.h"

namespace physdbg {

struct HullFace {
  std::vector<int> vertices;  // counter-clockwise seen from outside
  Vec3 normal;                // outward, unit length
  double offset = 0.0;        // normal . x == offset on the face
};

struct ConvexHull {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;  // outward (counter-clockwise) winding
  std::vector<HullFace> faces;                // coplanar triangles merged into polygons
  // Vertex adjacency in compressed rows: neighbours of v are
  // neighbours[neighbourStart[v] .. neighbourStart[v + 1]).
  std::vector<int> neighbourStart;
  std::vector<int> neighbours;
  std::vector<Vec3> neighbourPoints;  // vertices[neighbours[k]], contiguous for support climbing
};

// Throws std::invalid_argument, saying which, for non-finite values, fewer
// than 4 distinct points, a collinear or flat cloud (thinner than the
// tolerance), or a cloud spanning fewer than 1024 steps of double precision
// at its distance from the origin (1 m at 1e13 m), which is rounding noise.
ConvexHull buildConvexHull(const std::vector<Vec3>& points);

}  // namespace physdbg
