#pragma once
// Where a convex mesh's support climb starts, by direction: a cube map whose
// cells each hold the support vertex of the direction through the cell's
// centre. A cell whose whole cone of directions lies strictly inside that
// vertex's normal cone is "settled": every direction that looks it up has
// that vertex as its answer, with room for rounding, so the climb is skipped.
//
// Cells are cut finely enough that a typical vertex's normal cone holds
// whole cells (about 24 cells a vertex, at most 32 x 32 a face), so on a
// round 256-vertex hull about half the lookups are settled and most of the
// rest are one climbing step from the answer.
#include <cmath>
#include <vector>

#include "engine/colliders/convex_hull.h"

namespace physdbg {

class SupportCubeMap {
 public:
  // The cell's vertex: the answer when settled, else where to start climbing.
  struct Entry {
    int vertex = 0;
    bool settled = false;
  };

  SupportCubeMap() = default;
  // Sized for the hull; fill every cell with assign() before any lookup.
  explicit SupportCubeMap(int vertexCount);

  int cellCount() const { return static_cast<int>(entries_.size()); }
  Vec3 cellCentre(int cell) const { return cellDirection(cell, 0.5, 0.5); }
  // `vertex` is the exact support vertex of cellCentre(cell). `bandScale`
  // times |d|_1 is the band within which the hull's climb counts a
  // neighbour's p . d as a tie of the top. The cell is settled only when
  // every neighbour of the vertex is below it by three bands across the whole
  // cell, so a climb started there would return the vertex at once.
  void assign(const ConvexHull& hull, int cell, int vertex, double bandScale);

  // The cell of a finite, non-zero direction. Inline: GJK and EPA wait on
  // every support, so the lookup is on their critical path.
  Entry lookup(const Vec3& direction) const {
    const int entry = entries_[cellIndex(direction)];
    return entry < 0 ? Entry{~entry, true} : Entry{entry, false};
  }
  int cellsPerEdge() const { return cellsPerEdge_; }
  int settledCells() const;

 private:
  // The two axes of a cube face besides its own, in increasing order.
  static int firstOther(int axis) { return axis == 0 ? 1 : 0; }
  static int secondOther(int axis) { return axis == 2 ? 1 : 2; }

  // Face 2 * axis (+ 1 when the dominant coordinate is negative); within it
  // the other two coordinates over the dominant one, in [-1, 1], cut into
  // cellsPerEdge_ rows and columns.
  int cellIndex(const Vec3& direction) const {
    const double x = std::abs(direction.x()), y = std::abs(direction.y()), z = std::abs(direction.z());
    const int axis = x >= y ? (x >= z ? 0 : 2) : (y >= z ? 1 : 2);
    const double dominant = axis == 0 ? x : (axis == 1 ? y : z);
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
  bool coneInsideNormalCone(const ConvexHull& hull, int cell, int vertex, double bandScale) const;

  int cellsPerEdge_ = 0;
  double halfCells_ = 0.0;
  std::vector<int> entries_;  // vertex, or ~vertex when settled
};

}  // namespace physdbg
