#include "engine/colliders/heightfield_collider.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace physdbg {

HeightfieldCollider::HeightfieldCollider(std::vector<float> heights, int columns, int rows, double spacingX,
                                         double spacingZ, double scale, double activeEdgeDegrees)
    : heights_(std::move(heights)),
      columns_(columns),
      rows_(rows),
      spacingX_(spacingX),
      spacingZ_(spacingZ),
      scale_(scale),
      cosThreshold_(std::cos(activeEdgeDegrees * M_PI / 180.0)) {
  if (columns < 2 || rows < 2) throw std::invalid_argument("a heightfield needs at least 2 x 2 samples");
  if (heights_.size() != static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows))
    throw std::invalid_argument("a heightfield of " + std::to_string(columns) + " x " + std::to_string(rows) +
                                " samples got " + std::to_string(heights_.size()));
  for (const double value : {spacingX, spacingZ, scale})
    if (!(value > 0.0) || !std::isfinite(value))
      throw std::invalid_argument("a heightfield's spacing and scale must be positive and finite");
  float low = heights_[0], high = heights_[0];
  for (std::size_t k = 0; k < heights_.size(); ++k) {
    if (!std::isfinite(heights_[k]))
      throw std::invalid_argument("sample " + std::to_string(k % columns) + " of row " + std::to_string(k / columns) +
                                  " is not finite");
    low = std::min(low, heights_[k]);
    high = std::max(high, heights_[k]);
  }
  bounds_ = {Vec3(samplePoint(0, 0).x(), low * scale_, samplePoint(0, 0).z()),
             Vec3(samplePoint(columns_ - 1, 0).x(), high * scale_, samplePoint(0, rows_ - 1).z())};
}

Vec3 HeightfieldCollider::samplePoint(int column, int row) const {
  return Vec3((column - 0.5 * (columns_ - 1)) * spacingX_,
              static_cast<double>(heights_[static_cast<std::size_t>(row) * columns_ + column]) * scale_,
              (row - 0.5 * (rows_ - 1)) * spacingZ_);
}

// Half 0 of a cell is (i, j), (i, j + 1), (i + 1, j); half 1 is
// (i + 1, j), (i, j + 1), (i + 1, j + 1): both counter-clockwise from above.
SourceTriangle HeightfieldCollider::shape(int column, int row, int half) const {
  SourceTriangle triangle;
  if (half == 0)
    triangle.corners = {samplePoint(column, row), samplePoint(column, row + 1), samplePoint(column + 1, row)};
  else
    triangle.corners = {samplePoint(column + 1, row), samplePoint(column, row + 1), samplePoint(column + 1, row + 1)};
  triangle.normal =
      (triangle.corners[1] - triangle.corners[0]).cross(triangle.corners[2] - triangle.corners[0]).normalized();
  return triangle;
}

// Edge `edge` of half `half` of cell (column, row), against the triangle
// across it: half 0's edges are west, diagonal, south; half 1's diagonal,
// north, east. Off the field's border, the edge is active.
bool HeightfieldCollider::activeAcross(const SourceTriangle& triangle, int edge, int column, int row, int half) const {
  // The neighbour's corner off the shared edge: its place in the other
  // triangle's corners (shape()).
  int otherColumn = column, otherRow = row, beyondCorner = 0;
  if (half == 0 && edge == 0) otherColumn = column - 1, beyondCorner = 1;  // west: (i - 1, j + 1)
  else if (half == 0 && edge == 1) beyondCorner = 2;                       // diagonal: (i + 1, j + 1)
  else if (half == 0 && edge == 2) otherRow = row - 1, beyondCorner = 0;   // south: (i + 1, j - 1)
  else if (half == 1 && edge == 0) beyondCorner = 0;                       // diagonal: (i, j)
  else if (half == 1 && edge == 1) otherRow = row + 1, beyondCorner = 1;   // north: (i, j + 2)
  else otherColumn = column + 1, beyondCorner = 2;                        // east: (i + 2, j)
  const int otherHalf = 1 - half;
  if (otherColumn < 0 || otherRow < 0 || otherColumn >= columns_ - 1 || otherRow >= rows_ - 1) return true;
  const SourceTriangle other = shape(otherColumn, otherRow, otherHalf);
  const Vec3& beyond = other.corners[beyondCorner];
  const double flatness = 1e-12 * (bounds_.halfExtents().norm() + 1.0);
  return isActiveEdge(triangle.normal, other.normal, beyond - triangle.corners[edge], cosThreshold_, flatness);
}

