#pragma once
// Terrain as a grid of heights: static ground that would be millions of
// triangles as a mesh, stored as 4 bytes a sample. Triangles are made from
// the samples when the contact code asks for them (triangle_source.h), two a
// cell, so nothing is built for the whole field; a query touches only the
// cells under the box it is given.
//
// Sample (i, j) is column i (along x) of row j (along z), at
// x = (i - (columns - 1) / 2) * spacingX, z = (j - (rows - 1) / 2) * spacingZ,
// y = height * scale: the field is centred on its body's position. Each cell
// is split by the diagonal from (i + 1, j) to (i, j + 1). Edges are active
// by the mesh's rule (isActiveEdge), found from the neighbouring cell when
// the triangle is made; the field's border is active.
#include <cstdint>
#include <vector>

#include "engine/colliders/collider.h"
#include "engine/colliders/triangle_mesh_collider.h"
#include "engine/colliders/triangle_source.h"

namespace physdbg {

class HeightfieldCollider final : public Collider, public TriangleSource {
 public:
  // `heights` row by row (rows x columns, both at least 2). Throws
  // std::invalid_argument for a wrong count, non-finite heights, or
  // spacings and scale that are not positive and finite.
  HeightfieldCollider(std::vector<float> heights, int columns, int rows, double spacingX, double spacingZ,
                      double scale, double activeEdgeDegrees = TriangleMeshCollider::defaultActiveEdgeDegrees);

  int columns() const { return columns_; }
  int rows() const { return rows_; }
  double spacingX() const { return spacingX_; }
  double spacingZ() const { return spacingZ_; }
  std::size_t sampleBytes() const { return heights_.capacity() * sizeof(float); }
  Vec3 samplePoint(int column, int row) const;
  std::uint32_t triangleCount() const { return 2u * static_cast<std::uint32_t>((columns_ - 1) * (rows_ - 1)); }

  // The field as a triangle grid of at most maxCellsPerSide cells a side,
  // taking every k-th sample (and always the last): the whole of a small
  // field, an outline of a big one for drawing.
  void sampledGrid(int maxCellsPerSide, std::vector<Vec3>& vertices, std::vector<MeshTriangle>& triangles) const;

  void query(const Aabb& box, std::vector<std::uint32_t>& out) const override;
  SourceTriangle triangleAt(std::uint32_t triangle) const override;

  ColliderKind kind() const override { return ColliderKind::Heightfield; }
  Vec3 localSupport(const Vec3& direction) const override;
  Aabb localBounds() const override { return bounds_; }
  double volume() const override { return 0.0; }
  Mat3 unitInertia() const override { return Mat3::Zero(); }

 private:
  // Corners, normal, no edge flags: what an edge's neighbour is asked for.
  SourceTriangle shape(int column, int row, int half) const;
  bool activeAcross(const SourceTriangle& triangle, int edge, int column, int row, int half) const;

  std::vector<float> heights_;
  int columns_, rows_;
  double spacingX_, spacingZ_, scale_;
  double cosThreshold_;
  Aabb bounds_;
};

}  // namespace physdbg
