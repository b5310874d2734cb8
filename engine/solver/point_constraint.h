#pragma once
// One contact point as the sequential-impulse solver sees it. Rows: 0 the
// normal, 1 and 2 the tangents. For each, the arm crossed with the direction
// and the angular velocity change a unit impulse causes (inverse inertia
// applied, locked axes zeroed) are kept, so the inner loop does no matrix
// products.
#include <array>

#include "engine/math.h"

namespace physdbg {

// The friction directions every point of a manifold shares: kept once per
// manifold, not per point (the constraints are written and read back each
// step, a cache line per 64 bytes).
using ManifoldTangents = std::array<Vec3, 2>;

struct PointConstraint {
  Vec3 armA, armB;  // from the centres of mass at the start of the step
  Vec3 crossA[3], crossB[3];
  Vec3 turnA[3], turnB[3];
  double normalMass = 0, tangentMass[2] = {0, 0};
  double friction = 0;
  double approachVelocity = 0;  // normal velocity before the solve, for restitution
  double restitution = 0;
  double largestImpulse = 0;  // did this point ever push (restitution needs it)
  double gap = 0;             // separation at the current poses (measureGaps)
  double inverseMassA = 0, inverseMassB = 0;  // the bodies' inverse masses, as scaled for this contact
};

}  // namespace physdbg
