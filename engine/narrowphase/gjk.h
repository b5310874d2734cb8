#pragma once
// GJK distance on the cores of two support shapes (margins excluded).
#include "engine/narrowphase/narrow_phase_options.h"
#include "engine/narrowphase/simplex.h"
#include "engine/narrowphase/support_shape.h"

namespace physdbg {

struct GjkResult {
  bool overlapping = false;  // origin inside or on the boundary of A - B
  double distance = 0.0;     // between the cores when not overlapping
  Vec3 pointA = Vec3::Zero();
  Vec3 pointB = Vec3::Zero();
  Vec3 closest = Vec3::Zero();  // pointA - pointB, computed on the simplex
  Simplex simplex;  // last simplex, EPA's starting point
  int iterations = 0;
};

// Terminates when the origin is enclosed, the support point repeats, the
// distance stops shrinking, or after options.maxGjkIterations. Starts from the
// centre-to-centre direction.
GjkResult runGjk(SupportShape& a, SupportShape& b, const NarrowPhaseOptions& options);

// Support point of A - B along `direction`, with the points of A and B kept.
inline SimplexVertex supportOfDifference(SupportShape& a, SupportShape& b, const Vec3& direction) {
  const Vec3 pa = a.support(direction);
  const Vec3 pb = b.support(-direction);
  return {pa - pb, pa, pb};
}

// Scale of the pair used to make tolerances relative.
inline double pairSize(const SupportShape& a, const SupportShape& b) {
  return a.size() + b.size() + (a.centre() - b.centre()).norm();
}

// Flatness threshold on squared sines (relative 1e-10): below it a triangle
// or tetrahedron is treated as degenerate.
inline constexpr double kFlatTolerance = 1e-20;

}  // namespace physdbg
