#pragma once
// A static bounding-volume hierarchy over a mesh's triangles, built once when
// the mesh is made and only ever queried: a level's floor does not move
// within its own frame, so nothing of the dynamic tree's insertion, rotation
// or fat boxes is needed. The build splits by the surface-area heuristic over
// binned centroids (the cost model the broad phase uses, aabb.h) and stops at
// a few triangles a leaf, where testing the triangles is cheaper than
// descending further.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/aabb.h"

namespace physdbg {

class TriangleBvh {
 public:
  static constexpr int maxLeafTriangles = 4;

  struct Node {
    Aabb bounds;
    // A leaf (count > 0) holds triangles order()[first .. first + count);
    // an inner node (count == 0) has children first and first + 1.
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    bool isLeaf() const { return count > 0; }
  };

  TriangleBvh() = default;
  // `bounds[t]` is triangle t's box. Deterministic: the same boxes give the
  // same tree.
  explicit TriangleBvh(std::span<const Aabb> bounds);

  // Appends to `out` the triangles of every leaf whose box overlaps `box`,
  // in leaf order: a superset of the triangles that overlap it, by fewer
  // than maxLeafTriangles a leaf (the tree keeps no box per triangle).
  void query(const Aabb& box, std::vector<std::uint32_t>& out) const;

  const std::vector<Node>& nodes() const { return nodes_; }  // nodes()[0] is the root, when there is one
  const std::vector<std::uint32_t>& order() const { return order_; }
  int depth() const { return depth_; }

 private:
  void build(std::uint32_t index, std::span<const Aabb> bounds, std::span<const Vec3> centres, std::uint32_t first,
             std::uint32_t count, int depth);

  std::vector<Node> nodes_;
  std::vector<std::uint32_t> order_;
  int depth_ = 0;
};

}  // namespace physdbg
