#pragma once
// What a bounce gives back, as plain functions the solver's restitution pass
// (sequential_impulse_restitution.cpp) and its tests share.
//
// Along a contact normal the gap x and its rate v move, between contacts,
// under a steady pull p (the forces and gravity that close the pair, m/s^2)
// and the solver's substep h. Semi-implicit Euler (v += -p h, then x += v h)
// keeps E = v^2/2 + p x - p h v/2 exactly from substep to substep, and the
// height a body thrown up from x = 0 climbs to is E/p (to within p h^2/8). A
// body that starts a step at gap d > 0 moving at v0 and closes its
// speculative contact within the step arrives with the E0 it started with,
// whichever substep it lands in; taking the restitution from v0 alone (the
// start of the step) forgot what the pull added on the way down, so an
// elastic ball lost about 1.5% of its height each bounce. Here the point
// leaves with the speed that has e^2 E0 where the step ends it (gap x_end),
// so a ball dropped from H climbs back to e^2 H. With no pull this is
// e |v0|: two bodies meeting in free space leave as an analytic impact does.
#include <Eigen/Core>

#include "engine/contacts/contact_manifold.h"
#include "engine/solver/point_constraint.h"

namespace physdbg {

struct BounceInput {
  double startGap = 0;       // m, >= 0: the point's separation at the start of the step
  double startVelocity = 0;  // m/s, < 0 closing: the normal velocity at the start of the step
  double pull = 0;           // m/s^2, > 0 closing: forces and gravity along the normal
  double endGap = 0;         // m, < 0 overlapping: where the step leaves the point
  double restitution = 0;
  double substep = 0;  // s
};

// The normal velocity (m/s, > 0 opening) the point leaves with.
double bounceSpeed(const BounceInput& input);

// J M^-1 J^T of a manifold's normal rows (rows[p].crossA[0], turnA[0], ...
// built): entry (i, j) is point i's normal speed per unit impulse at point j.
// Zero past pointCount. linearMaskA/B: 0 on each body's locked translation axes.
Eigen::Matrix4d normalMassMatrix(const ContactManifold& manifold, const PointConstraint* rows,
                                 const Vec3& linearMaskA, const Vec3& linearMaskB);

// The impulse changes that bring the points in `mask` from velocity error
// `error` (current normal speed minus target) to zero at once, keeping each
// point's total (impulse + change) from pulling: the block solve first (the
// pseudo-inverse, so four coplanar points, which have three independent
// motions, share the impulse evenly), then, when that would pull, projected
// Gauss-Seidel iterated until it stops changing. Points outside the mask get
// no change.
Eigen::Vector4d bounceImpulses(const Eigen::Matrix4d& mass, const Eigen::Vector4d& error,
                               const Eigen::Vector4d& impulse, int count, int mask);

// Eigenvalues below 1e-9 of the largest count as zero: the directions the
// points cannot move in independently get no impulse.
Eigen::Matrix4d pseudoInverse(const Eigen::Matrix4d& matrix);

}  // namespace physdbg
