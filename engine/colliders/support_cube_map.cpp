#include "engine/colliders/support_cube_map.h"

#include <algorithm>
#include <cmath>

namespace physdbg {
namespace {

constexpr int kMinCellsPerEdge = 4;
constexpr int kMaxCellsPerEdge = 32;
constexpr double kCellsPerVertex = 24.0;
// Cells are tested with their sides pushed out by this much (in cube-face
// coordinates, which span 2), far more than the rounding of the division
// that sorts a direction into a cell (a few ulps of 1).
constexpr double kCellSlack = 1e-9;
// A settled cell's vertex beats each neighbour by this many climb bands at
// the cell's corners: one for the climb's own test, the rest for rounding of
// the check here and of p . d at lookup (each well under a tenth of a band).
constexpr double kSettledBands = 3.0;

}  // namespace

SupportCubeMap::SupportCubeMap(int vertexCount) {
  const double wanted = std::sqrt(kCellsPerVertex * vertexCount / 6.0);
  cellsPerEdge_ = std::clamp(static_cast<int>(std::ceil(wanted)), kMinCellsPerEdge, kMaxCellsPerEdge);
  halfCells_ = 0.5 * cellsPerEdge_;
  entries_.assign(6 * cellsPerEdge_ * cellsPerEdge_, 0);
}

void SupportCubeMap::assign(const ConvexHull& hull, int cell, int vertex, double bandScale) {
  entries_[cell] = coneInsideNormalCone(hull, cell, vertex, bandScale) ? ~vertex : vertex;
}

int SupportCubeMap::settledCells() const {
  return static_cast<int>(std::count_if(entries_.begin(), entries_.end(), [](int e) { return e < 0; }));
}

Vec3 SupportCubeMap::cellDirection(int cell, double u, double v) const {
  const int face = cell / (cellsPerEdge_ * cellsPerEdge_);
  const int row = cell / cellsPerEdge_ % cellsPerEdge_, column = cell % cellsPerEdge_;
  const int axis = face / 2;
  Vec3 direction;
  direction[axis] = face % 2 == 0 ? 1.0 : -1.0;
  direction[firstOther(axis)] = -1.0 + (row + u) * 2.0 / cellsPerEdge_;
  direction[secondOther(axis)] = -1.0 + (column + v) * 2.0 / cellsPerEdge_;
  return direction;
}

// The cell's directions are the positive combinations of its four corner
// rays, and p . d is linear in d, so a margin that holds at the corners holds
// across the cell (scaled by |d|_1, which is at most the combination of the
// corners' |c|_1, and the band grows with it).
bool SupportCubeMap::coneInsideNormalCone(const ConvexHull& hull, int cell, int vertex, double bandScale) const {
  const double slack = kCellSlack * cellsPerEdge_ / 2.0;  // in cell units
  const Vec3& top = hull.vertices[vertex];
  for (const double u : {-slack, 1.0 + slack}) {
    for (const double v : {-slack, 1.0 + slack}) {
      const Vec3 corner = cellDirection(cell, u, v);
      const double margin = kSettledBands * bandScale * corner.lpNorm<1>();
      for (int k = hull.neighbourStart[vertex]; k < hull.neighbourStart[vertex + 1]; ++k) {
        if (!(corner.dot(hull.neighbourPoints[k] - top) < -margin)) return false;
      }
    }
  }
  return true;
}

}  // namespace physdbg
