#include "engine/solver/sequential_impulse_solver.h"

#include <algorithm>
#include <cmath>
#include <numbers>

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

// Current gap at a manifold point, from its anchors on both bodies.
double currentSeparation(const RigidBody& a, const RigidBody& b, const ContactManifold& manifold,
                         const ManifoldPoint& point) {
  return (b.transform().apply(point.localB) - a.transform().apply(point.localA)).dot(manifold.normal);
}

}  // namespace

double SequentialImpulseSolver::step(std::vector<RigidBody>& bodies, const std::vector<bool>& movable,
                                     std::vector<ContactManifold>& manifolds, double dt,
                                     const SolverSettings& settings) {
  const int substeps = std::max(settings.substeps, 1);
  const double h = dt / substeps;
  // Stiffer than a quarter of the substep rate would ring; Box2D v3 uses 30 Hz.
  Softness softness;
  const double hertz = std::min(settings.contactHertz, 0.25 / h);
  if (hertz > 0.0) {
    const double omega = 2.0 * std::numbers::pi * hertz;
    const double a1 = 2.0 * settings.dampingRatio + h * omega;
    const double a2 = h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    softness = {omega / a1, a2 * a3, a3};
  }
  prepare(bodies, movable, manifolds, settings);
  const Softness rigid;
  for (int substep = 0; substep < substeps; ++substep) {
    for (std::size_t i = 0; i < bodies.size(); ++i)
      if (movable[i]) bodies[i].integrateVelocity(h);
    if (settings.warmStarting) warmStart(bodies, manifolds);
    for (int iteration = 0; iteration < settings.velocityIterations; ++iteration)
      solve(bodies, manifolds, h, softness, true, settings);
    for (std::size_t i = 0; i < bodies.size(); ++i)
      if (movable[i]) bodies[i].integratePosition(h);
    solve(bodies, manifolds, h, rigid, false, settings);
  }
  applyRestitution(bodies, manifolds);
  return largestPenetration(bodies, manifolds);
}

void SequentialImpulseSolver::prepare(const std::vector<RigidBody>& bodies, const std::vector<bool>& movable,
                                      std::vector<ContactManifold>& manifolds, const SolverSettings& settings) {
  inverseMass_.resize(bodies.size());
  inverseInertia_.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    inverseMass_[i] = movable[i] ? bodies[i].inverseMass() : 0.0;
    inverseInertia_[i] = movable[i] ? bodies[i].worldInverseInertia() : Mat3::Zero();
  }
  constraints_.resize(manifolds.size() * ContactManifold::maxPoints);
  for (std::size_t m = 0; m < manifolds.size(); ++m) {
    ContactManifold& manifold = manifolds[m];
    const RigidBody &a = bodies[manifold.a], &b = bodies[manifold.b];
    const double inverseMassSum = inverseMass_[manifold.a] + inverseMass_[manifold.b];
    const double restitution = std::max(a.material().restitution, b.material().restitution);
    for (int p = 0; p < manifold.pointCount; ++p) {
      ManifoldPoint& point = manifold.points[p];
      PointConstraint& c = constraints_[m * ContactManifold::maxPoints + p];
      const Vec3 contact = 0.5 * (point.pointA + point.pointB);
      c.armA = contact - a.position();
      c.armB = contact - b.position();
      tangentBasis(manifold.normal, c.tangent[0], c.tangent[1]);
      const Mat3 &inertiaA = inverseInertia_[manifold.a], &inertiaB = inverseInertia_[manifold.b];
      c.normalMass = effectiveMass(inverseMassSum, inertiaA, inertiaB, c.armA, c.armB, manifold.normal);
      for (int t = 0; t < 2; ++t)
        c.tangentMass[t] = effectiveMass(inverseMassSum, inertiaA, inertiaB, c.armA, c.armB, c.tangent[t]);
      const Vec3 relative = pointVelocity(b, c.armB) - pointVelocity(a, c.armA);
      c.approachVelocity = relative.dot(manifold.normal);
      const double slidingSpeed = (relative - c.approachVelocity * manifold.normal).norm();
      c.friction = slidingSpeed < settings.stickingSpeed
                       ? combineFriction(a.material().staticFriction, b.material().staticFriction)
                       : combineFriction(a.material().dynamicFriction, b.material().dynamicFriction);
      c.restitution = c.approachVelocity < -settings.restitutionThreshold ? restitution : 0.0;
      c.largestImpulse = 0.0;
      if (!settings.warmStarting) point.normalImpulse = point.tangentImpulse[0] = point.tangentImpulse[1] = 0.0;
    }
  }
}

void SequentialImpulseSolver::applyImpulse(std::vector<RigidBody>& bodies, const ContactManifold& manifold,
                                           const PointConstraint& c, const Vec3& impulse) {
  if (inverseMass_[manifold.a] > 0.0) {
    RigidBody& a = bodies[manifold.a];
    a.setLinearVelocity(a.linearVelocity() - inverseMass_[manifold.a] * impulse);
    a.setAngularVelocity(a.angularVelocity() - inverseInertia_[manifold.a] * c.armA.cross(impulse));
    a.applyLocks();
  }
  if (inverseMass_[manifold.b] > 0.0) {
    RigidBody& b = bodies[manifold.b];
    b.setLinearVelocity(b.linearVelocity() + inverseMass_[manifold.b] * impulse);
    b.setAngularVelocity(b.angularVelocity() + inverseInertia_[manifold.b] * c.armB.cross(impulse));
    b.applyLocks();
  }
}

