#include "engine/colliders/support_cube_map.h"

#include <algorithm>
#include <array>
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
// A vertex left off a cell's list is beaten by a listed one by this many
// rounding bands at the cell's corners: one for the rounding of p . d at
// lookup, the rest for the rounding of the check here (each well under a
// tenth of a band), with room to spare.
constexpr double kListBands = 3.0;

}  // namespace

SupportCubeMap::SupportCubeMap(int vertexCount) {
  const double wanted = std::sqrt(kCellsPerVertex * vertexCount / 6.0);
  cellsPerEdge_ = std::clamp(static_cast<int>(std::ceil(wanted)), kMinCellsPerEdge, kMaxCellsPerEdge);
  halfCells_ = 0.5 * cellsPerEdge_;
  cells_.assign(6 * cellsPerEdge_ * cellsPerEdge_, 0);
}

void SupportCubeMap::assign(const ConvexHull& hull, int cell, int vertex, double bandScale) {
  std::array<int, kMaxCandidates> list;
  const int count = candidatesOf(hull, cell, vertex, bandScale, list);
  if (count == 0) list[0] = vertex;
  // Short lists are padded with their last vertex, which changes no answer,
  // so a lookup weighs kPaddedCount vertices without a branch on the count.
  const int size = std::max(count, kPaddedCount);
  std::fill(list.begin() + std::max(count, 1), list.begin() + size, list[std::max(count, 1) - 1]);
  // Neighbouring cells often have the same list: store it once.
  if (cell > 0) {
    const std::uint32_t previous = cells_[cell - 1];
    const auto first = candidates_.begin() + (previous >> kCountBits);
    if (static_cast<int>(previous & kCountMask) == count && std::equal(list.begin(), list.begin() + size, first)) {
      cells_[cell] = previous;
      return;
    }
  }
  cells_[cell] = static_cast<std::uint32_t>(candidates_.size()) << kCountBits | static_cast<std::uint32_t>(count);
  candidates_.insert(candidates_.end(), list.begin(), list.begin() + size);
}

int SupportCubeMap::answeredCells() const {
  return static_cast<int>(std::count_if(cells_.begin(), cells_.end(), [](std::uint32_t c) { return (c & kCountMask) > 0; }));
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
// corners' |c|_1, and the band grows with it). Every neighbour of a listed
// vertex is either listed or beaten that way by one listed vertex.
int SupportCubeMap::candidatesOf(const ConvexHull& hull, int cell, int vertex, double bandScale,
                                 std::array<int, kMaxCandidates>& listed) const {
  const double slack = kCellSlack * cellsPerEdge_ / 2.0;  // in cell units
  std::array<Vec3, 4> corners;
  std::array<double, 4> margins;
  for (int c = 0; c < 4; ++c) {
    corners[c] = cellDirection(cell, c & 1 ? 1.0 + slack : -slack, c & 2 ? 1.0 + slack : -slack);
    margins[c] = kListBands * bandScale * corners[c].lpNorm<1>();
  }
  const auto beats = [&](int top, int other) {
    for (int c = 0; c < 4; ++c) {
      if (!(corners[c].dot(hull.vertices[other] - hull.vertices[top]) < -margins[c])) return false;
    }
    return true;
  };
  listed[0] = vertex;
  int count = 1;
  const auto end = [&] { return listed.begin() + count; };
  for (int i = 0; i < count; ++i) {  // the list grows while it is walked
    const int from = listed[i];
    for (int k = hull.neighbourStart[from]; k < hull.neighbourStart[from + 1]; ++k) {
      const int neighbour = hull.neighbours[k];
      if (std::find(listed.begin(), end(), neighbour) != end()) continue;
      if (std::any_of(listed.begin(), end(), [&](int top) { return beats(top, neighbour); })) continue;
      if (count == kMaxCandidates) return 0;
      listed[count++] = neighbour;
    }
  }
  std::sort(listed.begin(), end());
  return count;
}

}  // namespace physdbg
