#pragma once
// Meshes the mesh tests build: tessellated floors and ramps whose triangles
// tile a plane, so that their motion can be compared with the same plane
// made of a box.
#include <cmath>
#include <memory>
#include <vector>

#include "engine/colliders/heightfield_collider.h"
#include "engine/colliders/triangle_mesh_collider.h"
#include "engine/dynamics/rigid_body.h"

namespace physdbg::meshtest {

// A square grid of `cells` x `cells` cells of side `cell` in the plane y = 0
// centred on the origin, two triangles a cell, wound so the normals point up
// (a flat heightfield's triangles, as a mesh).
inline std::shared_ptr<TriangleMeshCollider> gridFloor(int cells, double cell) {
  std::vector<Vec3> vertices;
  std::vector<MeshTriangle> triangles;
  const std::size_t samples = static_cast<std::size_t>(cells + 1) * static_cast<std::size_t>(cells + 1);
  HeightfieldCollider(std::vector<float>(samples, 0.0f), cells + 1, cells + 1, cell, cell, 1.0)
      .sampledGrid(cells, vertices, triangles);
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
