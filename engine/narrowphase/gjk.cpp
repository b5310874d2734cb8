#include "engine/narrowphase/gjk.h"

#include <algorithm>

namespace physdbg {
namespace {

bool repeats(const Simplex& simplex, const Vec3& w) {
  for (int i = 0; i < simplex.size; ++i) {
    if (simplex.vertices[i].w == w) return true;
  }
  return false;
}

}  // namespace

GjkResult runGjk(SupportShape& a, SupportShape& b, const NarrowPhaseOptions& options) {
  const double size = pairSize(a, b);
  // Closer than this, the direction of the closest point is dominated by
  // rounding (of the inputs too: positions 1e5 away carry 1e-11 of noise), so
  // the pair counts as in contact and EPA takes the normal from the polytope.
  // Kept below the touching tolerance so no real gap is turned into contact.
  const double overlapDistance = std::max(1e-12 * size, std::min(1e-9 * size, 0.1 * options.touchingTolerance));
  const double overlapSquared = overlapDistance * overlapDistance;
  GjkResult result;
  Vec3 v = a.centre() - b.centre();
  if (v.squaredNorm() <= overlapSquared) v = Vec3::UnitX();
  // Two simplices in turn: each step reduces the current one, grown by the
  // new support point, into the other, and steps back by dropping that
  // point again; no step copies a simplex.
  std::array<Simplex, 2> simplices;
  int current = 0;
  while (result.iterations < options.maxGjkIterations) {
    ++result.iterations;
    Simplex& simplex = simplices[current];
    const SimplexVertex vertex = supportOfDifference(a, b, -v);
    if (simplex.size > 0) {
      const double gain = v.squaredNorm() - v.dot(vertex.w);
      if (repeats(simplex, vertex.w) || gain <= options.relativeTolerance * v.squaredNorm()) break;
    }
    const bool grown = simplex.size > 0;
    simplex.push(vertex);
    Simplex& reduced = simplices[1 - current];
    if (reduceToClosest(simplex, reduced, kFlatTolerance)) {
      result.overlapping = true;
      result.simplex = simplex;
      return result;
    }
    const Vec3 next = reduced.closestPoint();
    if (next.squaredNorm() <= overlapSquared) {
      result.overlapping = true;
      result.simplex = reduced;
      return result;
    }
    if (grown && next.squaredNorm() >= v.squaredNorm()) {  // no progress: keep the better one
      --simplex.size;
      break;
    }
    current = 1 - current;
    v = next;
  }
  const Simplex& simplex = simplices[current];
  result.simplex = simplex;
  result.distance = v.norm();
  result.closest = v;
  result.pointA = simplex.pointA();
  result.pointB = simplex.pointB();
  return result;
}

}  // namespace physdbg
