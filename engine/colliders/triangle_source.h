#pragma once
// Level geometry as the contact code sees it: triangles found by a box and
// read one at a time, each with its corners, its normal and which of its
// edges are active (triangle_mesh_collider.h says what that means). A
// triangle mesh stores its triangles; a heightfield makes them from its
// samples when asked. mesh_contacts.h works on either through this.
#include <array>
#include <cstdint>
#include <vector>

#include "engine/aabb.h"
#include "engine/colliders/triangle_collider.h"

namespace physdbg {

struct SourceTriangle {
  std::array<Vec3, 3> corners;  // counter-clockwise seen from the normal's side
  Vec3 normal;
  std::uint8_t activeEdges = 0b111;  // bit e: the edge from corner e to corner (e + 1) % 3
  bool edgeActive(int edge) const { return (activeEdges >> edge) & 1u; }
  TriangleCollider collider() const { return TriangleCollider(corners[0], corners[1], corners[2], normal); }
};

class TriangleSource {
 public:
  virtual ~TriangleSource() = default;
  // Appends, ascending, every triangle whose box overlaps `box` (source
  // frame), and perhaps a few near ones (a heightfield adds a cell's two
  // triangles together): the contact code tests each.
  virtual void query(const Aabb& box, std::vector<std::uint32_t>& out) const = 0;
  virtual SourceTriangle triangleAt(std::uint32_t triangle) const = 0;
};

// The source a collider is, or null for a convex shape.
const TriangleSource* triangleSourceOf(const Collider& collider);

// The one rule for an edge shared by two triangles: active when the fold is
// convex and sharper than the threshold. `first` and `second` are the two
// normals, the second already turned to agree in winding with the first;
// `beyond` is the second triangle's corner off the edge, relative to a point
// of the edge. A corner above the first triangle's plane (past `flatness`)
// makes the edge concave: smooth whatever its angle.
inline bool isActiveEdge(const Vec3& first, const Vec3& second, const Vec3& beyond, double cosThreshold,
                         double flatness) {
  const bool concave = beyond.dot(first) > flatness;
  return !concave && first.dot(second) < cosThreshold;
}

}  // namespace physdbg
