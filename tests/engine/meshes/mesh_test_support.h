#pragma once
// Meshes the mesh tests build: tessellated floors and ramps whose triangles
// tile a plane, so that their motion can be compared with the same plane
// made of a box.
#include <cmath>
#include <memory>
#include <vector>

#include "engine/colliders/triangle_mesh_collider.h"
#include "engine/dynamics/rigid_body.h"

namespace physdbg::meshtest {

// A square grid of `cells` x `cells` cells of side `cell` in the plane y = 0
// centred on the origin, two triangles a cell, wound so the normals point up.
inline std::shared_ptr<TriangleMeshCollider> gridFloor(int cells, double cell) {
  std::vector<Vec3> vertices;
  std::vector<MeshTriangle> triangles;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) vertices.emplace_back((i - 0.5 * cells) * cell, 0.0, (j - 0.5 * cells) * cell);
  const auto at = [cells](int i, int j) { return static_cast<std::uint32_t>(j * (cells + 1) + i); };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j)});
      triangles.push_back({at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)});
    }
  return std::make_shared<TriangleMeshCollider>(std::move(vertices), triangles);
}

inline BodyDefinition staticBody(std::shared_ptr<const Collider> collider, const Vec3& position = Vec3::Zero(),
                                 const Quat& orientation = Quat::Identity()) {
  BodyDefinition body;
  body.collider = std::move(collider);
  body.position = position;
  body.orientation = orientation;
  body.isStatic = true;
  return body;
}

}  // namespace physdbg::meshtest
