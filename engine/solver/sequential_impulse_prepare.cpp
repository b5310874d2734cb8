// SequentialImpulseSolver: each point's constraint rows (point_constraint.h),
// built where they are used rather than stored for the whole step. A
// PointConstraint is 472 bytes, and writing one for every point before the
// islands are known, then reading it back to pack the SIMD lanes, made the
// step memory bound (a second thread slowed both passes to half speed). Now
// a batch builds its wide groups' constraints on the stack and packs them
// straight into the lanes, and only manifolds solved one by one (and the
// rare ones that bounce, for restitution) keep theirs in constraints_. What
// runs before the batches (loadedHertz, prepareApproaches) builds the normal
// row it needs again. Every path computes a row by the same expressions from
// the same start-of-step data, so the numbers are bit for bit the ones a
// stored constraint held.
#include <algorithm>
#include <cstring>

#include "engine/contacts/material_combine.h"
#include "engine/solver/sequential_impulse_solver.h"

namespace physdbg {
namespace {

// 1 / (J M^-1 J^T) of one row, from the row's cross and turn vectors: the
// turn is what the row's impulse does to the spin, so a locked axis (masked
// out of the turn) adds no give, as it adds no motion.
double rowMass(double inverseMassSum, const PointConstraint& c, int row) {
  const double k = inverseMassSum + c.crossA[row].dot(c.turnA[row]) + c.crossB[row].dot(c.turnB[row]);
  return k > 0.0 ? 1.0 / k : 0.0;
}

}  // namespace

Vec3 SequentialImpulseSolver::relativeVelocity(const ContactManifold& manifold, const PointConstraint& c) const {
  const SolverBody &a = solverBodies_[manifold.a], &b = solverBodies_[manifold.b];
  return (b.motion.linearVelocity + b.motion.angularVelocity.cross(c.armB)) -
         (a.motion.linearVelocity + a.motion.angularVelocity.cross(c.armA));
}

// Bodies' poses and masses are those at the start of the step: RigidBody
// poses do not change until a batch ends, and solverBodies_ keeps the
// inverse masses and inertia prepare() gave it.
SequentialImpulseSolver::ManifoldFrame SequentialImpulseSolver::manifoldFrame(const std::vector<RigidBody>& bodies,
                                                                              const ContactManifold& manifold,
                                                                              std::size_t m) const {
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
  return frame;
}

void SequentialImpulseSolver::buildRows(const ManifoldFrame& frame, const ContactManifold& manifold, int p, int rows,
                                        PointConstraint& c) const {
  const ManifoldPoint& point = manifold.points[p];
  const SolverBody &bodyA = solverBodies_[manifold.a], &bodyB = solverBodies_[manifold.b];
  // Touching or overlapping, both bodies push at the midpoint. A
  // speculative point may still be metres from the other body; there
  // each pushes at its own surface, or friction gets a long lever.
  const bool apart = point.separation > settings_.linearSlop;
  const Vec3 middle = 0.5 * (point.pointA + point.pointB);
  c.armA = (apart ? point.pointA : middle) - frame.positionA;
  c.armB = (apart ? point.pointB : middle) - frame.positionB;
  for (int row = 0; row < rows; ++row) {
    c.crossA[row] = c.armA.cross(frame.directions[row]);
    c.crossB[row] = c.armB.cross(frame.directions[row]);
    c.turnA[row] = (frame.inverseInertiaA * c.crossA[row]).cwiseProduct(bodyA.angularMask);
    c.turnB[row] = (frame.inverseInertiaB * c.crossB[row]).cwiseProduct(bodyB.angularMask);
  }
  c.inverseMassA = frame.inverseMassA;
  c.inverseMassB = frame.inverseMassB;
  if (rows > 0) c.normalMass = rowMass(frame.inverseMassSum, c, 0);
  for (int t = 0; t + 1 < rows; ++t) c.tangentMass[t] = rowMass(frame.inverseMassSum, c, t + 1);
}

// Friction and restitution follow from the velocities at the start of the
// step. A batch builds its constraints before it solves, and no other batch
// moves its bodies, so those are still the velocities it sees.
void SequentialImpulseSolver::buildConstraints(const std::vector<RigidBody>& bodies, const ContactManifold& manifold,
                                               std::size_t m, PointConstraint* out) const {
  const SolverSettings& settings = settings_;
  const CombinedMaterial material = combineMaterials(bodies[manifold.a].material(), bodies[manifold.b].material(),
                                                     settings.restitutionCombine(), settings.frictionCombine());
  const ManifoldFrame frame = manifoldFrame(bodies, manifold, m);
  for (int p = 0; p < manifold.pointCount; ++p) {
    PointConstraint& c = out[p];
    buildRows(frame, manifold, p, 3, c);
    const Vec3 relative = relativeVelocity(manifold, c);
    c.approachVelocity = relative.dot(manifold.normal);
    const double slidingSpeed = (relative - c.approachVelocity * manifold.normal).norm();
    c.friction = slidingSpeed < settings.stickingSpeed ? material.staticFriction : material.dynamicFriction;
    c.restitution = c.approachVelocity < -settings.restitutionThreshold ? material.restitution : 0.0;
    c.largestImpulse = 0.0;
    c.gap = 0.0;
  }
}

// Each point's normal row alone, for what is decided before the batches.
void SequentialImpulseSolver::buildNormalRows(const std::vector<RigidBody>& bodies, const ContactManifold& manifold,
                                              std::size_t m, PointConstraint* out) const {
  const ManifoldFrame frame = manifoldFrame(bodies, manifold, m);
  for (int p = 0; p < manifold.pointCount; ++p) buildRows(frame, manifold, p, 1, out[p]);
}

// A batch's constraints: every wide group's, built on the stack and packed
// into its lanes, and every single manifold's into constraints_, in
// parallel (a pyramid is one batch).
void SequentialImpulseSolver::buildBatchConstraints(const std::vector<RigidBody>& bodies,
                                                    std::vector<ContactManifold>& manifolds, IslandWork& work,
                                                    const std::vector<std::uint32_t>& wideMembers,
                                                    const std::vector<std::size_t>& groupStarts) {
  constexpr int slots = ContactManifold::maxPoints;
  forEach(work.groups.size(), 8, [&](std::size_t g) {
    const std::uint32_t* members = wideMembers.data() + groupStarts[g];
    const int count = static_cast<int>(groupStarts[g + 1] - groupStarts[g]);
    PointConstraint local[simd::width][slots];
    const PointConstraint* lanes[simd::width] = {};
    for (int lane = 0; lane < count; ++lane) {
      const std::uint32_t m = members[lane];
      buildConstraints(bodies, manifolds[m], m, local[lane]);
      lanes[lane] = local[lane];
      // Restitution (after the substeps, manifold by manifold) reads the
      // constraints of a manifold that may bounce.
      bool bounces = false;
      for (int p = 0; p < manifolds[m].pointCount; ++p) bounces = bounces || local[lane][p].restitution != 0.0;
      if (!bounces) continue;
      std::copy(local[lane], local[lane] + manifolds[m].pointCount, constraints_.begin() + m * slots);
      constrained_[m] = 1;
    }
    packWideManifolds(members, count, manifolds, lanes, tangents_, solverBodies_, work.groups[g]);
  });
  forEach(work.singles.size(), 64, [&](std::size_t i) {
    const std::uint32_t m = work.singles[i];
    buildConstraints(bodies, manifolds[m], m, &constraints_[m * slots]);
    constrained_[m] = 1;
  });
}

}  // namespace physdbg
