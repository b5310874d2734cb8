#pragma once
// Sequential impulses over contact manifolds (Gauss-Seidel on velocities):
// warm-started normal and Coulomb friction impulses, restitution applied once
// after the iterations, speculative points that let a body approach exactly up
// to a surface (no tunnelling at 200 m/s), then a few position iterations that
// push remaining penetration out directly. Position error never feeds the
// velocities, so removing overlap adds no kinetic energy (no popping, no
// bounce out of a 25% overlap).
#include <vector>

#include "engine/contacts/contact_manifold.h"
#include "engine/dynamics/rigid_body.h"
#include "engine/solver/solver_settings.h"

namespace physdbg {

class SequentialImpulseSolver {
 public:
  // `movable[i]` false makes body i immovable for this step (static, asleep
  // or frozen). Impulses already in the manifolds warm-start the solve.
  void solveVelocities(std::vector<RigidBody>& bodies, const std::vector<bool>& movable,
                       std::vector<ContactManifold>& manifolds, double dt, const SolverSettings& settings);

  // After positions are integrated: returns the largest remaining penetration.
  double solvePositions(std::vector<RigidBody>& bodies, const std::vector<bool>& movable,
                        const std::vector<ContactManifold>& manifolds, const SolverSettings& settings);

 private:
  struct PointConstraint {
    Vec3 armA, armB;
    Vec3 tangent[2];
    double normalMass = 0, tangentMass[2] = {0, 0};
    double friction = 0;
    double targetVelocity = 0;     // normal velocity the constraint aims for (speculative approach)
    double approachVelocity = 0;   // normal velocity before the solve, for restitution
    double restitution = 0;
  };
  struct BodyState {
    double inverseMass = 0;
    Mat3 inverseInertia = Mat3::Zero();
  };

  void prepare(std::vector<RigidBody>& bodies, const std::vector<bool>& movable,
               std::vector<ContactManifold>& manifolds, double dt, const SolverSettings& settings);
  void warmStart(std::vector<RigidBody>& bodies, const std::vector<ContactManifold>& manifolds);
  void relax(std::vector<RigidBody>& bodies, std::vector<ContactManifold>& manifolds);
  void applyRestitution(std::vector<RigidBody>& bodies, std::vector<ContactManifold>& manifolds,
                        const SolverSettings& settings);

  std::vector<BodyState> states_;
  std::vector<PointConstraint> constraints_;  // maxPoints per manifold
};

}  // namespace physdbg
