#pragma once
// A static triangle mesh: level geometry (floors, ramps, walls, imported
// scenery) for static and kinematic bodies. It has no volume and no mass, so
// a dynamic body cannot own one; bodies collide with its triangles one at a
// time (engine/narrowphase/mesh_contacts.h).
//
// Built once: degenerate triangles are dropped (and counted), each
// triangle's normal is taken from its winding, each edge is marked active or
// not, and a bounding-volume hierarchy is built over the triangles.
//
// Active edges. Where two triangles meet at an edge that is flat, concave, or
// convex by less than activeEdgeAngle, the edge is inactive: the mesh is
// smooth there, and a contact found on it must take the triangle's face
// normal. Otherwise a box sliding across a floor of triangles meets each
// seam as a step (GJK/EPA's normal at an edge tilts toward it) and bumps.
// Edges of one triangle only (the mesh's border) and edges shared by three
// or more are active: there the edge's own normal is the true one.
#include <array>
#include <cstdint>
#include <vector>

#include "engine/colliders/collider.h"
#include "engine/colliders/triangle_bvh.h"
#include "engine/colliders/triangle_source.h"

namespace physdbg {

using MeshTriangle = std::array<std::uint32_t, 3>;

class TriangleMeshCollider final : public Collider, public TriangleSource {
 public:
  // Jolt's default too: a tessellated curve bends by less than this at each
  // edge and reads as smooth; a kerb or step bends by more.
  static constexpr double defaultActiveEdgeDegrees = 5.0;

  // Throws std::invalid_argument naming the triangle (triangles[k]) for an
  // index out of range, and for non-finite vertices (vertices[i]) or no
  // triangle left after dropping the degenerate ones.
  TriangleMeshCollider(std::vector<Vec3> vertices, const std::vector<MeshTriangle>& triangles,
                       double activeEdgeDegrees = defaultActiveEdgeDegrees);

  const std::vector<Vec3>& vertices() const { return vertices_; }
  const std::vector<MeshTriangle>& triangles() const { return triangles_; }
  const Vec3& normal(std::uint32_t triangle) const { return normals_[triangle]; }
  // Edge e of a triangle runs from its corner e to corner (e + 1) % 3.
  bool edgeActive(std::uint32_t triangle, int edge) const { return (activeEdges_[triangle] >> edge) & 1u; }
  // Triangles of the input left out for having (nearly) no area.
  std::size_t droppedTriangles() const { return dropped_; }
  std::size_t activeEdgeCount() const;
  const TriangleBvh& bvh() const { return bvh_; }
  // Appends to `out` the triangles whose boxes overlap `box` (mesh frame),
  // ascending.
  void query(const Aabb& box, std::vector<std::uint32_t>& out) const override;
  SourceTriangle triangleAt(std::uint32_t triangle) const override;
  Aabb triangleBounds(std::uint32_t triangle) const;

  ColliderKind kind() const override { return ColliderKind::TriangleMesh; }
  Vec3 localSupport(const Vec3& direction) const override;
  Aabb localBounds() const override { return bounds_; }
  double volume() const override { return 0.0; }
  Mat3 unitInertia() const override { return Mat3::Zero(); }

 private:
  void markActiveEdges(double activeEdgeDegrees);

  std::vector<Vec3> vertices_;
  std::vector<MeshTriangle> triangles_;
  std::vector<Vec3> normals_;
  std::vector<std::uint8_t> activeEdges_;  // bit e: edge e is active
  std::size_t dropped_ = 0;
  Aabb bounds_;
  TriangleBvh bvh_;
};

}  // namespace physdbg
