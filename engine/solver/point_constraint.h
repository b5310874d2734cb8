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

// No member is initialised by default: the solver builds constraints on the
// stack for every wide group (sequential_impulse_prepare.cpp), and zeroing
// 472 bytes a point first was a tenth of that build. The builder writes every
// field; a vector of them is zeroed by value-initialisation.
struct PointConstraint {
  Vec3 armA, armB;  // from the centres of mass at the start of the step
  Vec3 crossA[3], crossB[3];
  Vec3 turnA[3], turnB[3];
  double normalMass, tangentMass[2];
  double friction;
  double approachVelocity;  // normal velocity before the solve, for restitution
  double restitution;
  double largestImpulse;              // did this point ever push (restitution needs it)
  double gap;                         // separation at the current poses (measureGaps)
  double inverseMassA, inverseMassB;  // the bodies' inverse masses, as scaled for this contact
};

}  // namespace physdbg
