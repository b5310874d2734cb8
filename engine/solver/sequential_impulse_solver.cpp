#include "engine/solver/sequential_impulse_solver.h"

#include <algorithm>
#include <cmath>

namespace physdbg {
namespace {

// A fixed tangent basis from the normal alone, so tangent impulses stay
// meaningful for warm starting from one step to the next.
void tangentBasis(const Vec3& normal, Vec3& first, Vec3& second) {
  const Vec3 axis = std::abs(normal.x()) < 0.57735 ? Vec3::UnitX() : Vec3::UnitY();
  first = normal.cross(axis).normalized();
  second = normal.cross(first);
}

// Friction of a pair: geometric mean, so a frictionless surface (0) makes
// any pair on it frictionless and equal materials keep their value.
double combineFriction(double a, double b) { return std::sqrt(a * b); }

double effectiveMass(double inverseMassSum, const Mat3& inverseInertiaA, const Mat3& inverseInertiaB, const Vec3& armA,
                     const Vec3& armB, const Vec3& direction) {
  const Vec3 rnA = armA.cross(direction), rnB = armB.cross(direction);
  const double k = inverseMassSum + rnA.dot(inverseInertiaA * rnA) + rnB.dot(inverseInertiaB * rnB);
  return k > 0.0 ? 1.0 / k : 0.0;
}

Vec3 pointVelocity(const RigidBody& body, const Vec3& arm) {
  return body.linearVelocity() + body.angularVelocity().cross(arm);
}

}  // namespace

void SequentialImpulseSolver::solveVelocities(std::vector<RigidBody>& bodies, const std::vector<bool>& movable,
                                              std::vector<ContactManifold>& manifolds, double dt,
                                              const SolverSettings& settings) {
  prepare(bodies, movable, manifolds, dt, settings);
  if (settings.warmStarting) warmStart(bodies, manifolds);
  for (int iteration = 0; iteration < settings.velocityIterations; ++iteration) relax(bodies, manifolds);
  applyRestitution(bodies, manifolds, settings);
}

void SequentialImpulseSolver::prepare(std::vector<RigidBody>& bodies, const std::vector<bool>& movable,
                                      std::vector<ContactManifold>& manifolds, double dt,
                                      const SolverSettings& settings) {
  states_.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    states_[i].inverseMass = movable[i] ? bodies[i].inverseMass() : 0.0;
    states_[i].inverseInertia = movable[i] ? bodies[i].worldInverseInertia() : Mat3::Zero();
  }
  constraints_.resize(manifolds.size() * ContactManifold::maxPoints);
  for (std::size_t m = 0; m < manifolds.size(); ++m) {
    ContactManifold& manifold = manifolds[m];
    const RigidBody &a = bodies[manifold.a], &b = bodies[manifold.b];
    const BodyState &stateA = states_[manifold.a], &stateB = states_[manifold.b];
    const double inverseMassSum = stateA.inverseMass + stateB.inverseMass;
    const double restitution = std::max(a.material().restitution, b.material().restitution);
    for (int p = 0; p < manifold.pointCount; ++p) {
      ManifoldPoint& point = manifold.points[p];
      PointConstraint& constraint = constraints_[m * ContactManifold::maxPoints + p];
      const Vec3 contact = 0.5 * (point.pointA + point.pointB);
      constraint.armA = contact - a.position();
      constraint.armB = contact - b.position();
      tangentBasis(manifold.normal, constraint.tangent[0], constraint.tangent[1]);
      constraint.normalMass = effectiveMass(inverseMassSum, stateA.inverseInertia, stateB.inverseInertia,
                                            constraint.armA, constraint.armB, manifold.normal);
      for (int t = 0; t < 2; ++t)
        constraint.tangentMass[t] = effectiveMass(inverseMassSum, stateA.inverseInertia, stateB.inverseInertia,
                                                  constraint.armA, constraint.armB, constraint.tangent[t]);
      const Vec3 relative = pointVelocity(b, constraint.armB) - pointVelocity(a, constraint.armA);
      constraint.approachVelocity = relative.dot(manifold.normal);
      const double slidingSpeed = (relative - constraint.approachVelocity * manifold.normal).norm();
      constraint.friction =
          slidingSpeed < settings.stickingSpeed
              ? combineFriction(a.material().staticFriction, b.material().staticFriction)
              : combineFriction(a.material().dynamicFriction, b.material().dynamicFriction);
      // A speculative point (still apart) may close at most its gap this step.
      constraint.targetVelocity = point.separation > 0.0 ? -point.separation / dt : 0.0;
      constraint.restitution = constraint.approachVelocity < -settings.restitutionThreshold ? restitution : 0.0;
      if (!settings.warmStarting) point.normalImpulse = point.tangentImpulse[0] = point.tangentImpulse[1] = 0.0;
    }
  }
}

