// SequentialImpulseSolver: each point's constraint rows (point_constraint.h),
// built where they are used rather than stored for the whole step. A
// PointConstraint is 416 bytes, and writing one for every point before the
// islands are known, then reading it back to pack the SIMD lanes, cost more
// than building it. Now a batch builds its wide groups' constraints straight
// into their lanes, four manifolds at once (buildWideManifolds), and only
// manifolds solved one by one (and the rare ones that bounce, for
// restitution) keep theirs in constraints_. What runs before the batches
// (loadedHertz, prepareApproaches) builds the normal rows it needs. Every
// path computes a row by the same operations from the same start-of-step
// data (ManifoldFrame), so the numbers are bit for bit the same.
#include <algorithm>

#include "engine/solver/sequential_impulse_solver.h"

namespace physdbg {

// Bodies' poses and masses are those at the start of the step: RigidBody
// poses do not change until a batch ends, and solverBodies_ keeps the
// inverse masses and inertia prepare() gave it. Velocities and the material
// only where friction and restitution are wanted (withMotion).
ManifoldFrame SequentialImpulseSolver::manifoldFrame(const std::vector<RigidBody>& bodies,
                                                     const ContactManifold& manifold, std::size_t m,
                                                     bool withMotion) const {
  const SolverBody &bodyA = solverBodies_[manifold.a], &bodyB = solverBodies_[manifold.b];
  const auto [scaleA, scaleB] = massScales_[m];
  ManifoldFrame frame;
  frame.positionA = bodies[manifold.a].position();
  frame.positionB = bodies[manifold.b].position();
  frame.directions[0] = manifold.normal;
  frame.directions[1] = tangents_[m][0];
  frame.directions[2] = tangents_[m][1];
  frame.inverseMassA = scaleA * bodyA.inverseMass;
  frame.inverseMassB = scaleB * bodyB.inverseMass;
  frame.inverseMassSum = frame.inverseMassA + frame.inverseMassB;
  frame.inverseInertiaA = scaleA * bodyA.inverseInertia;
  frame.inverseInertiaB = scaleB * bodyB.inverseInertia;
  frame.angularMaskA = bodyA.angularMask;
  frame.angularMaskB = bodyB.angularMask;
  if (!withMotion) return frame;
  // A batch builds its constraints before it solves, and no other batch
  // moves its bodies: these are still the start-of-step velocities.
  frame.linearVelocityA = bodyA.motion.linearVelocity;
  frame.angularVelocityA = bodyA.motion.angularVelocity;
  frame.linearVelocityB = bodyB.motion.linearVelocity;
  frame.angularVelocityB = bodyB.motion.angularVelocity;
  frame.material = combineMaterials(bodies[manifold.a].material(), bodies[manifold.b].material(),
                                    settings_.restitutionCombine(), settings_.frictionCombine());
  return frame;
}

ConstraintSettings SequentialImpulseSolver::constraintSettings() const {
  return {settings_.linearSlop, settings_.stickingSpeed, settings_.restitutionThreshold};
}

void SequentialImpulseSolver::buildNormalRows(const std::vector<RigidBody>& bodies, const ContactManifold& manifold,
                                              std::size_t m, int rows, PointConstraint* out) const {
  const ManifoldFrame frame = manifoldFrame(bodies, manifold, m, false);
  const ConstraintSettings settings = constraintSettings();
  const bool locked = hasLinearLocks(manifold);
  for (int p = 0; p < manifold.pointCount; ++p) {
    buildPointRows(frame, manifold, p, rows, settings, out[p]);
    if (locked) maskLinearRows(frame, solverBodies_[manifold.a].linearMask, solverBodies_[manifold.b].linearMask, rows, out[p]);
  }
}

bool SequentialImpulseSolver::hasLinearLocks(const ContactManifold& manifold) const {
  return solverBodies_[manifold.a].linearMask != Vec3::Ones() || solverBodies_[manifold.b].linearMask != Vec3::Ones();
}

// A batch's constraints: every wide group's, straight into its lanes, and
// every single manifold's into constraints_, in parallel (a pyramid is one
// batch).
void SequentialImpulseSolver::buildBatchConstraints(const std::vector<RigidBody>& bodies,
                                                    std::vector<ContactManifold>& manifolds, IslandWork& work,
                                                    const std::vector<std::uint32_t>& wideMembers,
                                                    const std::vector<std::size_t>& groupStarts) {
  const ConstraintSettings settings = constraintSettings();
  forEach(work.groups.size(), 8, [&](std::size_t g) {
    const std::uint32_t* members = wideMembers.data() + groupStarts[g];
    const int count = static_cast<int>(groupStarts[g + 1] - groupStarts[g]);
    ManifoldFrame frames[simd::width];
    for (int lane = 0; lane < count; ++lane)
      frames[lane] = manifoldFrame(bodies, manifolds[members[lane]], members[lane], true);
    const unsigned bouncing =
        buildWideManifolds(members, count, manifolds, frames, solverBodies_.byRank(), ranks_, settings, work.groups[g]);
    // Restitution (after the substeps, manifold by manifold) reads the
    // constraints of a manifold that may bounce.
    for (int lane = 0; lane < count; ++lane) {
      if (!(bouncing & (1u << lane))) continue;
      const std::uint32_t m = members[lane];
      buildPointConstraints(frames[lane], manifolds[m], settings, pointConstraints(m));
      constrained_[m] = 1;
    }
  });
  forEach(work.singles.size(), 64, [&](std::size_t i) {
    const std::uint32_t m = work.singles[i];
    const ManifoldFrame frame = manifoldFrame(bodies, manifolds[m], m, true);
    PointConstraint* rows = pointConstraints(m);
    buildPointConstraints(frame, manifolds[m], settings, rows);
    if (hasLinearLocks(manifolds[m]))
      for (int p = 0; p < manifolds[m].pointCount; ++p) {
        maskLinearRows(frame, solverBodies_[manifolds[m].a].linearMask, solverBodies_[manifolds[m].b].linearMask, 3,
                       rows[p]);
        // A point the locks leave no motion along the normal carries no
        // load: a warm start or a new contact's seeded weight kept there
        // would only bound friction that stops a spin it cannot affect.
        if (rows[p].normalMass == 0.0) {
          ManifoldPoint& point = manifolds[m].points[p];
          point.normalImpulse = point.tangentImpulse[0] = point.tangentImpulse[1] = 0.0;
        }
      }
    constrained_[m] = 1;
  });
}

}  // namespace physdbg
