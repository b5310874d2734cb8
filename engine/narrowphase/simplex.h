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

// Writes into `reduced` the smallest face of `simplex` holding the point
// closest to the origin, with its weights; `simplex` itself is left as it
// was, so GJK can step back to it without a copy. Returns true, with
// `reduced` untouched and `simplex`'s weights set, when the origin lies inside
// a full-volume tetrahedron. Degenerate (collinear, flat) simplices fall back
// to their edges or faces, so no weight is ever NaN. `reduced` must not be
// `simplex`.
bool reduceToClosest(Simplex& simplex, Simplex& reduced, double flatTolerance);

}  // namespace physdbg
