#pragma once
// GJK's simplex: up to four points of the Minkowski difference A - B, each
// with the support points of A and B it came from, so closest points and EPA
// contact points are barycentric combinations of stored supports.
#include <array>

#include "engine/math.h"

namespace physdbg {

struct SimplexVertex {
  Vec3 w;  // a - b
  Vec3 a;
  Vec3 b;
};

struct Simplex {
  std::array<SimplexVertex, 4> vertices;
  std::array<double, 4> weights{};  // barycentric weights of the closest point
  int size = 0;

  void push(const SimplexVertex& vertex) { vertices[size++] = vertex; }
  Vec3 closestPoint() const;
  Vec3 pointA() const;
  Vec3 pointB() const;
};

// Reduces `simplex` to the smallest face holding the point closest to the
// origin and sets its weights. Returns true when the origin lies inside a
// full-volume tetrahedron. Degenerate (collinear, flat) simplices fall back to
// their edges or faces, so no weight is ever NaN.
bool reduceToClosest(Simplex& simplex, double flatTolerance);

}  // namespace physdbg
