#pragma once
// A convex mesh's support answers by direction: a cube map whose cells each
// list every vertex that can be the support of a direction in the cell, so a
// query takes the best of a few listed vertices (usually one to three)
// instead of climbing the hull. The list is complete, with room for
// rounding: every vertex next to a listed one but left out is beaten by a
// single listed vertex by three rounding bands across the whole cell, and on
// a convex hull the vertices above any level are connected, so nothing
// further away can win either.
//
// A cell whose list would pass kMaxCandidates (a face seen head-on with many
// corners, or a hull with more vertices than the map has cells) keeps only
// where to start climbing: the support of its centre.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "engine/colliders/convex_hull.h"

namespace physdbg {

class SupportCubeMap {
 public:
  static constexpr int kMaxCandidates = 7;
  // Every list holds at least this many entries (see Entry).
  static constexpr int kPaddedCount = 4;

  // What a cell says of the directions in it.
  struct Entry {
    // Ascending; with count 0, vertices[0] is where to climb from. Lists
    // shorter than kPaddedCount repeat their last vertex up to it.
    const int* vertices;
    int count;            // 0 when the cell has no complete list
  };

  SupportCubeMap() = default;
  // Sized for the hull; fill every cell with assign(), in cell order, before
  // any lookup.
  explicit SupportCubeMap(int vertexCount);

  int cellCount() const { return static_cast<int>(cells_.size()); }
  Vec3 cellCentre(int cell) const { return cellDirection(cell, 0.5, 0.5); }
  // `vertex` is the exact support vertex of cellCentre(cell). `bandScale`
  // times |d|_1 bounds the rounding of p . d (see ConvexMeshCollider::climb).
  void assign(const ConvexHull& hull, int cell, int vertex, double bandScale);

  // The cell of a finite, non-zero direction. Inline: GJK and EPA wait on
  // every support, so the lookup is on their critical path.
  Entry lookup(const Vec3& direction) const {
    const std::uint32_t packed = cells_[cellIndex(direction)];
    return {candidates_.data() + (packed >> kCountBits), static_cast<int>(packed & kCountMask)};
  }
  int cellsPerEdge() const { return cellsPerEdge_; }
  int answeredCells() const;  // cells with a complete list

 private:
  static constexpr int kCountBits = 3;
  static constexpr std::uint32_t kCountMask = (1u << kCountBits) - 1;
  static_assert(kMaxCandidates <= static_cast<int>(kCountMask));

  // The two axes of a cube face besides its own, in increasing order.
  static int firstOther(int axis) { return axis == 0 ? 1 : 0; }
  static int secondOther(int axis) { return axis == 2 ? 1 : 2; }

  // Face 2 * axis (+ 1 when the dominant coordinate is negative); within it
  // the other two coordinates over the dominant one, in [-1, 1], cut into
  // cellsPerEdge_ rows and columns.
  int cellIndex(const Vec3& direction) const {
    const double x = std::abs(direction.x()), y = std::abs(direction.y()), z = std::abs(direction.z());
    // Which axis dominates is a coin toss for GJK's directions, so it is
    // worked out without branches: x wins ties with both, y ties with z.
    const int xWins = (x >= y) & (x >= z), yWins = (x < y) & (y >= z);
    const int axis = 2 - 2 * xWins - yWins;
    const double dominant = std::max(x, std::max(y, z));
    const double scale = halfCells_ / dominant;
    const auto coordinate = [&](double other) {
      const int cell = static_cast<int>((other + dominant) * scale);
      return cell < 0 ? 0 : (cell >= cellsPerEdge_ ? cellsPerEdge_ - 1 : cell);
    };
    const int face = 2 * axis + (direction[axis] < 0.0 ? 1 : 0);
    return (face * cellsPerEdge_ + coordinate(direction[firstOther(axis)])) * cellsPerEdge_ +
           coordinate(direction[secondOther(axis)]);
  }
  Vec3 cellDirection(int cell, double u, double v) const;  // u, v in cell units from its low corner
  // Lists every vertex that can be the support somewhere in the cell,
  // ascending, and returns how many; 0 when more than kMaxCandidates would
  // be needed.
  int candidatesOf(const ConvexHull& hull, int cell, int vertex, double bandScale,
                   std::array<int, kMaxCandidates>& listed) const;

  int cellsPerEdge_ = 0;
  double halfCells_ = 0.0;
  std::vector<std::uint32_t> cells_;  // offset into candidates_ << kCountBits | count
  std::vector<int> candidates_;       // the cells' lists, a list shared by neighbouring cells stored once
};

}  // namespace physdbg