SourceTriangle HeightfieldCollider::triangleAt(std::uint32_t index) const {
  const int cell = static_cast<int>(index / 2), half = static_cast<int>(index % 2);
  const int column = cell % (columns_ - 1), row = cell / (columns_ - 1);
  SourceTriangle triangle = shape(column, row, half);
  triangle.activeEdges = 0;
  for (int edge = 0; edge < 3; ++edge)
    if (activeAcross(triangle, edge, column, row, half)) triangle.activeEdges |= static_cast<std::uint8_t>(1u << edge);
  return triangle;
}

void HeightfieldCollider::query(const Aabb& box, std::vector<std::uint32_t>& out) const {
  if (!box.overlaps(bounds_)) return;
  const double x0 = samplePoint(0, 0).x(), z0 = samplePoint(0, 0).z();
  const auto range = [](double low, double high, double origin, double spacing, int cells) {
    const double first = std::floor((low - origin) / spacing), last = std::floor((high - origin) / spacing);
    return std::pair<int, int>(static_cast<int>(std::clamp(first, 0.0, cells - 1.0)),
                               static_cast<int>(std::clamp(last, 0.0, cells - 1.0)));
  };
  const auto [firstColumn, lastColumn] = range(box.min.x(), box.max.x(), x0, spacingX_, columns_ - 1);
  const auto [firstRow, lastRow] = range(box.min.z(), box.max.z(), z0, spacingZ_, rows_ - 1);
  for (int row = firstRow; row <= lastRow; ++row)
    for (int column = firstColumn; column <= lastColumn; ++column) {
      const std::size_t at = static_cast<std::size_t>(row) * columns_ + column;
      const float corners[4] = {heights_[at], heights_[at + 1], heights_[at + columns_], heights_[at + columns_ + 1]};
      const double low = *std::min_element(corners, corners + 4) * scale_;
      const double high = *std::max_element(corners, corners + 4) * scale_;
      if (high < box.min.y() || low > box.max.y()) continue;
      const auto cell = static_cast<std::uint32_t>(row * (columns_ - 1) + column);
      out.push_back(2 * cell);
      out.push_back(2 * cell + 1);
    }
}

void HeightfieldCollider::sampledGrid(int maxCellsPerSide, std::vector<Vec3>& vertices,
                                      std::vector<MeshTriangle>& triangles) const {
  const auto picks = [maxCellsPerSide](int count) {
    const int stride = std::max(1, (count - 1 + maxCellsPerSide - 1) / std::max(1, maxCellsPerSide));
    std::vector<int> taken;
    for (int k = 0; k < count - 1; k += stride) taken.push_back(k);
    taken.push_back(count - 1);
    return taken;
  };
  const std::vector<int> columns = picks(columns_), rows = picks(rows_);
  vertices.clear();
  triangles.clear();
  for (const int row : rows)
    for (const int column : columns) vertices.push_back(samplePoint(column, row));
  const auto at = [&](std::size_t c, std::size_t r) { return static_cast<std::uint32_t>(r * columns.size() + c); };
  for (std::size_t r = 0; r + 1 < rows.size(); ++r)
    for (std::size_t c = 0; c + 1 < columns.size(); ++c) {
      triangles.push_back({at(c, r), at(c, r + 1), at(c + 1, r)});
      triangles.push_back({at(c + 1, r), at(c, r + 1), at(c + 1, r + 1)});
    }
}

Vec3 HeightfieldCollider::localSupport(const Vec3& direction) const {
  Vec3 best = samplePoint(0, 0);
  for (int row = 0; row < rows_; ++row)
    for (int column = 0; column < columns_; ++column) {
      const Vec3 point = samplePoint(column, row);
      if (point.dot(direction) > best.dot(direction)) best = point;
    }
  return best;
}

}  // namespace physdbg
