#include "engine/narrowphase/gjk.h"

namespace physdbg {
namespace {

SimplexVertex supportOfDifference(SupportShape& a, SupportShape& b, const Vec3& direction) {
  const Vec3 pa = a.support(direction);
  const Vec3 pb = b.support(-direction);
  return {pa - pb, pa, pb};
}

bool repeats(const Simplex& simplex, const Vec3& w) {
  for (int i = 0; i < simplex.size; ++i) {
    if (simplex.vertices[i].w == w) return true;
  }
  return false;
}

}  // namespace

GjkResult runGjk(SupportShape& a, SupportShape& b, const NarrowPhaseOptions& options) {
  const double size = pairSize(a, b);
  // Below this the closest point is rounding noise: treat it as contact and
  // let EPA find a normal from the polytope instead.
  const double overlapSquared = (1e-12 * size) * (1e-12 * size);
  GjkResult result;
  Vec3 v = a.centre() - b.centre();
  if (v.squaredNorm() <= overlapSquared) v = Vec3::UnitX();
  Simplex& simplex = result.simplex;
  while (result.iterations < options.maxGjkIterations) {
    ++result.iterations;
    const SimplexVertex vertex = supportOfDifference(a, b, -v);
    if (simplex.size > 0) {
      const double gain = v.squaredNorm() - v.dot(vertex.w);
      if (repeats(simplex, vertex.w) || gain <= options.relativeTolerance * v.squaredNorm()) break;
    }
    const Simplex previous = simplex;
    simplex.push(vertex);
    if (reduceToClosest(simplex, kFlatTolerance)) {
      result.overlapping = true;
      return result;
    }
    const Vec3 next = simplex.closestPoint();
    if (next.squaredNorm() <= overlapSquared) {
      result.overlapping = true;
      return result;
    }
    if (previous.size > 0 && next.squaredNorm() >= v.squaredNorm()) {  // no progress: keep the better one
      simplex = previous;
      break;
    }
    v = next;
  }
  result.distance = v.norm();
  result.pointA = simplex.pointA();
  result.pointB = simplex.pointB();
  return result;
}

}  // namespace physdbg
