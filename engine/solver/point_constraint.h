#pragma once
// One contact point as the sequential-impulse solver sees it. Rows: 0 the
// normal, 1 and 2 the tangents. For each, the arm crossed with the direction
// and the angular velocity change a unit impulse causes (inverse inertia
// applied, locked axes zeroed) are kept, so the inner loop does no matrix
// products.
#include <array>

#include "engine/contacts/contact_manifold.h"
#include "engine/contacts/material_combine.h"
#include "engine/math.h"

namespace physdbg {

// The friction directions every point of a manifold shares: kept once per
// manifold, not per point.
using ManifoldTangents = std::array<Vec3, 2>;

// No member is initialised by default: the solver builds normal rows on the
// stack for every loaded manifold (loadedHertz) and need not zero 416 bytes a
// point first. The builders write every field they are asked for, and the
// solver's store of them is not zeroed either (only the manifolds solved one
// by one, or that bounce, write theirs).
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

// What every point of one manifold shares when its constraints are built,
// all from the start of the step: poses, velocities, the inverse masses and
// inertia as scaled for the contact, the lock masks and the pair's material.
struct ManifoldFrame {
  Vec3 positionA, positionB;
  Vec3 directions[3];  // the normal, then the two tangents
  Mat3 inverseInertiaA, inverseInertiaB;
  Vec3 angularMaskA, angularMaskB;  // 0 on locked axes
  Vec3 linearVelocityA, angularVelocityA, linearVelocityB, angularVelocityB;
  double inverseMassA, inverseMassB, inverseMassSum;
  CombinedMaterial material;
};

// A manifold none of whose points is within this gap after the step's last
// move has not been reached: the last relax sweep leaves it alone (pushing
// would slow a body still in flight, millimetres above the floor). Closing
// a gap exactly leaves the positions' rounding, many orders below this.
// (A point that pushed bounces when it ends within the touching slop: the
// turn that follows a corner's impact lifts its anchor by a fraction of a
// millimetre.)
constexpr double kReachedGap = 1e-6;  // m

struct ConstraintSettings {
  double linearSlop;            // a point further apart pushes at its own surface
  double stickingSpeed;         // below it static friction, above it dynamic
  double restitutionThreshold;  // approaches slower than this do not bounce
};

// Each point's gap (separation) with A's centre and rotation at positionA,
// rotationA, and B's: n . (pB + RB lB - pA - RA lA) = n . (pB - pA) +
// (RB^T n) . lB - (RA^T n) . lA, so the normal is turned into each body's
// frame once instead of every anchor into the world. Products spelled out,
// so measureWideGaps repeats them exactly.
void pointGaps(const ContactManifold& manifold, const Vec3& positionA, const Mat3& rotationA, const Vec3& positionB,
               const Mat3& rotationB, double* gaps);

// Where point p of the manifold pushes, from each body's centre of mass.
void pointArms(const ContactManifold& manifold, int p, const Vec3& positionA, const Vec3& positionB, double linearSlop,
               Vec3& armA, Vec3& armB);
// Point p's rows [0, rows) (rows = 0: the arms alone), its masses and the
// bodies' inverse masses into c. The other fields are left alone.
void buildPointRows(const ManifoldFrame& frame, const ContactManifold& manifold, int p, int rows,
                    const ConstraintSettings& settings, PointConstraint& c);
// Every field of every point's constraint into out[0, pointCount).
void buildPointConstraints(const ManifoldFrame& frame, const ContactManifold& manifold,
                           const ConstraintSettings& settings, PointConstraint* out);

// A body with translation locks moves along a row's direction d only by its
// free part: the row's linear give is m^-1 d.(mask d), not m^-1. Rows built
// without the masks (every other body's, bit for bit as before) overstate
// it, so a contact along a locked axis kept building impulse that moved
// nothing, and friction bounded by that impulse stopped a free spin. Redoes
// rows [0, rows) of c's masses with each body's linear mask.
void maskLinearRows(const ManifoldFrame& frame, const Vec3& linearMaskA, const Vec3& linearMaskB, int rows,
                    PointConstraint& c);

}  // namespace physdbg