void SequentialImpulseSolver::warmStart(std::vector<RigidBody>& bodies, const std::vector<ContactManifold>& manifolds) {
  for (std::size_t m = 0; m < manifolds.size(); ++m) {
    const ContactManifold& manifold = manifolds[m];
    for (int p = 0; p < manifold.pointCount; ++p) {
      const ManifoldPoint& point = manifold.points[p];
      const PointConstraint& c = constraints_[m * ContactManifold::maxPoints + p];
      applyImpulse(bodies, manifold, c,
                   point.normalImpulse * manifold.normal + point.tangentImpulse[0] * c.tangent[0] +
                       point.tangentImpulse[1] * c.tangent[1]);
    }
  }
}

// One sweep over every point: the normal constraint (soft push-out while
// overlapping with `useBias`, exact closing of the gap while apart), then
// Coulomb friction clamped to the cone |f| <= mu * normal impulse.
void SequentialImpulseSolver::solve(std::vector<RigidBody>& bodies, std::vector<ContactManifold>& manifolds,
                                    double substep, const Softness& softness, bool useBias,
                                    const SolverSettings& settings) {
  for (std::size_t m = 0; m < manifolds.size(); ++m) {
    ContactManifold& manifold = manifolds[m];
    const RigidBody &a = bodies[manifold.a], &b = bodies[manifold.b];
    for (int p = 0; p < manifold.pointCount; ++p) {
      ManifoldPoint& point = manifold.points[p];
      PointConstraint& c = constraints_[m * ContactManifold::maxPoints + p];
      const double separation = currentSeparation(a, b, manifold, point);
      double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
      if (separation > 0.0) {
        bias = separation / substep;
      } else if (useBias) {
        bias = std::max(softness.biasRate * separation, -settings.maxPushSpeed);
        massScale = softness.massScale;
        impulseScale = softness.impulseScale;
      }
      const double normalVelocity = (pointVelocity(b, c.armB) - pointVelocity(a, c.armA)).dot(manifold.normal);
      const double impulse =
          -c.normalMass * massScale * (normalVelocity + bias) - impulseScale * point.normalImpulse;
      const double total = std::max(point.normalImpulse + impulse, 0.0);
      applyImpulse(bodies, manifold, c, (total - point.normalImpulse) * manifold.normal);
      point.normalImpulse = total;
      c.largestImpulse = std::max(c.largestImpulse, total);
    }
    for (int p = 0; p < manifold.pointCount; ++p) {
      ManifoldPoint& point = manifold.points[p];
      const PointConstraint& c = constraints_[m * ContactManifold::maxPoints + p];
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
      applyImpulse(bodies, manifold, c,
                   (tangentImpulse[0] - point.tangentImpulse[0]) * c.tangent[0] +
                       (tangentImpulse[1] - point.tangentImpulse[1]) * c.tangent[1]);
      point.tangentImpulse[0] = tangentImpulse[0];
      point.tangentImpulse[1] = tangentImpulse[1];
    }
  }
}

// Restitution once, after the substeps, only where the contact pushed: the
// approach velocity measured before the solve is reversed and scaled by e.
// A speculative point bounces on the step it would have hit.
void SequentialImpulseSolver::applyRestitution(std::vector<RigidBody>& bodies,
                                               std::vector<ContactManifold>& manifolds) {
  for (std::size_t m = 0; m < manifolds.size(); ++m) {
    ContactManifold& manifold = manifolds[m];
    for (int p = 0; p < manifold.pointCount; ++p) {
      ManifoldPoint& point = manifold.points[p];
      const PointConstraint& c = constraints_[m * ContactManifold::maxPoints + p];
      if (c.restitution == 0.0 || c.largestImpulse == 0.0) continue;
      const double normalVelocity =
          (pointVelocity(bodies[manifold.b], c.armB) - pointVelocity(bodies[manifold.a], c.armA)).dot(manifold.normal);
      const double target = -c.restitution * c.approachVelocity;
      const double total = std::max(point.normalImpulse - c.normalMass * (normalVelocity - target), 0.0);
      applyImpulse(bodies, manifold, c, (total - point.normalImpulse) * manifold.normal);
      point.normalImpulse = total;
    }
  }
}

double SequentialImpulseSolver::largestPenetration(const std::vector<RigidBody>& bodies,
                                                   const std::vector<ContactManifold>& manifolds) const {
  double deepest = 0.0;
  for (const ContactManifold& manifold : manifolds) {
    for (int p = 0; p < manifold.pointCount; ++p)
      deepest = std::max(deepest, -currentSeparation(bodies[manifold.a], bodies[manifold.b], manifold,
                                                     manifold.points[p]));
  }
  return deepest;
}

}  // namespace physdbg
