#include "engine/colliders/triangle_mesh_collider.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>

namespace physdbg {
namespace {

// A triangle whose area is below this share of its longest edge squared is
// a sliver with no trustworthy normal (its smallest angle under ~1e-10 rad).
constexpr double degenerateRatio = 1e-10;

struct EdgeUse {
  std::uint32_t low, high;  // vertex indices, low < high
  std::uint32_t triangle;
  int edge;
  bool operator<(const EdgeUse& other) const {
    return std::tie(low, high, triangle, edge) < std::tie(other.low, other.high, other.triangle, other.edge);
  }
};

}  // namespace

TriangleMeshCollider::TriangleMeshCollider(std::vector<Vec3> vertices, const std::vector<MeshTriangle>& triangles,
                                           double activeEdgeDegrees)
    : vertices_(std::move(vertices)) {
  for (std::size_t i = 0; i < vertices_.size(); ++i)
    if (!vertices_[i].allFinite())
      throw std::invalid_argument("vertices[" + std::to_string(i) + "] is not finite");
  triangles_.reserve(triangles.size());
  normals_.reserve(triangles.size());
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const MeshTriangle& triangle = triangles[k];
    for (const std::uint32_t index : triangle)
      if (index >= vertices_.size())
        throw std::invalid_argument("triangles[" + std::to_string(k) + "] names vertex " + std::to_string(index) +
                                    ", past the last of " + std::to_string(vertices_.size()) + " vertices");
    const Vec3 &a = vertices_[triangle[0]], &b = vertices_[triangle[1]], &c = vertices_[triangle[2]];
    const Vec3 cross = (b - a).cross(c - a);
    const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    const double area = cross.norm();
    if (!(area > degenerateRatio * longest) || !std::isfinite(area)) {
      ++dropped_;
      continue;
    }
    triangles_.push_back(triangle);
    normals_.push_back(cross / area);
  }
  if (triangles_.empty())
    throw std::invalid_argument("no triangle with an area (" + std::to_string(dropped_) + " degenerate ones dropped)");
  std::vector<Aabb> boxes(triangles_.size());
  for (std::uint32_t t = 0; t < triangles_.size(); ++t) boxes[t] = triangleBounds(t);
  bounds_ = boxes[0];
  for (const Aabb& box : boxes) bounds_ = bounds_.merged(box);
  markActiveEdges(activeEdgeDegrees);
  bvh_ = TriangleBvh(boxes);
}

// Edges are matched by their two vertex indices: meshes that repeat a
// position under two indices (a seam in an exported file) read as border
// there. Welding them is the loader's business, before this.
void TriangleMeshCollider::markActiveEdges(double activeEdgeDegrees) {
  const double cosThreshold = std::cos(activeEdgeDegrees * M_PI / 180.0);
  std::vector<EdgeUse> uses;
  uses.reserve(3 * triangles_.size());
  for (std::uint32_t t = 0; t < triangles_.size(); ++t)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t p = triangles_[t][e], q = triangles_[t][(e + 1) % 3];
      uses.push_back({std::min(p, q), std::max(p, q), t, e});
    }
  std::sort(uses.begin(), uses.end());
  activeEdges_.assign(triangles_.size(), 0b111);
  const double scale = bounds_.halfExtents().norm();
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j].low == uses[i].low && uses[j].high == uses[i].high) ++j;
    if (j - i == 2) {
      const EdgeUse &first = uses[i], &second = uses[i + 1];
      const MeshTriangle &t1 = triangles_[first.triangle], &t2 = triangles_[second.triangle];
      // Consistent windings run the shared edge in opposite directions;
      // otherwise the second normal is turned round to compare like with like.
      const bool consistent = t1[first.edge] == t2[(second.edge + 1) % 3];
      const Vec3 n1 = normals_[first.triangle];
      const Vec3 n2 = consistent ? normals_[second.triangle] : Vec3(-normals_[second.triangle]);
      const Vec3 beyond = vertices_[t2[(second.edge + 2) % 3]] - vertices_[t1[first.edge]];
      const bool active = isActiveEdge(n1, n2, beyond, cosThreshold, 1e-12 * scale);
      if (!active) {
        activeEdges_[first.triangle] &= static_cast<std::uint8_t>(~(1u << first.edge));
        activeEdges_[second.triangle] &= static_cast<std::uint8_t>(~(1u << second.edge));
      }
    }
    i = j;
  }
}

std::size_t TriangleMeshCollider::activeEdgeCount() const {
  std::size_t count = 0;
  for (const std::uint8_t bits : activeEdges_) count += (bits & 1u) + ((bits >> 1) & 1u) + ((bits >> 2) & 1u);
  return count;
}

Aabb TriangleMeshCollider::triangleBounds(std::uint32_t index) const {
  const MeshTriangle& triangle = triangles_[index];
  const Vec3 &a = vertices_[triangle[0]], &b = vertices_[triangle[1]], &c = vertices_[triangle[2]];
  return {a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)};
}

void TriangleMeshCollider::query(const Aabb& box, std::vector<std::uint32_t>& out) const {
  const std::size_t first = out.size();
  bvh_.query(box, out);
  const auto end = std::remove_if(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(),
                                  [&](std::uint32_t t) { return !triangleBounds(t).overlaps(box); });
  out.erase(end, out.end());
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
}

SourceTriangle TriangleMeshCollider::triangleAt(std::uint32_t index) const {
  const MeshTriangle& triangle = triangles_[index];
  return {{vertices_[triangle[0]], vertices_[triangle[1]], vertices_[triangle[2]]}, normals_[index], activeEdges_[index]};
}

Vec3 TriangleMeshCollider::localSupport(const Vec3& direction) const {
  std::size_t best = 0;
  for (std::size_t i = 1; i < vertices_.size(); ++i)
    if (vertices_[i].dot(direction) > vertices_[best].dot(direction)) best = i;
  return vertices_[best];
}

}  // namespace physdbg