namespace {

void applyImpulse(RigidBody& a, RigidBody& b, double inverseMassA, double inverseMassB, const Mat3& inverseInertiaA,
                  const Mat3& inverseInertiaB, const Vec3& armA, const Vec3& armB, const Vec3& impulse) {
  if (inverseMassA > 0.0) {
    a.setLinearVelocity(a.linearVelocity() - inverseMassA * impulse);
    a.setAngularVelocity(a.angularVelocity() - inverseInertiaA * armA.cross(impulse));
    a.applyLocks();
  }
  if (inverseMassB > 0.0) {
    b.setLinearVelocity(b.linearVelocity() + inverseMassB * impulse);
    b.setAngularVelocity(b.angularVelocity() + inverseInertiaB * armB.cross(impulse));
    b.applyLocks();
  }
}

}  // namespace

void SequentialImpulseSolver::warmStart(std::vector<RigidBody>& bodies, const std::vector<ContactManifold>& manifolds) {
  for (std::size_t m = 0; m < manifolds.size(); ++m) {
    const ContactManifold& manifold = manifolds[m];
    const BodyState &stateA = states_[manifold.a], &stateB = states_[manifold.b];
    for (int p = 0; p < manifold.pointCount; ++p) {
      const ManifoldPoint& point = manifold.points[p];
      const PointConstraint& constraint = constraints_[m * ContactManifold::maxPoints + p];
      const Vec3 impulse = point.normalImpulse * manifold.normal + point.tangentImpulse[0] * constraint.tangent[0] +
                           point.tangentImpulse[1] * constraint.tangent[1];
      applyImpulse(bodies[manifold.a], bodies[manifold.b], stateA.inverseMass, stateB.inverseMass,
                   stateA.inverseInertia, stateB.inverseInertia, constraint.armA, constraint.armB, impulse);
    }
  }
}

// One Gauss-Seidel sweep: friction first (it depends on the normal impulse of
// the previous sweep), then the non-penetration constraint, point by point.
void SequentialImpulseSolver::relax(std::vector<RigidBody>& bodies, std::vector<ContactManifold>& manifolds) {
  for (std::size_t m = 0; m < manifolds.size(); ++m) {
    ContactManifold& manifold = manifolds[m];
    RigidBody &a = bodies[manifold.a], &b = bodies[manifold.b];
    const BodyState &stateA = states_[manifold.a], &stateB = states_[manifold.b];
    const auto apply = [&](const PointConstraint& c, const Vec3& impulse) {
      applyImpulse(a, b, stateA.inverseMass, stateB.inverseMass, stateA.inverseInertia, stateB.inverseInertia, c.armA,
                   c.armB, impulse);
    };
    for (int p = 0; p < manifold.pointCount; ++p) {
      ManifoldPoint& point = manifold.points[p];
      const PointConstraint& c = constraints_[m * ContactManifold::maxPoints + p];
      // Coulomb friction, clamped to the cone |f| <= mu * normal impulse.
      const Vec3 relative = pointVelocity(b, c.armB) - pointVelocity(a, c.armA);
      double tangentImpulse[2];
      for (int t = 0; t < 2; ++t)
        tangentImpulse[t] = point.tangentImpulse[t] - c.tangentMass[t] * relative.dot(c.tangent[t]);
      const double limit = c.friction * point.normalImpulse;
      const double magnitude = std::hypot(tangentImpulse[0], tangentImpulse[1]);
      if (magnitude > limit && magnitude > 0.0) {
        tangentImpulse[0] *= limit / magnitude;
        tangentImpulse[1] *= limit / magnitude;
      }
      const Vec3 frictionImpulse = (tangentImpulse[0] - point.tangentImpulse[0]) * c.tangent[0] +
                                   (tangentImpulse[1] - point.tangentImpulse[1]) * c.tangent[1];
      point.tangentImpulse[0] = tangentImpulse[0];
      point.tangentImpulse[1] = tangentImpulse[1];
      apply(c, frictionImpulse);
    }
    for (int p = 0; p < manifold.pointCount; ++p) {
      ManifoldPoint& point = manifold.points[p];
      const PointConstraint& c = constraints_[m * ContactManifold::maxPoints + p];
      const double normalVelocity = (pointVelocity(b, c.armB) - pointVelocity(a, c.armA)).dot(manifold.normal);
      const double total = std::max(point.normalImpulse - c.normalMass * (normalVelocity - c.targetVelocity), 0.0);
      const double change = total - point.normalImpulse;
      point.normalImpulse = total;
      apply(c, change * manifold.normal);
    }
  }
}

