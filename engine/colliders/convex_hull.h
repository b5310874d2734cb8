#pragma once
// Convex hull of a point cloud, built once per convex-mesh collider by
// incremental insertion. Points within 1e-10 of the cloud's size of a face
// plane count as on it, so duplicates and coplanar samples are dropped
// instead of producing slivers.
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

// Throws std::invalid_argument for non-finite values, fewer than 4 distinct
// points, or a flat (collinear or coplanar) cloud.
ConvexHull buildConvexHull(const std::vector<Vec3>& points);

}  // namespace physdbg