// Restitution once, after the iterations, only where the contact pushed:
// the approach velocity measured before the solve is reversed and scaled by e.
// A speculative point bounces on the step it would have hit.
void SequentialImpulseSolver::applyRestitution(std::vector<RigidBody>& bodies,
                                               std::vector<ContactManifold>& manifolds, const SolverSettings&) {
  for (std::size_t m = 0; m < manifolds.size(); ++m) {
    ContactManifold& manifold = manifolds[m];
    RigidBody &a = bodies[manifold.a], &b = bodies[manifold.b];
    const BodyState &stateA = states_[manifold.a], &stateB = states_[manifold.b];
    for (int p = 0; p < manifold.pointCount; ++p) {
      ManifoldPoint& point = manifold.points[p];
      const PointConstraint& c = constraints_[m * ContactManifold::maxPoints + p];
      if (c.restitution == 0.0 || point.normalImpulse == 0.0) continue;
      const double normalVelocity = (pointVelocity(b, c.armB) - pointVelocity(a, c.armA)).dot(manifold.normal);
      const double target = -c.restitution * c.approachVelocity;
      const double total = std::max(point.normalImpulse - c.normalMass * (normalVelocity - target), 0.0);
      const double change = total - point.normalImpulse;
      point.normalImpulse = total;
      applyImpulse(a, b, stateA.inverseMass, stateB.inverseMass, stateA.inverseInertia, stateB.inverseInertia, c.armA,
                   c.armB, change * manifold.normal);
    }
  }
}

// Non-linear Gauss-Seidel on positions: each penetrating point is pushed out
// along the normal by a share of its depth, moving and turning both bodies by
// their inverse mass and inertia. Velocities are untouched.
double SequentialImpulseSolver::solvePositions(std::vector<RigidBody>& bodies, const std::vector<bool>& movable,
                                               const std::vector<ContactManifold>& manifolds,
                                               const SolverSettings& settings) {
  double deepest = 0.0;
  for (int iteration = 0; iteration < settings.positionIterations; ++iteration) {
    deepest = 0.0;
    for (const ContactManifold& manifold : manifolds) {
      RigidBody &a = bodies[manifold.a], &b = bodies[manifold.b];
      const double inverseMassA = movable[manifold.a] ? a.inverseMass() : 0.0;
      const double inverseMassB = movable[manifold.b] ? b.inverseMass() : 0.0;
      if (inverseMassA + inverseMassB == 0.0) continue;
      for (int p = 0; p < manifold.pointCount; ++p) {
        const ManifoldPoint& point = manifold.points[p];
        const Vec3 worldA = a.transform().apply(point.localA), worldB = b.transform().apply(point.localB);
        const double separation = (worldB - worldA).dot(manifold.normal);
        deepest = std::max(deepest, -separation);
        const double correction =
            std::clamp(settings.baumgarte * (separation + settings.linearSlop), -settings.maxCorrection, 0.0);
        if (correction == 0.0) continue;
        const Vec3 contact = 0.5 * (worldA + worldB);
        const Vec3 armA = contact - a.position(), armB = contact - b.position();
        const Mat3 inverseInertiaA = movable[manifold.a] ? a.worldInverseInertia() : Mat3::Zero();
        const Mat3 inverseInertiaB = movable[manifold.b] ? b.worldInverseInertia() : Mat3::Zero();
        const double mass = effectiveMass(inverseMassA + inverseMassB, inverseInertiaA, inverseInertiaB, armA, armB,
                                          manifold.normal);
        const Vec3 impulse = (-correction * mass) * manifold.normal;
        if (inverseMassA > 0.0) {
          a.translate(-inverseMassA * impulse);
          a.rotate(-(inverseInertiaA * armA.cross(impulse)));
        }
        if (inverseMassB > 0.0) {
          b.translate(inverseMassB * impulse);
          b.rotate(inverseInertiaB * armB.cross(impulse));
        }
      }
    }
  }
  return deepest;
}

}  // namespace physdbg
